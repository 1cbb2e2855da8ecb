// What `curvsph run` refuses up front and the guards of its time loop (issue 34): each bad
// input is exit 2 (3 where the physics fails) within seconds, with a message naming the file
// and the key, never a hang, a crash or lost output.
#include <gtest/gtest.h>
#include <omp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <thread>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/pvd_series.hpp"
#include "curvsph/setup/generate.hpp"
#include "curvsph/solver/run_guards.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

// A periodic box of 20 x 20 particles moving at a uniform velocity, with one probe.
constexpr const char* kBox = R"(name: box
dimension: 2
resolution: {dx: 0.05, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids:
  - name: fluid
    rho0: 1.0
    viscosity: 0.01
    velocity: [1.0, 0]
    region: {box: {min: [0, 0], max: [1, 1]}}
eos: {type: linear, c0: 10.0}
time: {end: 0.05}
output: {every: 0.01}
probes:
  - {name: C, point: [0.25, 0.25], fields: [p, vel]}
)";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class RunGuards : public testing::CommandTest {
 protected:
  static fs::path taylor_green() {
    return fs::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml";
  }
  // `run CASE -q --threads 1 --out DIR ARGS`; the seconds it took in seconds_.
  int run_case_file(const fs::path& file, const fs::path& out, const std::string& args) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc =
        run_curvsph("run " + file.string() + " -q --threads 1 --out " + out.string() + " " + args);
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return rc;
  }
  int run_tg(const std::string& args) {
    return run_case_file(taylor_green(), dir_ / "out", "--set resolution.dx=0.05 " + args);
  }
  double seconds_ = 0;
};

// --threads far above the processors used to crash (100000: segfault in the OpenMP start) or
// exit 1 (512); now capped at omp_get_num_procs() with a warning, and the run uses that many.
TEST_F(RunGuards, ThreadsAreCappedAtTheProcessorsWithAWarning) {
  const int procs = omp_get_num_procs();
  ASSERT_EQ(run_curvsph("run " + taylor_green().string() + " -q --out " + (dir_ / "out").string() +
                        " --set resolution.dx=0.05 --set time.end=0.01 --threads 100000"),
            0)
      << err_;
  EXPECT_TRUE(has(err_, "warning: --threads 100000")) << err_;
  EXPECT_TRUE(has(err_, "using " + std::to_string(procs))) << err_;
  EXPECT_EQ(nlohmann::json::parse(out_)["threads"].get<int>(), procs);
}

TEST_F(RunGuards, ThreadsBelowOneOrNotANumberAreExit2) {
  for (const char* bad : {"0", "-3", "abc", "1.5"}) {
    EXPECT_EQ(run_tg(std::string("--threads ") + bad), 2) << bad << ": " << err_;
    EXPECT_TRUE(has(err_, "--threads")) << err_;
    EXPECT_TRUE(has(err_, std::string("'") + bad + "'")) << err_;
  }
}

// time.end = 1e300 and output.probe_every = 1e-300 hung in the output schedule; output.every
// = 1e-12 wrote a snapshot every step. Each is now refused at once, naming the key.
TEST_F(RunGuards, HugeSnapshotOrProbeCountsAreRefusedUpFront) {
  EXPECT_EQ(run_tg("--set time.end=1e300"), 2) << err_;
  EXPECT_TRUE(has(err_, taylor_green().string()) && has(err_, "'output.every'")) << err_;
  EXPECT_TRUE(has(err_, "2e+301 snapshots") && has(err_, "--force")) << err_;
  EXPECT_LT(seconds_, 10);
  EXPECT_EQ(run_tg("--set output.probe_every=1e-300"), 2) << err_;
  EXPECT_TRUE(has(err_, "'output.probe_every'") && has(err_, "probe rows")) << err_;
  EXPECT_LT(seconds_, 10);
  EXPECT_EQ(run_tg("--set output.every=1e-12"), 2) << err_;
  EXPECT_TRUE(has(err_, "'output.every'") && has(err_, "1e+12 snapshots")) << err_;
  // time.max_steps bounds the count: the same schedule cut at 5 steps runs.
  EXPECT_EQ(run_tg("--set output.every=1e-12 --set time.max_steps=5"), 0) << err_;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "particles_000007.vtp"));  // 0..5 and the cut at most
}

