#include "curvsph/solver/snapshot_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "curvsph/io/forces_csv.hpp"
#include "curvsph/io/pvtp.hpp"
#include "curvsph/io/walls_vtp.hpp"

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
      fields_(c.output_fields),
      boundary_points_(c.write_boundary_points),
      dx_(c.dx),
      h_(c.h()),
      has_domain_(c.has_domain),
      domain_min_(c.domain_min),
      domain_max_(c.domain_max) {}

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

  write_boundary(solver, name, index);
  write_walls(solver, name, index);
}

template <int D>
void SnapshotWriter<D>::write_boundary(const Solver<D>& solver, const std::string& name,
                                       int index) {
  const bool parallel = comm_.size() > 1;
  // Ghosts / wall elements as a second block of the series (kind: 1 ghost, 2 element).
  // With MPI a rank's piece also holds the ghosts of its halo copies.
  const auto* b = solver.boundary();
  if (!b || !boundary_points_) return;
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

template <int D>
void SnapshotWriter<D>::write_walls(const Solver<D>& solver, const std::string& name, int index) {
  const WallSet<D>& walls = solver.walls();
  if (walls.empty()) return;
  const WallGroups groups = WallGroups::of(walls);
  bool moves = false;
  for (std::size_t k = 0; k < walls.size(); ++k) moves = moves || walls[k].moves();
  if (!moves && !wall_files_.empty()) {  // written once: listed again at this time
    if (comm_.root())
      for (std::size_t g = 0; g < wall_files_.size(); ++g)
        series_.add(solver.time(), wall_files_[g], static_cast<int>(2 + g), groups.names[g]);
    return;
  }
  // The clip box of infinite walls: the domain, or the particles' box (over every rank)
  // grown by half its size and 4h, as the boundary integrals clip them.
  Eigen::AlignedBox<double, D> clip;
  if (has_domain_) {
    clip = Eigen::AlignedBox<double, D>(domain_min_.head<D>(), domain_max_.head<D>());
  } else {
    std::vector<double> lo(D, std::numeric_limits<double>::infinity()), hi = lo;
    const Particles<D>& P = solver.particles();
    for (Index i = 0; i < solver.decomposition().owned(); ++i)
      for (int a = 0; a < D; ++a) {
        lo[static_cast<std::size_t>(a)] =
            std::min(lo[static_cast<std::size_t>(a)], double(P.x[i][a]));
        hi[static_cast<std::size_t>(a)] =
            std::min(hi[static_cast<std::size_t>(a)], -double(P.x[i][a]));
      }
    comm_.min(lo);  // [mpi] collective
    comm_.min(hi);
    VecD<D> a, b;
    for (int d = 0; d < D; ++d) {
      a[d] = lo[static_cast<std::size_t>(d)];
      b[d] = -hi[static_cast<std::size_t>(d)];
    }
    const VecD<D> grow = VecD<D>::Constant(4 * h_) + 0.5 * (b - a);
    clip = Eigen::AlignedBox<double, D>(a - grow, b + grow);
  }
  // Every rank records the file names: the early return above must be taken by all ranks
  // alike, as the clip box's reduction is collective.
  wall_files_.assign(groups.names.size(), "");
  for (std::size_t g = 0; g < groups.names.size(); ++g)
    wall_files_[g] = !moves         ? fmt::format("walls_{}.vtp", g)
                     : name.empty() ? fmt::format("walls_{}_{:06d}.vtp", g, index)
                                    : fmt::format("walls_{}_{}", g, name);
  if (!comm_.root()) return;
  for (std::size_t g = 0; g < groups.names.size(); ++g) {
    std::vector<const Wall<D>*> members;
    for (std::size_t k = 0; k < walls.size(); ++k)
      if (groups.group[k] == g) members.push_back(&walls[k]);
    const std::string& file = wall_files_[g];
    wall_polydata(tessellate_walls<D>(members, dx_, clip)).write(out_dir_ / file, options_);
    series_.add(solver.time(), file, static_cast<int>(2 + g), groups.names[g]);
  }
}

template class SnapshotWriter<2>;
template class SnapshotWriter<3>;

}  // namespace curvsph
