// The one schema of the input keys (io/case_schema.hpp, io/schema_table.cpp): every shipped
// case reads through it in strict mode, its defaults are the parser's, docs/keys.md is its
// current rendering, duplicate YAML keys are refused, and echoed input is clipped and escaped.
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "curvsph/core/error.hpp"
#include "curvsph/geometry/wall_parser.hpp"
#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/quote.hpp"
#include "curvsph/io/yaml_read.hpp"
#include "curvsph/physics/contact_angle.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Strict mode on for the test's duration (the suite's default, set again in case a test
// binary is built without tests/io/schema_strict_mode.cpp).
struct Strict {
  Strict() { schema::set_strict(true); }
};

TEST(CaseSchema, TableRowsParseAndPathsAreUnique) {
  const auto& keys = schema::keys();
  ASSERT_GT(keys.size(), 100u);
  std::set<std::string> seen;
  for (const auto& k : keys) {
    EXPECT_TRUE(seen.insert(k.path).second) << k.path;
    EXPECT_FALSE(k.meaning.empty()) << k.path;
    EXPECT_FALSE(k.unit.empty()) << k.path;
    // Every key's parent section is declared too (so that `keys PREFIX` and the unknown-key
    // lists find it).
    const auto dot = k.path.rfind('.');
    if (dot != std::string::npos) {
      std::string parent = k.path.substr(0, dot);
      if (parent.size() > 2 && parent.substr(parent.size() - 2) == ".*")
        parent.resize(parent.size() - 2);
      EXPECT_NE(schema::find(parent), nullptr) << k.path;
    }
  }
}

TEST(CaseSchema, PathsMapIndicesToStars) {
  EXPECT_EQ(schema::pattern("walls.12.motion.rotate.omega"), "walls.*.motion.rotate.omega");
  EXPECT_EQ(schema::pattern("resolution.dx"), "resolution.dx");
  ASSERT_NE(schema::find("walls.3.radius"), nullptr);
  EXPECT_EQ(schema::find("walls.3.radius")->path, "walls.*.radius");
  // A nested list element takes its list's entry (NURBS surface control points).
  ASSERT_NE(schema::find_element("walls.0.control_points.2.1.0"), nullptr);
  EXPECT_EQ(schema::find_element("walls.0.control_points.2.1.0")->path, "walls.*.control_points");
  EXPECT_FALSE(schema::governs("run.mode"));
  EXPECT_TRUE(schema::governs("boundary.contact"));
}

TEST(CaseSchema, UndeclaredReadIsAProgrammingErrorInStrictMode) {
  Strict on;
  EXPECT_THROW(schema::lookup("boundary.no_such_key"), std::logic_error);
  EXPECT_NO_THROW(schema::lookup("boundary.contact"));
  EXPECT_NO_THROW(schema::lookup("my_test_prefix.anything"));  // not a case key
  EXPECT_THROW(schema::check_default("boundary.contact", 0.2), std::logic_error);
  EXPECT_NO_THROW(schema::check_default("boundary.contact", 0.1));
  EXPECT_THROW(schema::check_default("boundary.method", "ghost"), std::logic_error);
  EXPECT_THROW(schema::check_option("boundary.method", "spheres"), std::logic_error);
  schema::set_strict(false);
  EXPECT_NO_THROW(schema::lookup("boundary.no_such_key"));
  schema::set_strict(true);
}

TEST(CaseSchema, RangesComeFromTheTable) {
  try {
    schema::check_number("c.yaml", "boundary.contact", 0.7);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "boundary.contact");
    EXPECT_NE(e.reason().find("[0, 0.5)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(schema::check_number("c.yaml", "walls.0.scale", 1e300), InputError);
  EXPECT_THROW(schema::check_number("c.yaml", "walls.0.semi_axes.1", -1), InputError);
  EXPECT_NO_THROW(schema::check_number("c.yaml", "walls.0.semi_axes.1", 2));
}

// Every shipped case, walls and contact angles included, reads in strict mode: no key the
// cases use lacks its row.
TEST(CaseSchema, EveryShippedCaseReadsInStrictMode) {
  Strict on;
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(CURVSPH_SOURCE_DIR) / "cases")) {
    if (e.path().extension() != ".yaml") continue;
    ++n;
    SCOPED_TRACE(e.path().string());
    const Case c = read_case(e.path());
    if (!c.root["walls"]) continue;
    if (c.dimension == 2) {
      EXPECT_NO_THROW(parse_walls<2>(c.root["walls"], c.file_name(), c.file.parent_path()));
      EXPECT_NO_THROW(
          parse_contact_angles<2>(c.root["walls"], c.file_name(), c.file.parent_path()));
    } else {
      EXPECT_NO_THROW(parse_walls<3>(c.root["walls"], c.file_name(), c.file.parent_path()));
    }
  }
  for (const auto& e :
       fs::directory_iterator(fs::path(CURVSPH_SOURCE_DIR) / "cases" / "geometry")) {
    if (e.path().extension() != ".yaml") continue;
    ++n;
    SCOPED_TRACE(e.path().string());
    const YAML::Node root = yaml::load_file(e.path().string());
    const long dim = yaml::read_key(root, "dimension", e.path().string(), "", yaml::read_integer);
    if (dim == 2)
      EXPECT_NO_THROW(parse_walls<2>(root["walls"], e.path().string(), e.path().parent_path()));
    else
      EXPECT_NO_THROW(parse_walls<3>(root["walls"], e.path().string(), e.path().parent_path()));
  }
  EXPECT_GE(n, 20);
}

