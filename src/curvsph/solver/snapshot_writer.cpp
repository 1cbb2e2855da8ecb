#include "curvsph/solver/snapshot_writer.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "curvsph/io/pvtp.hpp"

namespace curvsph {

namespace fs = std::filesystem;

namespace {

// The owned particles of this rank (the solver's arrays may carry halo copies behind them).
template <int D>
Particles<D> owned_part(const Solver<D>& s) {
  Particles<D> p = s.particles();
  const auto n = static_cast<std::size_t>(s.decomposition().owned());
  p.for_each_field([&](const char*, auto& data) { data.resize(n); });
  return p;
}

}  // namespace

template <int D>
SnapshotWriter<D>::SnapshotWriter(const Case& c, fs::path out_dir, const mpi::Comm& comm)
    : out_dir_(std::move(out_dir)),
      comm_(comm),
      series_(out_dir_ / "series.pvd"),
      options_{c.output_float32, c.output_zlib},
      fields_(c.output_fields) {}

template <int D>
std::string SnapshotWriter<D>::write_block(const io::VtkPolyData& poly,
                                           const std::string& file) const {
  if (comm_.size() == 1) {
    poly.write(out_dir_ / file, options_);
    return file;
  }
  const std::string stem = fs::path(file).stem().string();
  poly.write(out_dir_ / fmt::format("{}_r{}.vtp", stem, comm_.rank()), options_);
  if (comm_.root()) {
    std::vector<std::string> pieces;
    for (int r = 0; r < comm_.size(); ++r) pieces.push_back(fmt::format("{}_r{}.vtp", stem, r));
    io::write_pvtp(out_dir_ / (stem + ".pvtp"), poly, pieces, options_);
  }
  return stem + ".pvtp";
}

template <int D>
void SnapshotWriter<D>::write(const Solver<D>& solver, const std::string& name) {
  const bool parallel = comm_.size() > 1;
  const int index = index_;
  const std::string file = name.empty() ? fmt::format("particles_{:06d}.vtp", index_++) : name;
  const std::string listed = write_block(
      io::VtkPolyData::from_particles(parallel ? owned_part(solver) : solver.particles(), fields_),
      file);
  if (comm_.root()) series_.add(solver.time(), listed, 0, "particles");

  // Ghosts / wall elements as a second block of the series (kind: 1 ghost, 2 element).
  // With MPI a rank's piece also holds the ghosts of its halo copies.
  const auto* b = solver.boundary();
  if (!b) return;
  std::vector<Vec<D>> bx;
  std::vector<int> kind;
  b->append_output(bx, kind);
  const bool any = parallel ? comm_.sum(static_cast<std::int64_t>(bx.size())) > 0 : !bx.empty();
  if (!any) return;
  io::VtkPolyData poly;
  poly.set_points(bx);
  poly.add_scalar("kind", std::vector<std::int32_t>(kind.begin(), kind.end()));
  std::vector<std::byte> bytes = poly.points().bytes;
  const auto& k = poly.array("kind").bytes;
  bytes.insert(bytes.end(), k.begin(), k.end());
  bool changed = boundary_file_.empty() || bytes != boundary_bytes_;
  if (parallel) changed = comm_.max(static_cast<std::int64_t>(changed)) > 0;  // [mpi] all agree
  if (changed) {
    boundary_file_ = write_block(
        poly, name.empty() ? fmt::format("boundary_{:06d}.vtp", index) : "boundary_" + name);
    boundary_bytes_ = std::move(bytes);
  }
  if (comm_.root()) series_.add(solver.time(), boundary_file_, 1, "boundary");
}

template <int D>
std::string SnapshotWriter<D>::last_file() const {
  return fmt::format("particles_{:06d}.{}", index_ - 1, comm_.size() == 1 ? "vtp" : "pvtp");
}

template class SnapshotWriter<2>;
template class SnapshotWriter<3>;

}  // namespace curvsph
