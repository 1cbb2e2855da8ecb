// `run --restart` (issue 34 item 4): a run stopped at a snapshot (time.max_steps) and restarted
// from the restart state beside it (solver/restart_state.hpp) equals the straight run bit for
// bit on one thread: every particle field, t, dt, the step count and the analyses' figures.
// The reference is the straight run itself. A snapshot of another case, dimension or dx is
// exit 2 naming the snapshot and the key; a corrupt restart state is exit 2 naming its file.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/pvd_series.hpp"
#include "curvsph/solver/restart_state.hpp"
#include "curvsph/solver/solver.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;
const fs::path kCases = fs::path(CURVSPH_SOURCE_DIR) / "cases";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class Restart : public testing::CommandTest {
 protected:
  int run(const fs::path& file, const fs::path& out, const std::string& args) {
    return run_curvsph("run " + file.string() + " -q --threads 1 --out " + out.string() + " " +
                       args);
  }
  // The last snapshot listed in DIR/series.pvd (particles block).
  static fs::path last_snapshot(const fs::path& dir) {
    std::string last;
    for (const auto& e : io::PvdSeries::read(dir / "series.pvd"))
      if (e.part == 0) last = e.file;
    return dir / last;
  }
  // Straight run to the case's end, and the same run stopped after `cut` steps and restarted
  // from its last snapshot; expects the final states equal bit for bit. Returns both metrics.
  std::pair<nlohmann::json, nlohmann::json> straight_and_restarted(const fs::path& file,
                                                                   const std::string& args,
                                                                   int cut) {
    const fs::path a = dir_ / "straight", b = dir_ / "cut", c = dir_ / "restarted";
    EXPECT_EQ(run(file, a, args), 0) << err_;
    EXPECT_EQ(run(file, b, args + " --set time.max_steps=" + std::to_string(cut)), 0) << err_;
    const fs::path snap = last_snapshot(b);
    EXPECT_EQ(run(file, c, args + " --restart " + snap.string()), 0) << err_;
    const RestartState sa = read_restart_state(restart_state_path(last_snapshot(a)));
    const RestartState sb = read_restart_state(restart_state_path(snap));
    const RestartState sc = read_restart_state(restart_state_path(last_snapshot(c)));
    EXPECT_EQ(sb.header["steps"].get<long>(), cut);
    EXPECT_LT(sb.header["time"].get<double>(), sa.header["time"].get<double>());
    // Bitwise: the doubles compared by their bytes (EXPECT_EQ on vectors of doubles is
    // exact, and NaN would fail it).
    for (const char* key : {"time", "dt", "stable_step", "steps", "output_counter"})
      EXPECT_EQ(sa.header[key], sc.header[key]) << key;
    EXPECT_EQ(sa.header["analyses"], sc.header["analyses"]);
    EXPECT_EQ(sa.reals.size(), sc.reals.size());
    for (const auto& [name, v] : sa.reals) {
      EXPECT_TRUE(sc.reals.count(name)) << name;
      if (!sc.reals.count(name)) continue;
      const auto& w = sc.reals.at(name);
      EXPECT_EQ(v.size(), w.size()) << name;
      if (v.size() == w.size()) {
        EXPECT_EQ(std::memcmp(v.data(), w.data(), 8 * v.size()), 0) << name;
      }
    }
    for (const auto& [name, v] : sa.ints) {
      EXPECT_TRUE(sc.ints.count(name)) << name;
      if (sc.ints.count(name)) {
        EXPECT_EQ(v, sc.ints.at(name)) << name;
      }
    }
    // The restarted run numbers its snapshots after the one it started from.
    const int from = sb.header["snapshot_index"].get<int>();
    const auto entries = io::PvdSeries::read(c / "series.pvd");
    EXPECT_FALSE(entries.empty());
    if (!entries.empty()) {
      EXPECT_EQ(entries.front().file, fmt_index(from + 1));
    }
    const auto ma = nlohmann::json::parse(read(a / "metrics.json"));
    const auto mc = nlohmann::json::parse(read(c / "metrics.json"));
    return {ma, mc};
  }
  static std::string fmt_index(int k) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "particles_%06d.vtp", k);
    return buf;
  }
};

