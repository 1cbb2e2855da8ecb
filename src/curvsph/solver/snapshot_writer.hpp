#pragma once
// The VTK series of a run: series.pvd listing, at each output time, the particles
// (particles_NNNNNN.vtp, block "particles") and the boundary's ghosts or wall elements
// (boundary_NNNNNN.vtp, block "boundary"). Under MPI each block is a .pvtp naming one .vtp
// piece per rank. The boundary file is written only when its content differs from the last
// one written: wall elements (boundary integrals) are fixed, so one file serves every entry;
// ghosts follow the fluid and get a file per snapshot (output.boundary_points: false leaves
// them out). Then one block per wall, named after it (io/walls_vtp.hpp). Encoding
// (precision, zlib, fields) follows the case's output keys (io/vtk_writer.hpp).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "curvsph/io/pvd_series.hpp"
#include "curvsph/io/vtk_writer.hpp"
#include "curvsph/parallel/communicator.hpp"
#include "curvsph/solver/solver.hpp"

namespace curvsph {

template <int D>
class SnapshotWriter {
 public:
  SnapshotWriter(const Case& c, std::filesystem::path out_dir, const mpi::Comm& comm);

  // Writes the state of `solver` at its time: `name` empty, the next numbered snapshot;
  // otherwise that file name (particles_unstable.vtp). Collective under MPI.
  void write(const Solver<D>& solver, const std::string& name);
  // A restarted run numbers its snapshots after the one it starts from (never overwriting).
  void continue_after(int index) { index_ = index + 1; }
  // The index and the listed file (.vtp, .pvtp with MPI) of the last numbered snapshot.
  int last_index() const { return index_ - 1; }
  std::string last_file() const;

 private:
  // One block: the .vtp on one rank; with MPI a .pvtp naming one .vtp per rank. Returns the
  // file listed in series.pvd.
  std::string write_block(const io::VtkPolyData& poly, const std::string& file) const;

  std::filesystem::path out_dir_;
  const mpi::Comm& comm_;
  io::PvdSeries series_;
  io::VtkWriteOptions options_;
  std::vector<std::string> fields_;
  int index_ = 0;
  // The boundary file last written and its points and kinds (bytes), to reuse it while they
  // do not change.
  std::string boundary_file_;
  std::vector<std::byte> boundary_bytes_;
  bool boundary_points_ = true;  // output.boundary_points

  // The walls (io/walls_vtp.hpp): one block per `walls:` entry, after the boundary block.
  // Written once (walls_K.vtp) unless a wall moves (Wall::moves()): then at every snapshot
  // (walls_K_NNNNNN.vtp). Rank 0 writes them.
  void write_walls(const Solver<D>& solver, const std::string& name, int index);
  // The ghosts / wall elements block (boundary_*.vtp).
  void write_boundary(const Solver<D>& solver, const std::string& name, int index);
  double dx_ = 0, h_ = 0;
  bool has_domain_ = false;
  Vec3d domain_min_ = Vec3d::Zero(), domain_max_ = Vec3d::Zero();
  std::vector<std::string> wall_files_;  // per wall group: the file last written
};

}  // namespace curvsph
