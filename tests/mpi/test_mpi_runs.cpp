// Whole runs under mpirun (issue 8), built only with CURVSPH_MPI: the same case on 1, 2 and
// 4 ranks (oversubscribed on a small machine) gives the same particles, none lost or
// duplicated, and bad input stops every rank with one message and exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "curvsph/io/vtk_reader.hpp"
#include "curvsph_build_paths.hpp"
#include "support/command_fixture.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

class MpiRun : public testing::CommandTest {
 protected:
  // `mpirun -np N curvsph ARGS` with one OpenMP thread per rank.
  int run_ranks(int np, const std::string& args) {
    const std::string mpirun = std::string(CURVSPH_MPIEXEC) + " --oversubscribe" +
                               (getuid() == 0 ? " --allow-run-as-root" : "") + " -np " +
                               std::to_string(np) + " -x OMP_NUM_THREADS=1 -x OMP_WAIT_POLICY " +
                               CURVSPH_BINARY;
    const std::string cmd = mpirun + " " + args + " >" + (dir_ / "stdout").string() + " 2>" +
                            (dir_ / "stderr").string();
    setenv("OMP_WAIT_POLICY", "passive", 0);
    const int status = std::system(cmd.c_str());
    out_ = read(dir_ / "stdout");
    err_ = read(dir_ / "stderr");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // The last snapshot of a run: one .vtp, or the ranks' pieces; particles by id.
  template <int D>
  static std::map<std::int64_t, std::array<double, 2 * D + 3>> last_snapshot(const fs::path& out,
                                                                             int np) {
    std::vector<fs::path> files;
    int last = -1;
    for (const auto& e : fs::directory_iterator(out)) {
      const std::string f = e.path().filename().string();
      if (f.rfind("particles_", 0) == 0 && f.size() >= 16)
        last = std::max(last, std::stoi(f.substr(10, 6)));
    }
    char base[32];
    std::snprintf(base, sizeof base, "particles_%06d", last);
    if (np == 1)
      files.push_back(out / (std::string(base) + ".vtp"));
    else
      for (int r = 0; r < np; ++r)
        files.push_back(out / (std::string(base) + "_r" + std::to_string(r) + ".vtp"));
    std::map<std::int64_t, std::array<double, 2 * D + 3>> by_id;
    for (const auto& f : files) {
      const Particles<D> p = io::read_particles<D>(f);
      for (std::size_t i = 0; i < p.size(); ++i) {
        std::array<double, 2 * D + 3> v{};
        for (int d = 0; d < D; ++d) {
          v[static_cast<std::size_t>(d)] = p.x[i][d];
          v[static_cast<std::size_t>(D + d)] = p.v[i][d];
        }
        v[2 * D] = p.rho[i];
        v[2 * D + 1] = p.p[i];
        v[2 * D + 2] = p.mass[i];
        EXPECT_TRUE(by_id.emplace(p.id[i], v).second) << "particle " << p.id[i] << " twice";
      }
    }
    return by_id;
  }

  // Runs the case on 1, 2 and 4 ranks and compares every particle with the 1-rank run.
  template <int D>
  void same_on_1_2_4(const std::string& case_args, double tol) {
    std::map<std::int64_t, std::array<double, 2 * D + 3>> ref;
    for (int np : {1, 2, 4}) {
      const fs::path out = dir_ / ("np" + std::to_string(np));
      ASSERT_EQ(run_ranks(np, "run " + case_args + " -q --out " + out.string() +
                                  " --set parallel.check_conservation=true"
                                  // the snapshots compared to round-off: exact values
                                  " --set output.precision=float64"),
                0)
          << err_;
      const auto m = nlohmann::json::parse(read(out / "metrics.json"));
      EXPECT_EQ(m["ranks"].get<int>(), np);
      // Checked after every migration (every step, plus the start on several ranks).
      EXPECT_GE(m["conservation_checks"].get<long>(), m["steps"].get<long>());
      EXPECT_EQ(m["conservation_count_error_max"].get<long>(), 0);
      EXPECT_EQ(m["conservation_id_error_max"].get<long>(), 0);
      EXPECT_LT(m["conservation_mass_rel_error_max"].get<double>(), 1e-12);
      if (np > 1) {
        EXPECT_GT(m["halo_fraction"].get<double>(), 0);
      }
      const auto got = last_snapshot<D>(out, np);
      if (np == 1) {
        ref = got;
        // (open boundaries create and delete particles: `particles` is the count at the start)
        if (!m.contains("particles_inflow"))
          EXPECT_EQ(static_cast<long>(ref.size()), m["particles"].get<long>());
        else
          EXPECT_GT(m["particles_inflow"].get<long>(), 0);
        continue;
      }
      ASSERT_EQ(got.size(), ref.size()) << np << " ranks";
      // Scale of each field, so the tolerance is relative to the field's magnitude.
      std::array<double, 2 * D + 3> scale{};
      for (const auto& [id, v] : ref)
        for (std::size_t k = 0; k < v.size(); ++k) scale[k] = std::max(scale[k], std::abs(v[k]));
      double worst = 0;
      for (const auto& [id, v] : ref) {
        const auto it = got.find(id);
        ASSERT_NE(it, got.end()) << "particle " << id << " lost on " << np << " ranks";
        for (std::size_t k = 0; k < v.size(); ++k)
          if (scale[k] > 0) worst = std::max(worst, std::abs(it->second[k] - v[k]) / scale[k]);
      }
      EXPECT_LT(worst, tol) << np << " ranks";
      std::ostringstream w;
      w << std::scientific << worst;
      RecordProperty("max_rel_difference_np" + std::to_string(np), w.str());
    }
  }
};

const std::string kCases = std::string(CURVSPH_SOURCE_DIR) + "/cases/";

// Periodic on both axes, continuity + delta-SPH + shifting: every halo refresh is used.
TEST_F(MpiRun, TaylorGreenSameParticlesOn1And2And4Ranks) {
  same_on_1_2_4<2>(kCases +
                       "taylor_green_2d.yaml --set resolution.dx=0.02 --set time.max_steps=20 "
                       "--set output.every=10",
                   1e-12);
}

// The same case under the owner rule (every pair with an owned particle, halo 2h): same
// particles, and about twice the midpoint rule's halo (2 layers per cut face against 1).
TEST_F(MpiRun, TaylorGreenOwnerRuleSameAndTwiceTheMidpointHalo) {
  const std::string args = kCases +
                           "taylor_green_2d.yaml --set resolution.dx=0.02 --set "
                           "time.max_steps=20 --set output.every=10";
  same_on_1_2_4<2>(args + " --set parallel.halo_rule=owner", 1e-12);
  const auto owner = nlohmann::json::parse(read(dir_ / "np2" / "metrics.json"));
  EXPECT_EQ(owner["halo_rule_midpoint"].get<int>(), 0);
  const fs::path mid = dir_ / "midpoint_np2";
  ASSERT_EQ(run_ranks(2, "run " + args + " -q --out " + mid.string()), 0) << err_;
  const auto m = nlohmann::json::parse(read(mid / "metrics.json"));
  EXPECT_EQ(m["halo_rule_midpoint"].get<int>(), 1);
  const double ratio = m["halo_fraction"].get<double>() / owner["halo_fraction"].get<double>();
  EXPECT_GT(ratio, 0.35);
  EXPECT_LT(ratio, 0.65);
  RecordProperty("halo_ratio_midpoint_over_owner", std::to_string(ratio));
}

// 3-D periodic box, summation density, midpoint rule: cuts on two axes at 4 ranks, pairs whose
// midpoint belongs to a rank that owns neither particle. Random relaxed positions: on the
// case's lattice the uniform flow stays uniform and every acceleration is round-off.
TEST_F(MpiRun, PeriodicBox3DMidpointSameOn1And2And4Ranks) {
  same_on_1_2_4<3>(kCases +
                       "periodic_box_3d.yaml --set resolution.dx=0.0625 --set time.max_steps=10 "
                       "--set fluids.0.region.random=true --set setup.relax.max_steps=100 "
                       "--set output.every=100 --set output.vtk=true",
                   1e-12);
  const auto m = nlohmann::json::parse(read(dir_ / "np4" / "metrics.json"));
  EXPECT_EQ(m["halo_rule_midpoint"].get<int>(), 1);
}

// Ghost walls (rotating inner cylinder), summation density: ghosts of halo copies.
TEST_F(MpiRun, CouetteSameParticlesOn1And2And4Ranks) {
  same_on_1_2_4<2>(kCases +
                       "couette.yaml --set resolution.dx=1e-3 --set time.max_steps=20 "
                       "--set output.every=100",
                   1e-12);
}

// Re-bisecting at every step (any imbalance above 1e-9) moves particles between ranks all
// the time; the result must still equal the 1-rank run.
TEST_F(MpiRun, CouetteRebalancingEveryStepStillSame) {
  same_on_1_2_4<2>(kCases +
                       "couette.yaml --set resolution.dx=1e-3 --set time.max_steps=10 "
                       "--set output.every=100 --set parallel.rebalance_imbalance=1e-9",
                   1e-12);
  const auto m = nlohmann::json::parse(read(dir_ / "np4" / "metrics.json"));
  EXPECT_GE(m["rebalances"].get<long>(), 5) << "the re-balance path was not exercised";
}

// Surface tension: the curvature of an owned particle reads its neighbours' colour normals,
// each a sum over their own neighbours, so a halo copy's normal must be complete (halo of two
// supports); the ranks' cuts cross the drop's interface.
TEST_F(MpiRun, StaticDropletSurfaceTensionSameOn1And2And4Ranks) {
  same_on_1_2_4<2>(kCases +
                       "static_droplet_2d.yaml --set resolution.dx=0.02 --set time.max_steps=20 "
                       "--set output.every=100",
                   1e-12);
}

// Boundary integrals (wall pressure interpolated from the fluid near each element: a halo of
// two supports), continuity with delta-SPH (the density gradient of halo copies refreshed).
TEST_F(MpiRun, HydrostaticTankBoundaryIntegralsSameOn1And2And4Ranks) {
  same_on_1_2_4<2>(kCases +
                       "hydrostatic_tank.yaml --set resolution.dx=0.02 --set time.max_steps=10 "
                       "--set output.every=100",
                   1e-12);
}

// Open boundaries (solver/open_boundaries.hpp): particles created at the inflow buffer and
// deleted past the outflow buffer on whichever rank owns them; the same particles (created
// ids do not depend on the ranks), and the conservation check's reference follows them.
TEST_F(MpiRun, OpenChannelSameParticlesOn1And2And4Ranks) {
  same_on_1_2_4<2>(kCases +
                       "open_channel_2d.yaml --set resolution.dx=0.01 --set time.max_steps=60 "
                       "--set open_boundaries.0.velocity.ramp=0 "
                       "--set open_boundaries.0.velocity.parabolic.max=0.5 --set eos.c0=5 "
                       "--set fluids.0.velocity=[0.3,0] "
                       "--set output.every=10",
                   1e-10);
}

TEST_F(MpiRun, BadInputStopsEveryRankWithOneMessage) {
  const int rc = run_ranks(2, "run " + kCases + "couette.yaml -q --out " + (dir_ / "bad").string() +
                                  " --set walls.0.radius=-0.01");
  EXPECT_EQ(rc, 2) << err_;
  // Rank 0 prints it once; the key and reason are named.
  EXPECT_NE(err_.find("walls.0"), std::string::npos) << err_;
  std::size_t lines = 0;
  for (std::size_t at = err_.find("error:"); at != std::string::npos;
       at = err_.find("error:", at + 1))
    ++lines;
  EXPECT_EQ(lines, 1u) << err_;
}

}  // namespace
}  // namespace curvsph