// --force lets the 1e300 schedule through; the time step (about 3e-3) is then below
// 1e-12 time.end and the run stops at once with exit 3, naming the fastest particle.
TEST_F(RunGuards, ForcedScheduleOfAHugeEndCollapsesTheTimeStep) {
  EXPECT_EQ(run_tg("--set time.end=1e300 --force"), 3) << err_;
  EXPECT_TRUE(has(err_, "time step collapsed") && has(err_, "below 1e-12 time.end")) << err_;
  EXPECT_TRUE(has(err_, "particle ") && has(err_, "|v| = ")) << err_;
  EXPECT_LT(seconds_, 10);
}

// rho0 = 1e-300 and a velocity of 1e200 gave dt = 0 for ever; now exit 3 at the first step.
TEST_F(RunGuards, CollapsedTimeStepIsExit3NamingTheParticle) {
  EXPECT_EQ(run_tg("--set fluids.0.rho0=1e-300"), 3) << err_;
  EXPECT_TRUE(has(err_, "step 0") && has(err_, "time step collapsed")) << err_;
  EXPECT_TRUE(has(err_, "particle ")) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "particles_unstable.vtp"));
  const fs::path box = write("box.yaml", kBox);
  // Every particle moves at 1e150: dt = cfl h / (c0 + |v|) = 0.2 * 0.065 / 1e150 = 1.3e-152.
  EXPECT_EQ(run_case_file(box, dir_ / "v150", "--set fluids.0.velocity=[1e150,0]"), 3) << err_;
  EXPECT_TRUE(has(err_, "dt = 1.3e-152") && has(err_, "|v| = 1e+150")) << err_;
  EXPECT_EQ(run_case_file(box, dir_ / "v200", "--set fluids.0.velocity=[1e200,0]"), 3) << err_;
  EXPECT_TRUE(has(err_, "time step collapsed")) << err_;
  // The viscous limit 0.125 h^2 / nu names the fluid.
  EXPECT_EQ(run_case_file(box, dir_ / "nu", "--set fluids.0.viscosity=1e300"), 3) << err_;
  EXPECT_TRUE(has(err_, "viscous limit") && has(err_, "fluids.0")) << err_;
  EXPECT_LT(seconds_, 10);
}

// resolution.dx = 1e-6 allocated until bad_alloc (exit 1); dx = 1e-20 overflowed lround. Both
// are refused before any particle exists, with the count and the memory in the message.
TEST_F(RunGuards, ResolutionBeyondTheMemoryIsRefusedWithTheEstimate) {
  EXPECT_EQ(run_tg("--set resolution.dx=1e-6"), 2) << err_;
  EXPECT_TRUE(has(err_, taylor_green().string()) && has(err_, "'resolution.dx'")) << err_;
  EXPECT_TRUE(has(err_, "1e+12 particles") && has(err_, "physical memory")) << err_;
  EXPECT_LT(seconds_, 10);
  EXPECT_EQ(run_tg("--set resolution.dx=1e-20"), 2) << err_;
  EXPECT_TRUE(has(err_, "1e+40 particles")) << err_;
  // (1 / 0.05)^2 = 400 particles at kBytesPerParticle: over 100 kB, under 1 MB.
  EXPECT_EQ(run_tg("--set time.end=0.01 --max-memory 100kB"), 2) << err_;
  EXPECT_TRUE(has(err_, "400 particles") && has(err_, "--max-memory")) << err_;
  EXPECT_EQ(run_tg("--set time.end=0.01 --max-memory 1MB"), 0) << err_;
  EXPECT_EQ(run_tg("--max-memory 12x"), 2) << err_;
  EXPECT_TRUE(has(err_, "--max-memory") && has(err_, "'12x'")) << err_;
}

// The estimate against what generation makes: exact for a lattice filling a box, within the
// lattice's staircase error for a disk; the lattice refuses a count beyond long.
TEST(ParticleEstimate, MatchesGeneratedCounts) {
  Case c = read_case(fs::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml",
                     {"resolution.dx=0.05"});
  Particles<2> P;
  generate_particles<2>(c, P, WallSet<2>());
  EXPECT_DOUBLE_EQ(estimate_particle_count(c), 400);
  EXPECT_EQ(P.size(), 400u);
  RegionSpec disk;
  disk.kind = RegionSpec::Kind::disk;
  disk.radius = 0.3;
  const double n = static_cast<double>(generate_region(disk, 2, 0.01, "f", "k").size());
  c.fluids[0].region = disk;
  c.dx = 0.01;
  EXPECT_NEAR(estimate_particle_count(c), std::numbers::pi * 0.09 / 1e-4, 1e-9);
  EXPECT_NEAR(estimate_particle_count(c) / n, 1, 0.01);
  try {
    generate_region(c.fluids[0].region, 2, 1e-20, "f.yaml", "fluids.0.region");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "resolution.dx");
    EXPECT_EQ(e.file(), "f.yaml");
  }
}