// delta-SPH continuity density and particle shifting (Taylor-Green), stopped at step 20 where
// the next step re-sorts the particles (the stopped run's cell order is carried); the
// kinetic-energy ratio measures from the original t = 0 (before: 0.375 against 0.195).
TEST_F(Restart, ShiftingTaylorGreenBitForBitAcrossAResort) {
  const auto [ma, mc] = straight_and_restarted(
      kCases / "taylor_green_2d.yaml",
      "--set resolution.dx=0.05 --set time.end=0.1 --set output.every=0.03", 20);
  EXPECT_EQ(ma["kinetic_energy_ratio"], mc["kinetic_energy_ratio"]);
  EXPECT_EQ(ma["decay_rate"], mc["decay_rate"]);
  EXPECT_EQ(ma["steps"], mc["steps"]);
  EXPECT_LT(ma["kinetic_energy_ratio"].get<double>(), 1.0);
}

// Ghost particles (Poiseuille channel, summation density), stopped between re-sorts.
TEST_F(Restart, GhostPoiseuilleBitForBit) {
  const auto [ma, mc] = straight_and_restarted(kCases / "poiseuille_2d.yaml",
                                               "--set time.end=0.01 --set output.every=0.0035", 13);
  EXPECT_EQ(ma["steps"], mc["steps"]);
}

// Boundary integrals with continuity density (hydrostatic tank), stopped between re-sorts.
TEST_F(Restart, IntegralsHydrostaticBitForBit) {
  const auto [ma, mc] = straight_and_restarted(
      kCases / "hydrostatic_tank.yaml",
      "--set resolution.dx=0.05 --set setup.relax.max_steps=0 --set time.end=0.02 "
      "--set output.every=0.007",
      7);
  EXPECT_EQ(ma["steps"], mc["steps"]);
}

// Another case, another dimension or another dx: exit 2 naming the snapshot and the key.
TEST_F(Restart, SnapshotOfAnotherCaseDimensionOrDxIsRefused) {
  const fs::path tg = kCases / "taylor_green_2d.yaml";
  const std::string small = "--set resolution.dx=0.05 --set time.end=0.01 ";
  ASSERT_EQ(run(tg, dir_ / "a", small), 0) << err_;
  const fs::path snap = last_snapshot(dir_ / "a");
  ASSERT_EQ(run(kCases / "poiseuille_2d.yaml", dir_ / "b", "--restart " + snap.string()), 2);
  EXPECT_TRUE(has(err_, snap.string()) && has(err_, "key 'name'")) << err_;
  ASSERT_EQ(run(kCases / "periodic_box_3d.yaml", dir_ / "c",
                "--set name=taylor_green_2d --restart " + snap.string()),
            2);
  EXPECT_TRUE(has(err_, snap.string()) && has(err_, "key 'dimension'")) << err_;
  ASSERT_EQ(run(tg, dir_ / "d", "--set resolution.dx=0.04 --restart " + snap.string()), 2);
  EXPECT_TRUE(has(err_, snap.string()) && has(err_, "key 'resolution.dx'")) << err_;
}

// A snapshot without its restart state, and a truncated one: exit 2 naming the .restart file.
TEST_F(Restart, MissingOrTruncatedRestartStateIsRefused) {
  const fs::path tg = kCases / "taylor_green_2d.yaml";
  const std::string small = "--set resolution.dx=0.05 --set time.end=0.02 --set output.every=0.01 ";
  ASSERT_EQ(run(tg, dir_ / "a", small), 0) << err_;
  // output.restart: last (the default) keeps only the last snapshot's state.
  EXPECT_FALSE(fs::exists(dir_ / "a" / "particles_000001.restart"));
  const fs::path last = dir_ / "a" / "particles_000002.restart";
  ASSERT_TRUE(fs::exists(last));
  ASSERT_EQ(
      run(tg, dir_ / "b", small + "--restart " + (dir_ / "a" / "particles_000001.vtp").string()),
      2);
  EXPECT_TRUE(has(err_, "particles_000001.restart")) << err_;
  fs::resize_file(last, fs::file_size(last) - 100);
  ASSERT_EQ(
      run(tg, dir_ / "c", small + "--restart " + (dir_ / "a" / "particles_000002.vtp").string()),
      2);
  EXPECT_TRUE(has(err_, "particles_000002.restart") && has(err_, "truncated")) << err_;
}

