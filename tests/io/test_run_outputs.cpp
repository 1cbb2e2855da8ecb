// The outputs of `curvsph run` (README, Outputs): the series read by VTK's own Python module
// (Debian python3-vtk9, the reader ParaView uses), named blocks, the boundary file written
// only when it changes, restarts from compressed float32 snapshots and the refusal of one
// that lacks a field, probes.csv only with probes; and the terminal: a progress line of at
// most 79 characters showing the CFL step, warnings printed with --quiet.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "../support/command_fixture.hpp"
#include "curvsph/io/pvd_series.hpp"
#include "curvsph/io/vtk_reader.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

const fs::path kCases = fs::path(CURVSPH_SOURCE_DIR) / "cases";

class RunOutputs : public testing::CommandTest {
 protected:
  int run_case(const fs::path& file, const fs::path& out, const std::string& args,
               bool quiet = true) {
    return run_curvsph("run " + file.string() + (quiet ? " -q" : "") + " --threads 1 --out " +
                       out.string() + " " + args);
  }
  // VTK's reading of the series (tests/io/read_series_vtk.py); skips when VTK is missing.
  nlohmann::json read_with_vtk(const fs::path& pvd) {
    const std::string cmd = "/usr/bin/python3 " + std::string(CURVSPH_SOURCE_DIR) +
                            "/tests/io/read_series_vtk.py " + pvd.string() + " >" +
                            (dir_ / "vtk.json").string() + " 2>" + (dir_ / "vtk.err").string();
    const int status = std::system(cmd.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == 4) return nullptr;
    EXPECT_EQ(code, 0) << read(dir_ / "vtk.err");
    return nlohmann::json::parse(read(dir_ / "vtk.json"));
  }
};

// Sum of all values of an array as our own reader decodes it (the oracle is VTK's decoding).
double sum_of(const io::VtkArray& a) {
  double s = 0;
  if (io::vtk_type_is_float(a.type))
    for (double v : a.converted<double>()) s += v;
  else
    for (std::int64_t v : a.converted<std::int64_t>()) s += static_cast<double>(v);
  return s;
}

// Taylor–Green at dx = 0.05 (400 particles), three snapshots with the default encoding
// (float32, zlib): VTK reads every file, the arrays are the default fields with 400 tuples,
// the times are those of the schedule, the block is named, and VTK's values equal those of
// our reader and of scripts/vtp.py.
TEST_F(RunOutputs, VtkPythonReadsTheSeries) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(run_case(kCases / "taylor_green_2d.yaml", out,
                     "--set resolution.dx=0.05 --set time.end=0.02 --set output.every=0.01"),
            0)
      << err_;
  const std::string head = read(out / "particles_000001.vtp").substr(0, 2000);
  EXPECT_NE(head.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(head.find("type=\"Float32\" Name=\"velocity\""), std::string::npos);
  const nlohmann::json vtk = read_with_vtk(out / "series.pvd");
  if (vtk.is_null()) GTEST_SKIP() << "python3-vtk9 is not installed: " << read(dir_ / "vtk.err");
  ASSERT_EQ(vtk.size(), 3u);
  const std::set<std::string> names{"Points", "velocity", "pressure", "density",
                                    "mass",   "phase",    "id"};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& e = vtk[k];
    EXPECT_NEAR(e["time"].get<double>(), 0.01 * static_cast<double>(k), 1e-12);
    EXPECT_EQ(e["name"], "particles");
    EXPECT_EQ(e["points"], 400);
    EXPECT_EQ(e["verts"], 400);
    std::set<std::string> got;
    for (const auto& [name, a] : e["arrays"].items()) {
      got.insert(name);
      EXPECT_EQ(a[0], 400) << name;
      EXPECT_EQ(a[1], name == "velocity" || name == "Points" ? 3 : 1) << name;
    }
    EXPECT_EQ(got, names);
    const io::VtkPolyData ours = io::read_vtp(out / e["file"].get<std::string>());
    for (const auto& [name, a] : e["arrays"].items()) {
      const double s = sum_of(name == "Points" ? ours.points() : ours.array(name));
      EXPECT_NEAR(a[2].get<double>(), s, 1e-9 * (1 + std::abs(s))) << name;
      // scripts/vtp.py decodes the same values.
      ASSERT_FALSE(a[3].is_null()) << name;
      EXPECT_NEAR(a[3].get<double>(), s, 1e-9 * (1 + std::abs(s))) << name;
    }
  }
}

