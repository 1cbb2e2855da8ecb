// A box read as a CAD solid (six trimmed planar faces under the solid's classifier, as
// `shape: cad` builds it) against the analytic `box` wall: the boundary elements, the
// geometric Shepard factor and the wall sum of the boundary integrals,
//   G(x) = sum_b W_ib A_b n_b   (W_ib the kernel averaged over element b),
// at the fill lattice of a tank at rest (dx / 2 off every face, so also beside the edges and
// corners). Reference: the `box` wall's elements (dx squares, exact areas and normals), an
// independent generator. The two must be the same element set: the wall terms of the boundary
// integrals then coincide, and whatever a tank at rest does with integrals is the method's, not
// the CAD import's (docs/validation/cad_at_rest/findings.md).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <TopoDS_Shape.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "curvsph/boundary/integrals/element_quadrature.hpp"
#include "curvsph/boundary/integrals/shepard.hpp"
#include "curvsph/boundary/integrals/wall_elements.hpp"
#include "curvsph/cad/cad_import.hpp"
#include "curvsph/geometry/box.hpp"

using namespace curvsph;

namespace {

Vec3d wall_sum(const BoundaryElements<3>& el, const ElementQuadrature<3>& q, const WendlandC2<3>& W,
               const Vec3d& x) {
  Vec3d g = Vec3d::Zero();
  for (std::size_t b = 0; b < el.size(); ++b) {
    const Vec<3> r = (x - el.centre[b]).cast<Real>();
    g += static_cast<double>(q.mean_kernel(W, b, r)) * el.area[b] * el.normal[b];
  }
  return g;
}

}  // namespace

TEST(CadBoxIntegrals, SameElementsShepardAndWallSumAsTheBoxWall) {
  // The cad_at_rest study's box: 0.08 x 0.08 x 0.16 m at H/dx = 6, h = 2 dx.
  const double L = 0.08, Lz = 0.16, dx = L / 6, h = 2 * dx;
  const TopoDS_Shape solid = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(L, L, Lz)).Shape();
  const auto faces = cad::faces_to_walls(solid, cad::FluidSide::inside, 1.0);
  ASSERT_EQ(faces.size(), 6u);
  WallSet<3> cad_walls, box_walls;
  cad_walls.add(cad::make_solid_wall(solid, faces, cad::FluidSide::inside, 1.0, "box"));
  box_walls.add(std::make_shared<BoxWall<3>>(Vec3d(0, 0, 0), Vec3d(L, L, Lz), FluidSide::inside));
  const auto ec = elements_from_walls<3>(cad_walls, dx, {});
  const auto eb = elements_from_walls<3>(box_walls, dx, {});
  const double area_c = std::accumulate(ec.area.begin(), ec.area.end(), 0.0);
  const double exact = 2 * L * L + 4 * L * Lz;
  std::printf("CAD box: %zu elements, area / exact - 1 = %.2e; box wall: %zu elements\n", ec.size(),
              area_c / exact - 1, eb.size());
  EXPECT_NEAR(area_c / exact, 1.0, 1e-12);
  // The same set: every CAD element is a box element (centre, normal, area, vertex count).
  EXPECT_EQ(ec.size(), eb.size());
  double worst_match = ec.size() == eb.size() ? 0.0 : 1.0;
  for (std::size_t j = 0; j < ec.size() && ec.size() == eb.size(); ++j) {
    std::size_t best = 0;
    double d = 1e300;
    for (std::size_t k = 0; k < eb.size(); ++k)
      if (const double dk = (ec.centre[j] - eb.centre[k]).norm(); dk < d) {
        d = dk;
        best = k;
      }
    worst_match = std::max({worst_match, d / dx, (ec.normal[j] - eb.normal[best]).norm(),
                            std::abs(ec.area[j] / eb.area[best] - 1)});
    EXPECT_EQ(ec.vertex_count[j], eb.vertex_count[best]) << ec.centre[j].transpose();
  }
  std::printf("CAD box against the box wall: largest centre / normal / area mismatch %.2e\n",
              worst_match);
  EXPECT_LT(worst_match, 1e-10);
  // gamma (exact: solid angles, so equal on any tiling of the faces) and the wall sum at the fill
  // lattice and a quarter dx from the walls, edges and corners.
  const WendlandC2<3> W(static_cast<Real>(h));
  const auto qc = element_quadrature(ec), qb = element_quadrature(eb);
  double worst_gamma = 0, worst_g = 0, g_scale = 0;
  for (double off : {0.5, 0.25})
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 6; ++k) {
          auto at = [&](int n) {
            return n == 0 ? off * dx : n == 5 ? L - off * dx : (n + 0.5) * dx;
          };
          const Vec3d x(at(i), at(j), at(k));
          worst_gamma = std::max(worst_gamma, std::abs(shepard_geometric<3>(ec, x, h) -
                                                       shepard_geometric<3>(eb, x, h)));
          const Vec3d gb = wall_sum(eb, qb, W, x);
          worst_g = std::max(worst_g, (wall_sum(ec, qc, W, x) - gb).norm());
          g_scale = std::max(g_scale, gb.norm());
        }
  std::printf("CAD box against the box wall: max |gamma diff| %.2e, max |G diff| / max |G| %.2e\n",
              worst_gamma, worst_g / g_scale);
  EXPECT_LT(worst_gamma, 1e-8);  // round-off of the solid angles (2e-9 before as well)
  EXPECT_LT(worst_g / g_scale, 1e-6);
}