// The format's own checks (solver/restart_state.cpp), on bytes: a round trip is exact, and
// each kind of damage is an InputError naming the file and the key.
TEST(RestartState, RoundTripAndDamage) {
  RestartState s;
  s.header["time"] = 0.1 + 0.2;
  s.header["steps"] = 7;
  s.reals["x"] = {1.0 / 3.0, -0.0, 1e-310};
  s.ints["id"] = {0, -1, 1LL << 62};
  const fs::path file = fs::temp_directory_path() / ("curvsph_rs_" + std::to_string(getpid()));
  write_restart_state(file, s);
  const RestartState r = read_restart_state(file);
  EXPECT_EQ(header_number(r, "time", "f"), 0.1 + 0.2);
  EXPECT_EQ(std::memcmp(r.reals.at("x").data(), s.reals.at("x").data(), 24), 0);
  EXPECT_EQ(r.ints.at("id"), s.ints.at("id"));
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(file);
  auto refusal = [](const std::string& b) {
    try {
      parse_restart_state(b, "s.restart");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_TRUE(has(refusal(bytes.substr(0, bytes.size() - 1)), "truncated"));
  EXPECT_TRUE(has(refusal(bytes + "x"), "trailing"));
  EXPECT_TRUE(has(refusal("garbage"), "s.restart"));
  std::string huge = bytes;
  huge.replace(huge.find("\"count\":3"), 9, "\"count\":9");
  EXPECT_TRUE(has(refusal(huge), "arrays.0"));
  EXPECT_THROW(header_integer(r, "time", "f"), InputError);  // 0.3 is not an integer
  EXPECT_THROW(real_array(r, "x", 4, "f"), InputError);
}

// Solver::load_state checks what the format cannot: array sizes against the particle count,
// phases against the case's fluids, the re-sort order a permutation. Against the state
// save_state wrote after two steps, which loads and continues to the same next step.
TEST(RestartState, SolverLoadChecksTheState) {
  const Case c = read_case(YAML::Load(R"(name: box
dimension: 2
resolution: {dx: 0.1, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1.0, viscosity: 0.01, velocity: [1.0, 0], region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {type: linear, c0: 10.0}
density: {method: continuity, shifting: 0.05}
time: {end: 0.1}
)"),
                           "box.yaml");
  Solver<2> a(c);
  a.initialize();
  a.step();
  a.step();
  RestartState s;
  a.save_state(s);
  EXPECT_EQ(s.ints.at("id").size(), 100u);
  Solver<2> b(c);
  b.load_state(s, "s.restart");
  b.initialize();
  a.step();
  b.step();
  EXPECT_EQ(a.time(), b.time());
  for (std::size_t i = 0; i < a.particles().size(); ++i) {
    EXPECT_EQ(a.particles().x[i], b.particles().x[i]) << i;
    EXPECT_EQ(a.particles().v[i], b.particles().v[i]) << i;
  }
  auto refusal = [&](RestartState bad) {
    Solver<2> d(c);
    try {
      d.load_state(bad, "s.restart");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  RestartState bad = s;
  bad.ints["phase"][7] = 3;
  EXPECT_TRUE(has(refusal(bad), "arrays.phase")) << refusal(bad);
  bad = s;
  bad.reals["velocity"].pop_back();
  EXPECT_TRUE(has(refusal(bad), "arrays.velocity")) << refusal(bad);
  bad = s;
  if (bad.ints.count("resort_order")) {
    bad.ints["resort_order"][0] = bad.ints["resort_order"][1];
    EXPECT_TRUE(has(refusal(bad), "arrays.resort_order")) << refusal(bad);
  }
  bad = s;
  bad.header.erase("steps");
  EXPECT_TRUE(has(refusal(bad), "key 'steps'")) << refusal(bad);
}

}  // namespace
}  // namespace curvsph
