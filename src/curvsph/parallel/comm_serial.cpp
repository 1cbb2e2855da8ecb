// Single-rank implementation of communicator.hpp, compiled when CMake does not find MPI
// (CURVSPH_MPI off): every collective is the identity.
#include "curvsph/parallel/communicator.hpp"

namespace curvsph::mpi {

CommStats Comm::stats_{};

Session::Session(int&, char**&) {}
Session::~Session() = default;

Comm Comm::world() {
  return Comm(0, 1);
}
bool Comm::mpi_enabled() {
  return false;
}

double Comm::sum(double v) const {
  return v;
}
double Comm::min(double v) const {
  return v;
}
double Comm::max(double v) const {
  return v;
}
std::int64_t Comm::sum(std::int64_t v) const {
  return v;
}
std::int64_t Comm::max(std::int64_t v) const {
  return v;
}
std::int64_t Comm::min(std::int64_t v) const {
  return v;
}
void Comm::sum(std::vector<std::int64_t>&) const {}
void Comm::sum(std::vector<double>&) const {}
void Comm::min(std::vector<double>&) const {}
void Comm::barrier() const {}
std::string Comm::broadcast(const std::string& s, int) const {
  return s;
}
void Comm::exchange(const std::vector<std::vector<std::byte>>& send,
                    std::vector<std::vector<std::byte>>& recv, bool) const {
  recv.resize(send.size());
  for (std::size_t r = 0; r < send.size(); ++r) recv[r].assign(send[r].begin(), send[r].end());
}
std::vector<std::byte> Comm::gather(const std::vector<std::byte>& mine, int) const {
  return mine;
}

}  // namespace curvsph::mpi
