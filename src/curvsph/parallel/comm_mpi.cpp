// MPI implementation of communicator.hpp (CURVSPH_MPI on). Only this file includes <mpi.h>.
#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "curvsph/parallel/communicator.hpp"

namespace curvsph::mpi {
namespace {

bool initialised() {
  int flag = 0, finalised = 0;
  MPI_Initialized(&flag);
  MPI_Finalized(&finalised);
  return flag && !finalised;
}

// Accumulates the wall time of one communication call into the counters.
struct Timed {
  CommStats& s;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  ~Timed() {
    s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
};

int checked_int(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("MPI message larger than 2 GiB");
  return static_cast<int>(n);
}

}  // namespace

CommStats Comm::stats_{};

// MPI starts only under a launcher (mpirun / mpiexec / srun set these). A plain `curvsph`
// stays a single process without MPI: it starts faster and can itself launch `mpirun`
// (validate scaling), which an MPI singleton process cannot do reliably.
static bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

Session::Session(int& argc, char**& argv) {
  if (!initialised() && launched_by_mpi()) MPI_Init(&argc, &argv);
}
Session::~Session() {
  if (initialised()) MPI_Finalize();
}

Comm Comm::world() {
  if (!initialised()) return Comm(0, 1);
  int r = 0, s = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return Comm(r, s);
}
bool Comm::mpi_enabled() {
  return true;
}

namespace {
template <class T>
T reduce(int size, T v, MPI_Datatype type, MPI_Op op, CommStats& st) {
  if (size == 1) return v;
  Timed t{st};
  ++st.collectives;
  T out{};
  MPI_Allreduce(&v, &out, 1, type, op, MPI_COMM_WORLD);
  return out;
}
}  // namespace

double Comm::sum(double v) const {
  return reduce(size_, v, MPI_DOUBLE, MPI_SUM, stats_);
}
double Comm::min(double v) const {
  return reduce(size_, v, MPI_DOUBLE, MPI_MIN, stats_);
}
double Comm::max(double v) const {
  return reduce(size_, v, MPI_DOUBLE, MPI_MAX, stats_);
}
std::int64_t Comm::sum(std::int64_t v) const {
  return reduce(size_, v, MPI_INT64_T, MPI_SUM, stats_);
}
std::int64_t Comm::max(std::int64_t v) const {
  return reduce(size_, v, MPI_INT64_T, MPI_MAX, stats_);
}
std::int64_t Comm::min(std::int64_t v) const {
  return reduce(size_, v, MPI_INT64_T, MPI_MIN, stats_);
}
void Comm::sum(std::vector<std::int64_t>& v) const {
  if (size_ == 1 || v.empty()) return;
  Timed t{stats_};
  ++stats_.collectives;
  MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_int(v.size()), MPI_INT64_T, MPI_SUM,
                MPI_COMM_WORLD);
}
void Comm::sum(std::vector<double>& v) const {
  if (size_ == 1 || v.empty()) return;
  Timed t{stats_};
  ++stats_.collectives;
  MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_int(v.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}
void Comm::min(std::vector<double>& v) const {
  if (size_ == 1 || v.empty()) return;
  Timed t{stats_};
  ++stats_.collectives;
  MPI_Allreduce(MPI_IN_PLACE, v.data(), checked_int(v.size()), MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
}
void Comm::barrier() const {
  if (size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
}

std::string Comm::broadcast(const std::string& s, int root) const {
  if (size_ == 1) return s;
  Timed t{stats_};
  stats_.collectives += 2;
  long n = static_cast<long>(s.size());
  MPI_Bcast(&n, 1, MPI_LONG, root, MPI_COMM_WORLD);
  std::string out = rank_ == root ? s : std::string(static_cast<std::size_t>(n), '\0');
  MPI_Bcast(out.data(), checked_int(out.size()), MPI_CHAR, root, MPI_COMM_WORLD);
  return out;
}

void Comm::exchange(const std::vector<std::vector<std::byte>>& send,
                    std::vector<std::vector<std::byte>>& recv, bool sizes_known) const {
  const auto P = static_cast<std::size_t>(size_);
  const auto me = static_cast<std::size_t>(rank_);
  recv.resize(P);
  if (size_ == 1) {
    recv[0].assign(send[0].begin(), send[0].end());
    return;
  }
  Timed t{stats_};
  // Scratch kept between calls: the exchange allocates nothing once it has grown.
  static thread_local std::vector<int> scount, rcount;
  static thread_local std::vector<MPI_Request> req;
  if (!sizes_known) {
    // Sizes first (one integer per pair), then the payload.
    scount.resize(P);
    rcount.resize(P);
    for (std::size_t r = 0; r < P; ++r) scount[r] = checked_int(send[r].size());
    ++stats_.collectives;
    MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (std::size_t r = 0; r < P; ++r) recv[r].resize(static_cast<std::size_t>(rcount[r]));
  }
  // Point-to-point with the ranks that have something to send or receive: a rank talks to
  // its few geometric neighbours, not to all P - 1 others (MPI_Alltoallv would).
  constexpr int kTag = 8;  // issue 8; every exchange is collective and in order
  req.clear();
  for (std::size_t r = 0; r < P; ++r)
    if (r != me && !recv[r].empty()) {
      req.emplace_back();
      MPI_Irecv(recv[r].data(), checked_int(recv[r].size()), MPI_BYTE, static_cast<int>(r), kTag,
                MPI_COMM_WORLD, &req.back());
    }
  for (std::size_t r = 0; r < P; ++r)
    if (r != me && !send[r].empty()) {
      ++stats_.messages;
      stats_.bytes += static_cast<std::int64_t>(send[r].size());
      req.emplace_back();
      // MPI_Isend takes a non-const buffer in older MPI headers; it only reads it.
      MPI_Isend(const_cast<std::byte*>(send[r].data()), checked_int(send[r].size()), MPI_BYTE,
                static_cast<int>(r), kTag, MPI_COMM_WORLD, &req.back());
    }
  recv[me].assign(send[me].begin(), send[me].end());
  MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

std::vector<std::byte> Comm::gather(const std::vector<std::byte>& mine, int root) const {
  if (size_ == 1) return mine;
  Timed t{stats_};
  stats_.collectives += 2;
  const int n = checked_int(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size_)), displ(counts.size());
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displ[r] = checked_int(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  std::vector<std::byte> out(rank_ == root ? total : 0);
  MPI_Gatherv(mine.data(), n, MPI_BYTE, out.data(), counts.data(), displ.data(), MPI_BYTE, root,
              MPI_COMM_WORLD);
  return out;
}

}  // namespace curvsph::mpi