// Boundary integrals: the wall elements are fixed, so boundary_000000.vtp is written once and
// every entry of the series lists it under the block name "boundary"; VTK reads it (kind 2).
// Ghosts follow the fluid: a boundary file per snapshot.
TEST_F(RunOutputs, BoundaryFileWrittenOnlyWhenItChanges) {
  const fs::path out = dir_ / "bi";
  ASSERT_EQ(run_case(kCases / "hydrostatic_tank.yaml", out,
                     "--set resolution.dx=0.05 --set setup.relax.max_steps=0 "
                     "--set time.end=0.006 --set output.every=0.002"),
            0)
      << err_;
  const auto entries = io::PvdSeries::read(out / "series.pvd");
  std::size_t boundary = 0;
  for (const auto& e : entries) {
    if (e.part > 1) continue;  // the walls' blocks (test_walls_output.cpp)
    EXPECT_EQ(e.name, e.part == 0 ? "particles" : "boundary");
    if (e.part == 1) {
      ++boundary;
      EXPECT_EQ(e.file, "boundary_000000.vtp");
    }
  }
  EXPECT_EQ(boundary, 4u);  // t = 0, 0.002, 0.004, 0.006
  EXPECT_FALSE(fs::exists(out / "boundary_000001.vtp"));
  const nlohmann::json vtk = read_with_vtk(out / "series.pvd");
  if (!vtk.is_null()) {
    ASSERT_EQ(vtk.size(), 12u);  // particles, boundary and the box wall at 4 times
    const auto& b = vtk[1];
    EXPECT_EQ(b["name"], "boundary");
    EXPECT_GT(b["points"].get<long>(), 0);
    // Every element has kind 2: the sum of the kinds is twice the count.
    EXPECT_EQ(b["arrays"]["kind"][2].get<double>(), 2.0 * b["points"].get<double>());
  }

  const fs::path ghosts = dir_ / "ghosts";
  ASSERT_EQ(run_case(kCases / "poiseuille_2d.yaml", ghosts,
                     "--set time.end=0.004 --set output.every=0.002"),
            0)
      << err_;
  std::set<std::string> files;
  for (const auto& e : io::PvdSeries::read(ghosts / "series.pvd"))
    if (e.part == 1) files.insert(e.file);
  EXPECT_EQ(files.size(), 3u);  // the ghosts moved with the fluid
}

// A restart continues from the float64 restart state beside a compressed float32 snapshot
// that holds only the velocity (output.fields): its next snapshot is numbered after it, and the
// state it starts from is the first run's to the bit, not the float32 fields.
TEST_F(RunOutputs, RestartFromCompressedFloat32SnapshotReadsTheFullState) {
  const fs::path tg = kCases / "taylor_green_2d.yaml";
  const std::string small =
      "--set resolution.dx=0.05 --set output.every=0.01 "
      "--set 'output.fields=[velocity]' ";
  const fs::path a = dir_ / "a";
  ASSERT_EQ(run_case(tg, a, small + "--set time.end=0.02 --set output.restart=every"), 0) << err_;
  ASSERT_TRUE(fs::exists(a / "particles_000001.restart"));
  const fs::path b = dir_ / "b";
  ASSERT_EQ(
      run_case(tg, b,
               small + "--set time.end=0.02 --restart " + (a / "particles_000001.vtp").string()),
      0)
      << err_;
  const auto m = nlohmann::json::parse(read(b / "metrics.json"));
  EXPECT_NEAR(m["time_reached"].get<double>(), 0.02, 1e-12);
  const auto entries = io::PvdSeries::read(b / "series.pvd");
  ASSERT_FALSE(entries.empty());
  EXPECT_EQ(entries.front().file, "particles_000002.vtp");
  EXPECT_FALSE(fs::exists(b / "particles_000000.vtp"));
  // Both runs end at t = 0.02 with the same velocities, to the bit (float32 files of equal
  // float64 states are equal).
  const Particles<2> x = io::read_particles<2>(a / "particles_000002.vtp");
  const Particles<2> y = io::read_particles<2>(b / "particles_000002.vtp");
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x.v[i], y.v[i]) << i;
}

