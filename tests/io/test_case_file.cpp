// Case files (DESIGN.md §3): every validation error names the file and the dotted key, `--set`
// overrides (list elements by index, new nested keys), YAML syntax errors name the line, and
// the built `curvsph run` exits with 2 on bad input and 3 (with a last snapshot) when unstable.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_overrides.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

// A small valid case; every error test breaks exactly one thing in it.
const char* const kValid = R"(
name: valid
dimension: 2
resolution: {dx: 0.01, h_over_dx: 1.3}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids:
  - name: water
    rho0: 1000
    viscosity: 1.0e-3
    region: {box: {min: [0, 0], max: [1, 1]}}
eos: {type: tait, c0: 10, gamma: 7, p0: 0}
density: {method: summation}
time: {end: 1.0, cfl: 0.2}
output: {every: 0.1}
)";

YAML::Node valid() {
  return YAML::Load(kValid);
}

// Reads the case after `edit`; expects an InputError for `key` whose reason contains `reason`.
void expect_error(const std::function<void(YAML::Node&)>& edit, const std::string& key,
                  const std::string& reason = "") {
  YAML::Node root = valid();
  edit(root);
  try {
    read_case(root, "dir/case.yaml");
    ADD_FAILURE() << "no error for key '" << key << "'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "dir/case.yaml");
    EXPECT_EQ(e.key(), key) << e.what();
    const std::string what = e.what();
    EXPECT_NE(what.find("dir/case.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("'" + key + "'"), std::string::npos) << what;
    EXPECT_NE(e.reason().find(reason), std::string::npos) << what;
  }
}

// The same through `--set` overrides applied to the valid tree.
void expect_error_set(const std::vector<std::string>& sets, const std::string& file,
                      const std::string& key, const std::string& reason = "") {
  YAML::Node root = valid();
  try {
    apply_overrides(root, sets);
    read_case(root, "dir/case.yaml");
    ADD_FAILURE() << "no error for key '" << key << "'";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
  }
}

TEST(CaseFile, ValidCaseReads) {
  const Case c = read_case(valid(), "dir/case.yaml");
  EXPECT_EQ(c.name, "valid");
  EXPECT_EQ(c.dimension, 2);
  EXPECT_DOUBLE_EQ(c.dx, 0.01);
  EXPECT_DOUBLE_EQ(c.h(), 0.013);
  ASSERT_EQ(c.fluids.size(), 1u);
  EXPECT_DOUBLE_EQ(c.fluids[0].rho0, 1000);
  EXPECT_TRUE(c.periodic[0] && c.periodic[1]);
  EXPECT_EQ(c.eos.type, EosSpec::Type::tait);
  EXPECT_DOUBLE_EQ(c.eos.c0, 10);
  EXPECT_DOUBLE_EQ(c.t_end, 1.0);
}

TEST(CaseFile, UnknownKeyTopLevel) {
  expect_error([](YAML::Node& r) { r["resolutoin"] = 1; }, "resolutoin", "unknown key");
}

TEST(CaseFile, UnknownKeyNested) {
  expect_error([](YAML::Node& r) { r["fluids"][0]["regon"] = 1; }, "fluids.0.regon", "unknown key");
  expect_error([](YAML::Node& r) { r["resolution"]["dy"] = 1; }, "resolution.dy", "unknown key");
  expect_error([](YAML::Node& r) { r["eos"]["c"] = 1; }, "eos.c", "unknown key");
  expect_error([](YAML::Node& r) { r["time"]["stop"] = 1; }, "time.stop", "unknown key");
  expect_error([](YAML::Node& r) { r["fluids"][0]["region"]["box"]["mx"] = 1; },
               "fluids.0.region.box.mx", "unknown key");
  expect_error([](YAML::Node& r) { r["fluids"][0]["region"] = YAML::Load("{cube: {}}"); },
               "fluids.0.region.cube", "unknown region");
}

TEST(CaseFile, UnknownKeyListsTheAllowedOnes) {
  YAML::Node root = valid();
  root["eos"]["gama"] = 7;
  try {
    read_case(root, "c.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.reason().find("gamma"), std::string::npos) << e.what();
  }
}

TEST(CaseFile, WrongTypeStringForNumber) {
  expect_error([](YAML::Node& r) { r["resolution"]["dx"] = "small"; }, "resolution.dx",
               "must be a finite number");
  expect_error([](YAML::Node& r) { r["fluids"][0]["rho0"] = "water"; }, "fluids.0.rho0",
               "must be a finite number");
  expect_error([](YAML::Node& r) { r["dimension"] = "two"; }, "dimension");
  expect_error([](YAML::Node& r) { r["time"]["end"] = YAML::Load("[1, 2]"); }, "time.end",
               "must be a finite number");
  expect_error([](YAML::Node& r) { r["dimension"] = 2.5; }, "dimension", "integer");
  expect_error([](YAML::Node& r) { r["output"]["vtk"] = "maybe"; }, "output.vtk", "true or false");
}

TEST(CaseFile, WrongTypeListOfWrongLength) {
  expect_error([](YAML::Node& r) { r["domain"]["min"] = YAML::Load("[0]"); }, "domain.min",
               "list of 2 numbers");
  expect_error([](YAML::Node& r) { r["gravity"] = YAML::Load("[0, 0, -9.81]"); }, "gravity",
               "list of 2 numbers");
  expect_error([](YAML::Node& r) { r["fluids"][0]["velocity"] = 1.0; }, "fluids.0.velocity",
               "list of 2 numbers");
  expect_error([](YAML::Node& r) { r["domain"]["periodic"] = YAML::Load("[true]"); },
               "domain.periodic", "list of 2 booleans");
  expect_error([](YAML::Node& r) { r["domain"]["periodic"] = YAML::Load("[true, 3]"); },
               "domain.periodic.1", "true or false");
  expect_error([](YAML::Node& r) { r["domain"]["max"] = YAML::Load("[1, x]"); }, "domain.max.1",
               "must be a finite number");
}

TEST(CaseFile, WrongTypeScalarWhereMapRequired) {
  expect_error([](YAML::Node& r) { r["resolution"] = 0.01; }, "resolution", "mapping");
  expect_error([](YAML::Node& r) { r["eos"] = "tait"; }, "eos", "mapping");
  expect_error([](YAML::Node& r) { r["time"] = YAML::Load("[1, 0.2]"); }, "time", "mapping");
  expect_error([](YAML::Node& r) { r["fluids"][0] = "water"; }, "fluids.0", "mapping");
  expect_error([](YAML::Node& r) { r["fluids"][0]["region"] = "box"; }, "fluids.0.region");
  expect_error([](YAML::Node& r) { r["fluids"] = YAML::Load("{water: 1}"); }, "fluids");
  expect_error([](YAML::Node& r) { r["walls"] = 3; }, "walls", "list");
  expect_error([](YAML::Node& r) { r["probes"] = "P1"; }, "probes", "list");
}

TEST(CaseFile, WrongChoice) {
  expect_error([](YAML::Node& r) { r["eos"]["type"] = "ideal_gas"; }, "eos.type", "tait | linear");
  expect_error([](YAML::Node& r) { r["density"]["method"] = "sph"; }, "density.method",
               "summation | continuity");
  expect_error([](YAML::Node& r) { r["boundary"]["method"] = "walls"; }, "boundary.method");
}

// pressure_gradient (physics/pressure_gradient.hpp): symmetric unless set, confined or not
// (the difference form alone clumps the particles: throttled_pipe/findings.md).
TEST(CaseFile, PressureGradientKey) {
  EXPECT_FALSE(read_case(valid(), "dir/case.yaml").pressure_difference);
  YAML::Node g = valid();
  g["domain"]["periodic"] = YAML::Load("[true, false]");
  g["gravity"] = YAML::Load("[0, -9.81]");
  EXPECT_FALSE(read_case(g, "dir/case.yaml").pressure_difference);
  YAML::Node d = valid();
  d["pressure_gradient"] = "difference";
  EXPECT_TRUE(read_case(d, "dir/case.yaml").pressure_difference);
  expect_error([](YAML::Node& r) { r["pressure_gradient"] = "consistent"; }, "pressure_gradient",
               "symmetric | difference");
}

TEST(CaseFile, MissingRequiredKeys) {
  expect_error([](YAML::Node& r) { r.remove("dimension"); }, "dimension", "missing");
  expect_error([](YAML::Node& r) { r["resolution"].remove("dx"); }, "resolution.dx", "missing");
  expect_error([](YAML::Node& r) { r.remove("resolution"); }, "resolution.dx", "missing");
  expect_error([](YAML::Node& r) { r.remove("fluids"); }, "fluids", "missing");
  expect_error([](YAML::Node& r) { r["fluids"] = YAML::Load("[]"); }, "fluids", "missing");
  expect_error([](YAML::Node& r) { r.remove("eos"); }, "eos", "missing");
  expect_error([](YAML::Node& r) { r["eos"].remove("c0"); }, "eos.c0", "missing");
  expect_error([](YAML::Node& r) { r.remove("time"); }, "time", "missing");
  expect_error([](YAML::Node& r) { r["time"].remove("end"); }, "time.end", "missing");
  expect_error([](YAML::Node& r) { r["fluids"][0].remove("rho0"); }, "fluids.0.rho0", "missing");
  expect_error([](YAML::Node& r) { r["fluids"][0].remove("region"); }, "fluids.0.region",
               "missing");
}

TEST(CaseFile, InconsistentValues) {
  expect_error([](YAML::Node& r) { r["resolution"]["h_over_dx"] = 0.5; }, "resolution.h_over_dx",
               "[0.8, 4]");
  expect_error([](YAML::Node& r) { r["resolution"]["h_over_dx"] = 4.5; }, "resolution.h_over_dx",
               "[0.8, 4]");
  expect_error([](YAML::Node& r) { r["resolution"]["dx"] = -0.01; }, "resolution.dx", "> 0");
  expect_error([](YAML::Node& r) { r["dimension"] = 4; }, "dimension", "2 or 3");
  // 2h = 0.026: an axis of 0.07 spans 2.7 supports.
  expect_error([](YAML::Node& r) { r["domain"]["max"] = YAML::Load("[1, 0.07]"); },
               "domain.periodic", "at least 3");
  expect_error([](YAML::Node& r) { r["domain"]["max"] = YAML::Load("[1, 0]"); }, "domain.max",
               "must exceed min");
  expect_error(
      [](YAML::Node& r) { r["fluids"][0]["region"]["box"]["max"] = YAML::Load("[0.5, 0]"); },
      "fluids.0.region.box.max", "must exceed min");
  expect_error(
      [](YAML::Node& r) {
        r["fluids"][0]["region"] = YAML::Load("{annulus: {center: [0, 0], r_in: 0.4, r_out: 0.3}}");
      },
      "fluids.0.region.annulus.r_out", "must exceed r_in");
  expect_error(
      [](YAML::Node& r) {
        r["fluids"][0]["region"] = YAML::Load("{annulus: {center: [0, 0], r_in: 0.3, r_out: 0.3}}");
      },
      "fluids.0.region.annulus.r_out", "must exceed r_in");
  expect_error([](YAML::Node& r) { r["density"]["delta_sph"] = 0.1; }, "density.delta_sph",
               "continuity");
  expect_error(
      [](YAML::Node& r) {
        r["walls"] = YAML::Load("[{shape: circle, center: [0, 0], radius: 1, fluid: inside}]");
      },
      "boundary.method", "ghost or integrals");
  expect_error([](YAML::Node& r) { r["eos"]["c0"] = 0; }, "eos.c0", "> 0");
  expect_error([](YAML::Node& r) { r["time"]["cfl"] = 1.5; }, "time.cfl", "<= 1");
  expect_error([](YAML::Node& r) { r["fluids"][0]["viscosity"] = -1; }, "fluids.0.viscosity",
               ">= 0");
  expect_error(
      [](YAML::Node& r) {
        r["fluids"][0]["region"] = YAML::Load("{ball: {center: [0, 0], radius: 1}}");
      },
      "fluids.0.region.ball", "3-D");
}

TEST(CaseFile, ContinuityAcceptsDeltaSph) {
  YAML::Node root = valid();
  root["density"] = YAML::Load("{method: continuity, delta_sph: 0.2}");
  const Case c = read_case(root, "c.yaml");
  EXPECT_EQ(c.density.method, DensitySpec::Method::continuity);
  EXPECT_DOUBLE_EQ(c.density.delta_sph, 0.2);
}

// Without a density key every case, confined or not, takes the continuity density with
// Antuono's delta-SPH term at 0.1; transport_velocity, whose density follows the transported
// positions, keeps summation.
TEST(CaseFile, DensityDefaultsToContinuityWithDeltaSph) {
  YAML::Node root = valid();
  root.remove("density");
  const Case c = read_case(root, "c.yaml");
  EXPECT_FALSE(c.free_surface_defaults);
  EXPECT_EQ(c.density.method, DensitySpec::Method::continuity);
  EXPECT_DOUBLE_EQ(c.density.delta_sph, 0.1);
  EXPECT_EQ(c.density.diffusion, DensitySpec::Diffusion::antuono);
  root["transport_velocity"] = YAML::Load("{}");
  EXPECT_EQ(read_case(root, "c.yaml").density.method, DensitySpec::Method::summation);
  root["density"] = YAML::Load("{method: continuity}");
  EXPECT_THROW(read_case(root, "c.yaml"), InputError);
}

TEST(CaseFile, SetWithoutEquals) {
  expect_error_set({"resolution.dx"}, "--set", "resolution.dx", "key.path=value");
  expect_error_set({"=3"}, "--set", "=3", "key.path=value");
}

TEST(CaseFile, SetIndexOutOfRange) {
  expect_error_set({"fluids.3.rho0=2"}, "--set", "fluids.3", "out of range");
  expect_error_set({"fluids.x.rho0=2"}, "--set", "fluids.x", "by index");
}

TEST(CaseFile, SetIntoScalar) {
  expect_error_set({"resolution.dx.value=2"}, "--set", "resolution.dx.value", "scalar");
  expect_error_set({"name.first=x"}, "--set", "name.first", "scalar");
}

TEST(CaseFile, SetInvalidYamlValue) {
  expect_error_set({"domain.min=[0, "}, "--set", "domain.min", "not valid YAML");
}

TEST(CaseFile, SetTypoGetsTheFileMessage) {
  // An override creates the key; validation then rejects it like a typo in the file.
  expect_error_set({"fluids.0.regon=1"}, "dir/case.yaml", "fluids.0.regon", "unknown key");
  expect_error_set({"resolution.dx=abc"}, "dir/case.yaml", "resolution.dx", "finite number");
}

TEST(CaseFile, SetListElementTakesEffect) {
  YAML::Node root = valid();
  apply_overrides(root, {"fluids.0.rho0=2", "fluids.0.velocity=[0.5, -1]",
                         "domain.periodic=[true, false]", "resolution.h_over_dx=2"});
  const Case c = read_case(root, "c.yaml");
  EXPECT_DOUBLE_EQ(c.fluids[0].rho0, 2);
  EXPECT_DOUBLE_EQ(c.fluids[0].velocity[0], 0.5);
  EXPECT_DOUBLE_EQ(c.fluids[0].velocity[1], -1);
  EXPECT_TRUE(c.periodic[0]);
  EXPECT_FALSE(c.periodic[1]);
  EXPECT_DOUBLE_EQ(c.h_over_dx, 2);
  EXPECT_EQ(c.fluids[0].name, "water");  // siblings untouched
}

TEST(CaseFile, SetNewNestedValueTakesEffect) {
  YAML::Node root = valid();
  root.remove("output");
  apply_overrides(root,
                  {"output.probe_every=0.25", "setup.random_seed=7", "time.dt_max=1e-4",
                   "forcing.drive.v0=0.5", "forcing.drive.tau=2", "fluids.1.rho0=1.5",
                   "fluids.1.region.disk.center=[0.5, 0.5]", "fluids.1.region.disk.radius=0.1"});
  const Case c = read_case(root, "c.yaml");
  EXPECT_DOUBLE_EQ(c.probe_every, 0.25);
  EXPECT_EQ(c.random_seed, 7u);
  EXPECT_DOUBLE_EQ(c.dt_max, 1e-4);
  EXPECT_TRUE(c.drive);
  EXPECT_DOUBLE_EQ(c.drive_v0, 0.5);
  EXPECT_DOUBLE_EQ(c.drive_tau, 2);
  ASSERT_EQ(c.fluids.size(), 2u);  // index == size appends an element
  EXPECT_DOUBLE_EQ(c.fluids[1].rho0, 1.5);
  EXPECT_EQ(c.fluids[1].region.kind, RegionSpec::Kind::disk);
  EXPECT_DOUBLE_EQ(c.fluids[1].region.radius, 0.1);
}

// Files on disk: YAML syntax errors, overrides through read_case(path, sets), the binary.
class CaseFileOnDisk : public curvsph::testing::CommandTest {
 protected:
  int run(const std::string& args) { return run_curvsph(args); }
};

TEST_F(CaseFileOnDisk, YamlSyntaxErrorNamesTheLine) {
  const fs::path p = write("broken.yaml",
                           "name: broken\n"
                           "dimension: 2\n"
                           "resolution: {dx: 0.01, h_over_dx: 1.3\n"
                           "eos: {c0: 10}\n");
  try {
    read_case(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), p.string());
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find("line 4"), std::string::npos) << what;
  }
  const fs::path q = write("tabs.yaml", "name: x\ndimension: 2\n  bad: [\n");
  try {
    read_case(q);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
}

TEST_F(CaseFileOnDisk, MissingFile) {
  try {
    read_case(dir_ / "nope.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "nope.yaml").string());
    EXPECT_NE(e.reason().find("cannot open"), std::string::npos);
  }
}

TEST_F(CaseFileOnDisk, OverridesApplyToTheFile) {
  const fs::path p = write("case.yaml", kValid);
  const Case c = read_case(p, {"fluids.0.rho0=2", "time.end=0.5"});
  EXPECT_DOUBLE_EQ(c.fluids[0].rho0, 2);
  EXPECT_DOUBLE_EQ(c.t_end, 0.5);
  EXPECT_EQ(c.file, p);
  EXPECT_DOUBLE_EQ(c.root["fluids"][0]["rho0"].as<double>(), 2);  // the tree after overrides
  try {
    read_case(p, {"fluids.0.regon=1"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), p.string());
    EXPECT_EQ(e.key(), "fluids.0.regon");
  }
}

TEST_F(CaseFileOnDisk, RunExitsWith2AndNamesFileAndKey) {
  std::string text = kValid;
  text.replace(text.find("    region:"), 11, "    regon:");
  const fs::path p = write("malformed.yaml", text);
  EXPECT_EQ(run("run " + p.string() + " --out " + (dir_ / "out").string() + " --quiet"), 2) << err_;
  EXPECT_NE(err_.find(p.string()), std::string::npos) << err_;
  EXPECT_NE(err_.find("fluids.0.regon"), std::string::npos) << err_;

  // A bad --set on a good file: exit 2 naming the override.
  const fs::path good = write("good.yaml", kValid);
  EXPECT_EQ(run("run " + good.string() + " --out " + (dir_ / "out").string() +
                " --quiet --set fluids.7.rho0=1"),
            2)
      << err_;
  EXPECT_NE(err_.find("fluids.7"), std::string::npos) << err_;
  // A missing case file: exit 2 naming it.
  EXPECT_EQ(run("run " + (dir_ / "absent.yaml").string() + " --quiet"), 2) << err_;
  EXPECT_NE(err_.find("absent.yaml"), std::string::npos) << err_;
}

// Taylor–Green at a coarse resolution (400 particles) with a flow speed of the sound speed
// (U = 10 = c0): the flow compresses, and the density leaves [0.5, 2] rho0 after ~15 steps
// (density.clamp: false; by default the density is clamped and the run goes on).
// Must exit 3, name the step and particle, and leave particles_unstable.vtp.
TEST_F(CaseFileOnDisk, UnstableRunExitsWith3AndLeavesSnapshot) {
  const fs::path tg = fs::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml";
  ASSERT_TRUE(fs::exists(tg));
  const fs::path out = dir_ / "out";
  const int code = run("run " + tg.string() + " --out " + out.string() +
                       " --quiet --threads 1 --set initial.taylor_green.U=10"
                       " --set analysis.taylor_green.U=10 --set resolution.dx=0.05"
                       " --set output.every=10 --set density.clamp=false");
  EXPECT_EQ(code, 3) << err_ << out_;
  EXPECT_NE(err_.find("unstable"), std::string::npos) << err_;
  EXPECT_NE(err_.find("density out of"), std::string::npos) << err_;
  EXPECT_NE(err_.find("particle "), std::string::npos) << err_;
  EXPECT_EQ(err_.find("step 0,"), std::string::npos) << "should go unstable mid-run: " << err_;
  EXPECT_TRUE(fs::exists(out / "particles_unstable.vtp")) << err_;
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
}

// With c0 = 0.1 the initial Taylor–Green pressure field maps to densities far outside
// [0.5, 2] rho0 (density.clamp: false): the run is unstable before its first step and must
// still exit 3 with a snapshot of the offending state.
TEST_F(CaseFileOnDisk, UnstableInitialStateExitsWith3AndLeavesSnapshot) {
  const fs::path tg = fs::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml";
  const fs::path out = dir_ / "out";
  const int code = run("run " + tg.string() + " --out " + out.string() +
                       " --quiet --threads 1 --set eos.c0=0.1 --set resolution.dx=0.05"
                       " --set density.clamp=false");
  EXPECT_EQ(code, 3) << err_ << out_;
  EXPECT_NE(err_.find("step 0"), std::string::npos) << err_;
  EXPECT_TRUE(fs::exists(out / "particles_unstable.vtp")) << err_;
}

// With the periodic VTK output turned off the unstable state is still written (and only it).
TEST_F(CaseFileOnDisk, UnstableRunWithVtkOffStillLeavesSnapshot) {
  const fs::path tg = fs::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml";
  const fs::path out = dir_ / "out";
  const int code =
      run("run " + tg.string() + " --out " + out.string() +
          " --quiet --threads 1 --set eos.c0=0.1 --set resolution.dx=0.05 --set density.clamp=false"
          " --set output.vtk=false");
  EXPECT_EQ(code, 3) << err_ << out_;
  EXPECT_TRUE(fs::exists(out / "particles_unstable.vtp")) << err_;
  EXPECT_FALSE(fs::exists(out / "particles_000000.vtp"));
}

// boundary.wall_particles was read and never used: it is an unknown key now.
TEST(CaseFile, WallParticlesIsAnUnknownKey) {
  expect_error([](YAML::Node& r) { r["boundary"]["wall_particles"] = true; },
               "boundary.wall_particles", "unknown key");
}

// output.precision, compress and fields (README, Outputs): defaults and bad values.
TEST(CaseFile, OutputEncodingKeys) {
  const Case d = read_case(valid(), "case.yaml");
  EXPECT_TRUE(d.output_float32);
  EXPECT_TRUE(d.output_zlib);
  EXPECT_EQ(d.output_fields, (std::vector<std::string>{"position", "velocity", "pressure",
                                                       "density", "mass", "phase", "id"}));
  YAML::Node r = valid();
  r["output"]["precision"] = "float64";
  r["output"]["compress"] = "none";
  r["output"]["fields"] = YAML::Load("[pressure, number_density, pressure]");
  const Case c = read_case(r, "case.yaml");
  EXPECT_FALSE(c.output_float32);
  EXPECT_FALSE(c.output_zlib);
  // position always, duplicates once, in the order given.
  EXPECT_EQ(c.output_fields, (std::vector<std::string>{"position", "pressure", "number_density"}));
  expect_error([](YAML::Node& n) { n["output"]["precision"] = "half"; }, "output.precision",
               "float32 | float64");
  expect_error([](YAML::Node& n) { n["output"]["compress"] = "gzip"; }, "output.compress",
               "zlib | none");
  expect_error([](YAML::Node& n) { n["output"]["fields"] = YAML::Load("[velocity, vel]"); },
               "output.fields.1", "'vel' is not one of");
  expect_error([](YAML::Node& n) { n["output"]["fields"] = "velocity"; }, "output.fields",
               "must be a list");
}

}  // namespace
}  // namespace curvsph