// A run into a directory holding another run's files mixed both; now refused unless
// --overwrite, which removes the old files (a stale later snapshot included).
TEST_F(RunGuards, OutputDirectoryOfAnotherRunNeedsOverwrite) {
  const fs::path box = write("box.yaml", kBox), out = dir_ / "out";
  ASSERT_EQ(run_case_file(box, out, ""), 0) << err_;
  ASSERT_TRUE(fs::exists(out / "particles_000005.vtp"));
  EXPECT_EQ(run_case_file(box, out, "--set output.every=0.05"), 2) << err_;
  EXPECT_TRUE(has(err_, out.string()) && has(err_, "--overwrite")) << err_;
  EXPECT_TRUE(fs::exists(out / "particles_000005.vtp"));  // nothing touched
  EXPECT_EQ(run_case_file(box, out, "--set output.every=0.05 --overwrite"), 0) << err_;
  EXPECT_FALSE(fs::exists(out / "particles_000005.vtp"));
  EXPECT_EQ(io::PvdSeries::read(out / "series.pvd").size(), 2u);  // t = 0 and 0.05
  // --overwrite must not remove the snapshot a restart reads.
  EXPECT_EQ(
      run_case_file(box, out, "--overwrite --restart " + (out / "particles_000001.vtp").string()),
      2)
      << err_;
  EXPECT_TRUE(has(err_, "restart")) << err_;
  EXPECT_TRUE(fs::exists(out / "particles_000001.vtp"));
  // Files of other kinds do not count as another run.
  fs::create_directories(dir_ / "notes");
  write("notes/readme.txt", "kept");
  EXPECT_EQ(run_case_file(box, dir_ / "notes", ""), 0) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "notes" / "readme.txt"));
}

TEST_F(RunGuards, OutputAtAFileOrDevNullIsExit2) {
  const fs::path box = write("box.yaml", kBox), file = write("file.txt", "x");
  EXPECT_EQ(run_case_file(box, file, ""), 2) << err_;
  EXPECT_TRUE(has(err_, file.string()) && has(err_, "'--out'") && has(err_, "not a directory"))
      << err_;
  EXPECT_EQ(run_case_file(box, "/dev/null", ""), 2) << err_;
  EXPECT_TRUE(has(err_, "/dev/null") && has(err_, "not a directory")) << err_;
  EXPECT_EQ(run_case_file(box, file / "sub", ""), 2) << err_;
  EXPECT_TRUE(has(err_, "cannot create")) << err_;
}

// A directory as the case file exited 1; a NUL byte said "unknown escape character".
TEST_F(RunGuards, DirectoryOrNulByteAsCaseFileIsExit2) {
  EXPECT_EQ(run_case_file(dir_, dir_ / "out", ""), 2) << err_;
  EXPECT_TRUE(has(err_, dir_.string()) && has(err_, "is a directory")) << err_;
  std::string text = kBox;
  text.insert(text.find("dimension"), std::string("x: \"a\0g\"\n", 9));
  const fs::path nul = write("nul.yaml", text);
  ASSERT_EQ(fs::file_size(nul), text.size());
  EXPECT_EQ(run_case_file(nul, dir_ / "out", ""), 2) << err_;
  EXPECT_TRUE(has(err_, nul.string()) && has(err_, "NUL byte on line 2")) << err_;
  EXPECT_FALSE(has(err_, "escape")) << err_;
}