// output.precision: float64, compress: none give the exact raw files.
TEST_F(RunOutputs, Float64UncompressedOnRequest) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(run_case(kCases / "taylor_green_2d.yaml", out,
                     "--set resolution.dx=0.05 --set time.end=0.01 --set output.every=0.01 "
                     "--set output.precision=float64 --set output.compress=none"),
            0)
      << err_;
  const std::string head = read(out / "particles_000000.vtp").substr(0, 2000);
  EXPECT_EQ(head.find("compressor"), std::string::npos);
  EXPECT_NE(head.find("type=\"Float64\" Name=\"velocity\""), std::string::npos);
}

// probes.csv is written when the case has probes, and only then (README, Outputs).
TEST_F(RunOutputs, ProbesCsvOnlyWithProbes) {
  const fs::path tg = kCases / "taylor_green_2d.yaml";
  const std::string small = "--set resolution.dx=0.05 --set time.end=0.01 ";
  ASSERT_EQ(run_case(tg, dir_ / "with", small), 0) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "with" / "probes.csv"));
  ASSERT_EQ(run_case(tg, dir_ / "without", small + "--set 'probes=[]'"), 0) << err_;
  EXPECT_FALSE(fs::exists(dir_ / "without" / "probes.csv"));
}

// Output every 1e-4 s, below the CFL step (0.25 h / (c0 + |v|) = 3e-3 at dx = 0.05): every
// step is cut to land on an output time, and the progress line shows the CFL step, not the
// cut one. Every line fits 79 characters in a pipe.
TEST_F(RunOutputs, ProgressShowsTheCflStepInAtMost79Characters) {
  const fs::path out = dir_ / "out";
  ASSERT_EQ(run_case(kCases / "taylor_green_2d.yaml", out,
                     "--set resolution.dx=0.05 --set time.end=0.001 --set output.every=1e-4 "
                     "--set output.vtk=false",
                     false),
            0)
      << err_;
  std::istringstream lines(err_);
  std::string line;
  double dt = -1;
  while (std::getline(lines, line)) {
    EXPECT_LE(line.size(), 79u) << line;
    std::smatch m;
    if (std::regex_search(line, m, std::regex("dt ([0-9.e+-]+)"))) dt = std::stod(m[1]);
  }
  EXPECT_GT(dt, 1e-3) << err_;  // the CFL step, not the 1e-4 cut
}

// A warning (packing stopped above its tolerance) is printed with --quiet.
TEST_F(RunOutputs, WarningsPrintedWithQuiet) {
  ASSERT_EQ(run_case(kCases / "taylor_green_2d.yaml", dir_ / "out",
                     "--set resolution.dx=0.05 --set time.end=0.001 --set setup.jitter=0.3 "
                     "--set 'setup.relax={max_steps: 1, tolerance: 1e-9}'"),
            0)
      << err_;
  EXPECT_NE(err_.find("warning:"), std::string::npos) << err_;
  EXPECT_NE(err_.find("setup.relax stopped"), std::string::npos) << err_;
}

}  // namespace
}  // namespace curvsph