// Every key written in a shipped case (analysis and initial parameters included, which their
// analyses read themselves) has its row: the walk visits every map key and list element.
void expect_declared(const YAML::Node& node, const std::string& path, const std::string& file) {
  if (!path.empty()) {
    EXPECT_TRUE(schema::find(path) || schema::find_element(path))
        << file << ": " << path << " (" << schema::pattern(path) << ") has no row";
  }
  if (node.IsMap())
    for (const auto& kv : node)
      expect_declared(kv.second, yaml::join(path, kv.first.Scalar()), file);
  else if (node.IsSequence())
    for (std::size_t i = 0; i < node.size(); ++i)
      expect_declared(node[i], yaml::join(path, i), file);
}

TEST(CaseSchema, EveryKeyOfTheShippedCasesIsDeclared) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(CURVSPH_SOURCE_DIR) / "cases")) {
    if (e.path().extension() != ".yaml") continue;
    ++n;
    expect_declared(yaml::load_file(e.path().string()), "", e.path().string());
  }
  EXPECT_GE(n, 20);
}

// The parser's defaults are the table's: a minimal case leaves every key below out.
TEST(CaseSchema, ParsedDefaultsEqualTheTable) {
  const Case c = read_case(YAML::Load(R"(
dimension: 2
resolution: {dx: 0.1}
domain: {min: [0, 0], max: [1, 1], periodic: [true, true]}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {c0: 10}
density: {method: continuity}
setup: {relax: {}}
time: {end: 1}
)"),
                           "minimal.yaml");
  const auto d = [](const char* key) {
    const auto v = schema::default_number(key);
    EXPECT_TRUE(v.has_value()) << key;
    return v.value_or(-12345);
  };
  EXPECT_EQ(c.h_over_dx, d("resolution.h_over_dx"));
  EXPECT_EQ(c.eos.gamma, d("eos.gamma"));
  EXPECT_EQ(c.eos.p0, d("eos.p0"));
  EXPECT_EQ(c.fluids[0].viscosity, d("fluids.*.viscosity"));
  EXPECT_EQ(c.density.delta_sph, d("density.delta_sph"));
  EXPECT_EQ(c.shifting, d("density.shifting"));
  EXPECT_EQ(c.boundary.contact, d("boundary.contact"));
  EXPECT_EQ(c.boundary.wall_force, d("boundary.wall_force") != 0);
  EXPECT_EQ(c.boundary.wall_tension, d("boundary.wall_tension") != 0);
  EXPECT_EQ(c.cfl, d("time.cfl"));
  EXPECT_EQ(c.dt_max, d("time.dt_max"));
  EXPECT_EQ(c.max_steps, d("time.max_steps"));
  EXPECT_EQ(c.max_removed_fraction, d("time.max_removed_fraction"));
  EXPECT_EQ(c.random_seed, d("setup.random_seed"));
  EXPECT_EQ(c.jitter, d("setup.jitter"));
  EXPECT_EQ(c.relax.max_steps, d("setup.relax.max_steps"));
  EXPECT_EQ(c.relax.tolerance, d("setup.relax.tolerance"));
  EXPECT_EQ(c.output_every, d("output.every"));
  EXPECT_EQ(c.probe_every, d("output.probe_every"));
  EXPECT_EQ(c.write_vtk, d("output.vtk") != 0);
  EXPECT_EQ(c.rebalance_imbalance, d("parallel.rebalance_imbalance"));
  EXPECT_EQ(c.check_conservation, d("parallel.check_conservation") != 0);
  const auto s = [](const char* key) { return schema::find(key)->fallback; };
  EXPECT_EQ(c.boundary.method, s("boundary.method"));
  EXPECT_EQ(c.boundary.map, s("boundary.map"));
  EXPECT_EQ(c.boundary.velocity, s("boundary.velocity"));
  EXPECT_EQ(c.boundary.shepard, s("boundary.shepard"));
  EXPECT_EQ(c.boundary.pressure, s("boundary.pressure"));
  EXPECT_EQ(c.boundary.penetration_stop, s("boundary.penetration") == "stop");
  EXPECT_EQ(c.eos.type == EosSpec::Type::tait, s("eos.type") == "tait");
  EXPECT_EQ(c.output_float32, s("output.precision") == "float32");
  EXPECT_EQ(c.output_zlib, s("output.compress") == "zlib");
  EXPECT_EQ(c.density.diffusion == DensitySpec::Diffusion::antuono,
            s("density.diffusion_term") == "antuono");
  EXPECT_EQ(c.halo_rule == Case::HaloRule::automatic, s("parallel.halo_rule") == "auto");
}

