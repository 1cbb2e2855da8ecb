#pragma once
// The force and moment the fluid exerts on each wall (forces.csv, DESIGN.md §3), accumulated by
// a boundary model inside its own wall pass (BoundaryModel::add_accelerations), so that no
// second neighbour sweep is needed.
//
// Newton's third law: whatever a boundary model adds to the momentum equation of a fluid
// particle, m_i (a_i after - a_i before its hook), is an external force on the fluid, and the
// wall feels its reaction, -m_i da_i (the fluid-fluid pair terms are internal: equal and
// opposite pair by pair, physics/momentum.hpp). Summed over the particles, the walls then
// carry exactly the part of the fluid's momentum balance that is not gravity or the driving
// term: a fluid at rest in a closed tank loads its walls with its weight.
//
// The sums run over particles [0, count()) (the owned ones under MPI) in fixed blocks of
// kBlock particles; each block's partial sums are added in block order, so the totals do not
// depend on the thread count or the schedule. A model visits the blocks with for_blocks()
// (each block by one thread, its particles in order) and calls add() from inside.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "curvsph/core/parallel.hpp"
#include "curvsph/core/types.hpp"
#include "curvsph/geometry/wall.hpp"

namespace curvsph {

// Per wall: force (fx, fy, fz) and moment (mx, my, mz) about the wall's moment_center; in
// 2-D fz = mx = my = 0 (per unit depth).
struct WallLoad {
  std::array<double, 3> force{0, 0, 0};
  std::array<double, 3> moment{0, 0, 0};
};

template <int D>
class WallLoadSums {
 public:
  static constexpr Index kBlock = 256;
  static constexpr std::size_t kStride = 6;  // fx fy fz mx my mz

  // Zeroes the sums for particles [0, n) and the walls of `walls` (their moment centres).
  void reset(Index n, const WallSet<D>& walls) {
    count_ = n;
    walls_ = walls.size();
    centre_.resize(walls_);
    for (std::size_t k = 0; k < walls_; ++k) centre_[k] = walls[k].moment_center;
    blocks_ = static_cast<std::size_t>((n + kBlock - 1) / kBlock);
    sums_.assign(blocks_ * walls_ * kStride, 0.0);
  }

  Index count() const { return count_; }
  std::size_t walls() const { return walls_; }

  // The reaction `force` on wall k of particle i (< count()), acting at `point`.
  void add(Index i, std::size_t k, const Vec<D>& force, const VecD<D>& point) {
    double* s = &sums_[(static_cast<std::size_t>(i / kBlock) * walls_ + k) * kStride];
    const VecD<D> f = force.template cast<double>();
    const VecD<D> r = point - centre_[k];
    for (int a = 0; a < D; ++a) s[a] += f[a];
    if constexpr (D == 2) {
      s[5] += r.x() * f.y() - r.y() * f.x();
    } else {
      const Vec3d m = r.cross(f);
      s[3] += m.x();
      s[4] += m.y();
      s[5] += m.z();
    }
  }

  // Calls f(i) for every particle of [0, n) (halo copies included; add() only for i <
  // count()), in blocks of kBlock particles, each by one thread, in order within the block.
  // `balanced`: blocks handed out as threads free up (wall work sits in a few stretches of
  // the cell order). f(i) must write only index i's results and add()'s.
  template <class F>
  static void for_blocks(Index n, bool balanced, F&& f) {
    const Index nb = (n + kBlock - 1) / kBlock;
    auto block = [&](Index b) {
      const Index end = std::min(n, (b + 1) * kBlock);
      for (Index i = b * kBlock; i < end; ++i) f(i);
    };
    if (balanced)
      parallel_for_balanced(nb, block, 1);
    else
      parallel_for(nb, block);
  }

  // Totals per wall of the set, blocks added in order (this rank's; the caller sums ranks).
  std::vector<WallLoad> totals() const {
    std::vector<WallLoad> out(walls_);
    for (std::size_t b = 0; b < blocks_; ++b)
      for (std::size_t k = 0; k < walls_; ++k) {
        const double* s = &sums_[(b * walls_ + k) * kStride];
        for (int a = 0; a < 3; ++a) {
          out[k].force[static_cast<std::size_t>(a)] += s[a];
          out[k].moment[static_cast<std::size_t>(a)] += s[3 + a];
        }
      }
    return out;
  }

 private:
  Index count_ = 0;
  std::size_t walls_ = 0, blocks_ = 0;
  std::vector<VecD<D>> centre_;
  std::vector<double> sums_;  // [block][wall][kStride]
};

}  // namespace curvsph
