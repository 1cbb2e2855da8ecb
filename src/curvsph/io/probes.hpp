#pragma once
// probes.csv (DESIGN.md §3): a header `time` then one column per probe quantity named
// NAME.field (P1.p, P1.vel_x, ...; a gauge gives H1.height), one row per probe time.
// Point values are Shepard-normalised SPH interpolations; a gauge's height is the distance
// along its direction to the last point where the fluid fraction sum_j V_j W_j >= 1/2.
// `p_wall` is the pressure a wall-mounted sensor at the point reads: the fluid pressure
// extrapolated to the point as onto a fixed wall (Adami, Hu & Adams 2012, eq. 27 with zero
// wall acceleration; the same as the boundary-integral wall pressure, item 3 of
// boundary/integrals/integrals_boundary.cpp):
//   p_wall(x) = sum_j (p_j + rho_j g.(x - x_j)) W V_j / sum_j W V_j.
// A plain Shepard average `p` at a wall point is the pressure at the centroid of the half
// support (about 0.75 h into the fluid), biased by the hydrostatic gradient there.
// A probe whose fluid fraction is below 0.1 (dry) writes NaN.
// A probe with a `normal` (probes.*.normal: the normal of the wall face it sits on, into the
// fluid) sums only the particles in front of that face, (x_j - x).n >= 0: a flush sensor
// feels the fluid on its own side of the wall, not fluid across an edge of the wall within
// the kernel's support (2h, 0.11 m at the dam break's 0.55/20, where the sensors on the box
// top sit 0.021 m from its front edge; docs/validation/dam_break_3d/findings.md).
#include <fstream>
#include <string>
#include <vector>

#include "curvsph/core/particles.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/kernels/wendland.hpp"
#include "curvsph/neighbors/cell_list.hpp"

namespace curvsph {

template <int D>
class ProbeWriter {
 public:
  ProbeWriter(std::vector<ProbeSpec> probes, const std::string& path, Real dx,
              const Vec<D>& gravity = Vec<D>::Zero());
  bool empty() const { return probes_.empty(); }
  // Column names after `time`.
  std::vector<std::string> columns() const;
  // Values in column order.
  std::vector<double> sample(const Particles<D>& P, const CellList<D>& cells,
                             const WendlandC2<D>& W) const;
  void write_row(double t, const Particles<D>& P, const CellList<D>& cells, const WendlandC2<D>& W);

 private:
  std::vector<ProbeSpec> probes_;
  std::ofstream out_;
  Real dx_;
  Vec<D> gravity_;
};

}  // namespace curvsph