// A run cut by time.max_steps ends its snapshot and probe series with the state at the cut,
// labelled with the time it reached, and nothing beyond it.
TEST_F(RunGuards, MaxStepsCutEndsTheSeriesAtTheTimeReached) {
  const fs::path box = write("box.yaml", kBox), out = dir_ / "out";
  ASSERT_EQ(run_case_file(box, out, "--set time.max_steps=3"), 0) << err_;
  const auto m = nlohmann::json::parse(read(out / "metrics.json"));
  const double t = m["time_reached"];
  EXPECT_EQ(m["steps"].get<long>(), 3);
  EXPECT_GT(t, 0);
  EXPECT_LT(t, 0.01);  // three steps of about 1e-3 stop before the first output time
  const auto series = io::PvdSeries::read(out / "series.pvd");
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(series[0].time, 0);
  EXPECT_NEAR(series[1].time, t, 1e-15);
  std::istringstream probes(read(out / "probes.csv"));
  std::string line, last;
  int rows = 0;
  std::getline(probes, line);  // header
  while (std::getline(probes, line)) last = line, ++rows;
  EXPECT_EQ(rows, 2);
  EXPECT_NEAR(std::stod(last.substr(0, last.find(','))), t, 1e-8 * t);
}

// The output schedule by integer counters: output times are multiples of `every`, and an
// interval far below the round-off of t moves on in one call instead of looping.
TEST(OutputSchedule, CountsMultiplesOfEvery) {
  OutputSchedule s(0.05, 0, 1e-9);
  EXPECT_DOUBLE_EQ(s.next(), 0.05);
  EXPECT_FALSE(s.reached(0.049));
  EXPECT_TRUE(s.reached(0.05 - 1e-12));
  EXPECT_DOUBLE_EQ(s.next(), 0.1);
  EXPECT_TRUE(s.reached(0.23));  // overshot several: the next is after t
  EXPECT_DOUBLE_EQ(s.next(), 0.25);
  OutputSchedule restart(0.05, 0.1, 1e-9);  // a restart at an output time
  EXPECT_DOUBLE_EQ(restart.next(), 0.15000000000000002);
  OutputSchedule tiny(1e-20, 0, 1e-9);  // `next += every` looped 1e20 times to pass t = 1
  EXPECT_TRUE(tiny.reached(1.0));
  EXPECT_GT(tiny.next(), 1.0);
  EXPECT_LT(tiny.next(), 1.0 + 2e-9);
  OutputSchedule beyond(1e-300, 0, 1e291);  // k overflows: no time is ever reached
  EXPECT_FALSE(beyond.reached(1.0));
  EXPECT_TRUE(std::isinf(beyond.next()));
}

// `validate` ignored SIGINT: the stop ended the current run, and the study went on with the
// next. Now the stopped run writes its outputs, no further run or study starts, and the
// command exits 130 (128 + SIGINT) without the study's summary.
TEST_F(RunGuards, SigintStopsValidateAfterTheCurrentRun) {
  const fs::path out = dir_ / "val", study = out / "taylor_green";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string log = (dir_ / "validate.log").string();
    freopen(log.c_str(), "w", stderr);
    freopen("/dev/null", "w", stdout);
    execl(CURVSPH_BINARY, CURVSPH_BINARY, "validate", "taylor_green", "--quick", "--threads", "1",
          "--out", out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // The second resolution's probes.csv is opened just before its time loop.
  const fs::path probes = study / "dx_0.02" / "probes.csv";
  int status = 0;
  bool exited = false;
  for (int i = 0; i < 1200 && !fs::exists(probes); ++i) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_FALSE(exited) << "validate ended before the signal: " << read(dir_ / "validate.log");
  ASSERT_TRUE(fs::exists(probes)) << read(dir_ / "validate.log");
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto t0 = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  while (waitpid(pid, &status, WNOHANG) != pid) {
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(30)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      FAIL() << "validate did not stop within 30 s of SIGINT";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // Caught in the time loop: exit 130; arrived between runs: the default action, killed by
  // SIGINT (which a shell also reports as 130).
  const bool code130 = WIFEXITED(status) && WEXITSTATUS(status) == 130;
  const bool killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGINT;
  EXPECT_TRUE(code130 || killed) << "status " << status << ": " << read(dir_ / "validate.log");
  if (code130) {
    EXPECT_TRUE(has(read(dir_ / "validate.log"), "interrupted by signal 2"));
  }
  EXPECT_FALSE(fs::exists(study / "summary.json"));  // the study did not finish
  EXPECT_FALSE(fs::exists(study / "dx_0.02_tvf"));   // nor start its next run
}

}  // namespace
}  // namespace curvsph
