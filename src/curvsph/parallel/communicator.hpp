#pragma once
// The one place curvsph talks to MPI (issue 8). Everything the domain decomposition needs
// from the message-passing layer is this small interface over bytes and a few reductions;
// comm_mpi.cpp implements it with MPI (CMake option CURVSPH_MPI, on when MPI is found) and
// comm_serial.cpp with a single rank, so the solver compiles and runs the same code with or
// without MPI and no #ifdef leaves this directory.
//
// Comm is a handle on MPI_COMM_WORLD (no state of its own): when MPI was never initialised
// (the unit-test binary, a library user) it reports one rank and every call is the serial
// identity, so a build with MPI behaves exactly like one without until mpi::Session starts.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace curvsph::mpi {

// Starts MPI for the lifetime of the program (constructed first thing in main) when the
// process was started by an MPI launcher, and ends it.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

// Bytes exchanged and calls made, for the scaling study's communication model.
struct CommStats {
  double seconds = 0;      // wall time inside communication calls
  long messages = 0;       // point-to-point messages with a non-empty payload (sent)
  long collectives = 0;    // reductions, broadcasts, gathers
  std::int64_t bytes = 0;  // payload bytes sent
};

class Comm {
 public:
  static Comm world();
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  // True when built with MPI support (whether or not more than one rank runs).
  static bool mpi_enabled();

  double sum(double v) const;
  double min(double v) const;
  double max(double v) const;
  std::int64_t sum(std::int64_t v) const;
  std::int64_t max(std::int64_t v) const;
  std::int64_t min(std::int64_t v) const;
  // Element-wise sums (one collective for several counters).
  void sum(std::vector<std::int64_t>& v) const;
  void sum(std::vector<double>& v) const;
  // Element-wise minimum (one collective for several bounds).
  void min(std::vector<double>& v) const;
  void barrier() const;
  // Root's string on every rank.
  std::string broadcast(const std::string& s, int root) const;
  // Personalised exchange: send[r] goes to rank r, recv[r] receives what rank r sent here.
  // The buffers are the caller's and are reused from call to call (no allocation once they
  // have grown). Only ranks with a non-empty message are contacted (point-to-point). With
  // sizes_known the caller has already sized recv[r] to what rank r sends (a refresh of a
  // halo whose layout was fixed by the previous exchange), so the MPI_Alltoall of the message
  // sizes (P - 1 latencies) is skipped.
  void exchange(const std::vector<std::vector<std::byte>>& send,
                std::vector<std::vector<std::byte>>& recv, bool sizes_known = false) const;
  // Concatenation of every rank's bytes on rank `root` (rank order); empty elsewhere.
  std::vector<std::byte> gather(const std::vector<std::byte>& mine, int root) const;

  CommStats& stats() const { return stats_; }

 private:
  Comm(int rank, int size) : rank_(rank), size_(size) {}
  int rank_ = 0, size_ = 1;
  static CommStats stats_;  // process-wide counters of the one world communicator
};

}  // namespace curvsph::mpi
