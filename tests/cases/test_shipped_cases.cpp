// Every case shipped in cases/ reads without an input error: a case the README points users
// to must parse with the keys, ranges and defaults of the current reader.
#include <gtest/gtest.h>

#include <filesystem>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

TEST(ShippedCases, EveryCaseFileReads) {
  const auto dir = std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases";
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".yaml") continue;
    ++n;
    EXPECT_NO_THROW(read_case(e.path())) << e.path();
  }
  EXPECT_GE(n, 15);
}

TEST(ShippedCases, FreeSurfaceCasesTakeTheFreeSurfaceDefaults) {
  const auto dir = std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases";
  for (const char* name : {"column_on_cylinder_2d", "column_on_sphere_3d", "dam_break_2d"}) {
    const Case c = read_case(dir / (std::string(name) + ".yaml"));
    EXPECT_TRUE(c.free_surface_defaults) << name;
    EXPECT_EQ(c.density.method, DensitySpec::Method::continuity) << name;
    EXPECT_EQ(c.boundary.ghost_pressure, "hydrostatic") << name;
    EXPECT_DOUBLE_EQ(c.boundary.contact, 0.1) << name;
  }
  // Gravity along a periodic axis drives a channel: the confined-flow defaults stay.
  const Case p = read_case(dir / "poiseuille_2d.yaml");
  EXPECT_FALSE(p.free_surface_defaults);
  EXPECT_EQ(p.boundary.ghost_pressure, "copy");
  // Barker's cases, which sum the density (Barker eq. 8), ask for it: the default is continuity.
  EXPECT_EQ(p.density.method, DensitySpec::Method::summation);
  EXPECT_EQ(read_case(dir / "couette.yaml").density.method, DensitySpec::Method::summation);
}

}  // namespace
}  // namespace curvsph