// docs/keys.md is the schema's current rendering (`make keys` regenerates it).
TEST(CaseSchema, KeysReferenceIsCurrent) {
  const fs::path doc = fs::path(CURVSPH_SOURCE_DIR) / "docs" / "keys.md";
  ASSERT_TRUE(fs::exists(doc));
  EXPECT_TRUE(slurp(doc) == schema::render_markdown())
      << "docs/keys.md is stale: run `make keys` (build/curvsph keys --markdown > docs/keys.md)";
}

TEST(CaseSchema, UnknownKeyListsTheTablesKeys) {
  try {
    read_case(YAML::Load(R"(
dimension: 2
resolution: {dx: 0.1}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {c0: 10}
boundary: {methd: ghost}
time: {end: 1}
)"),
              "u.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "boundary.methd");
    for (const std::string& k : schema::children("boundary"))
      EXPECT_NE(e.reason().find(k), std::string::npos) << k << ": " << e.what();
  }
}

TEST(InputQuote, ClipsTo80AndEscapesNonPrintables) {
  EXPECT_EQ(clip("abc"), "abc");
  EXPECT_EQ(clip(std::string("a\0b\x7f\xff\n", 6)), "a\\x00b\\x7f\\xff\\x0a");
  EXPECT_EQ(clip("a\\b"), "a\\x5cb");
  const std::string big(10'000'000, 'x');
  const std::string c = clip(big);
  EXPECT_EQ(c, std::string(80, 'x') + "... (10000000 bytes)");
  EXPECT_EQ(quote("ok"), "'ok'");
}

// yaml-cpp keeps both entries of a duplicated key in the map node (node[key] answers the
// first): the loader must see and refuse it.
TEST(YamlDuplicates, YamlCppKeepsBothEntries) {
  const YAML::Node n = YAML::Load("{a: 1, b: 2, a: 3}");
  int a = 0;
  for (const auto& kv : n) a += kv.first.Scalar() == "a";
  EXPECT_EQ(a, 2);
  EXPECT_EQ(n["a"].as<int>(), 1);
}

TEST(YamlDuplicates, LoaderRefusesNamingFileKeyAndLine) {
  const fs::path p =
      fs::temp_directory_path() / ("curvsph_dup_" + std::to_string(getpid()) + ".yaml");
  std::ofstream(p) << "dimension: 2\nwalls:\n  - {shape: circle, radius: 1, radius: 2}\n";
  try {
    yaml::load_file(p.string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), p.string());
    EXPECT_EQ(e.key(), "walls.0.radius");
    EXPECT_NE(e.reason().find("duplicate key"), std::string::npos) << e.what();
    EXPECT_NE(e.reason().find("line 3"), std::string::npos) << e.what();
  }
  fs::remove(p);
}

// A duplicate that comes in a --set value is refused too (without a line: the line would be
// the override's, not the file's).
TEST(YamlDuplicates, InAnOverrideValue) {
  const fs::path p =
      fs::temp_directory_path() / ("curvsph_dup_set_" + std::to_string(getpid()) + ".yaml");
  std::ofstream(p) << R"(dimension: 2
resolution: {dx: 0.1}
fluids: [{rho0: 1000, region: {box: {min: [0, 0], max: [1, 1]}}}]
eos: {c0: 10}
time: {end: 1}
)";
  EXPECT_NO_THROW(read_case(p, {"domain={min: [0, 0], max: [1, 1]}"}));
  try {
    read_case(p, {"domain={min: [0, 0], min: [1, 1]}"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), p.string());
    EXPECT_EQ(e.key(), "domain.min");
    EXPECT_EQ(e.reason(), "duplicate key");
  }
  fs::remove(p);
}

}  // namespace
}  // namespace curvsph
