// The parameters of the analyses and initial flow fields (`analysis.NAME`, `initial.NAME`) are
// checked by their rows in io/schema_table.cpp (io/schema_section.hpp, issue 34 item 1): the
// reference is the table itself — every row with a range refuses a value just outside it and
// accepts one inside, whatever the analysis's own code checks.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "../support/command_fixture.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/io/case_schema.hpp"
#include "curvsph/io/schema_section.hpp"

namespace curvsph {
namespace {

using schema::Key;
using schema::Type;

// The sections `analysis.NAME` and `initial.NAME` of the table and their parameter rows.
bool is_section(const Key& k) {
  const auto dots = std::count(k.path.begin(), k.path.end(), '.');
  return dots == 1 && (k.path.rfind("analysis.", 0) == 0 || k.path.rfind("initial.", 0) == 0);
}

// A value inside the row's range (the text YAML reads back as it).
std::string inside(const Key& k) {
  if (k.type == Type::choice) return k.choices.front();
  if (k.type == Type::string) return "all";
  const schema::Range& r = k.range;
  double v = r.lo > -1e308 ? r.lo + (r.lo_open ? 1 : 0) : 0.0;
  if (r.hi < 1e308 && !r.contains(v)) v = 0.5 * (r.lo + r.hi);
  if (k.type == Type::integer) return std::to_string(static_cast<long>(std::ceil(v)));
  return std::to_string(v);
}

// The section `path` with every required parameter set inside its range.
YAML::Node valid_section(const std::string& path) {
  YAML::Node n(YAML::NodeType::Map);
  for (const auto& name : schema::children(path)) {
    const Key* k = schema::find(path + "." + name);
    if (k->fallback == "required") n[name] = YAML::Load(inside(*k));
  }
  return n;
}

// The InputError of check_section, or "" when it accepts the section.
std::string error_of(const YAML::Node& n, const std::string& path, std::string* key = nullptr) {
  try {
    schema::check_section(n, "c.yaml", path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "c.yaml");
    if (key) *key = e.key();
    return e.what();
  }
  return "";
}

TEST(SchemaSection, EveryRangeOfAnAnalysisOrInitialRowIsEnforced) {
  int sections = 0, bounds = 0;
  for (const Key& s : schema::keys()) {
    if (!is_section(s)) continue;
    ++sections;
    EXPECT_EQ(error_of(valid_section(s.path), s.path), "") << s.path;
    for (const auto& name : schema::children(s.path)) {
      const Key& k = *schema::find(s.path + "." + name);
      if (k.type != Type::number && k.type != Type::integer) continue;
      YAML::Node n = valid_section(s.path);
      n[name] = YAML::Load(inside(k));
      EXPECT_EQ(error_of(n, s.path), "") << k.path;
      // Just below the lower bound (at it when open), just above the upper bound.
      for (const double bad : {k.range.lo_open ? k.range.lo : k.range.lo - 1,
                               k.range.hi_open ? k.range.hi : k.range.hi + 1}) {
        if (std::abs(bad) >= 1e308) continue;
        ++bounds;
        n[name] = bad;
        std::string key;
        const std::string e = error_of(n, s.path, &key);
        EXPECT_EQ(key, k.path) << e;
        EXPECT_NE(e.find("must be"), std::string::npos) << e;
      }
      if (k.type == Type::integer) continue;
      n[name] = std::nan("");
      std::string key;
      EXPECT_NE(error_of(n, s.path, &key).find("finite"), std::string::npos) << k.path;
      EXPECT_EQ(key, k.path);
    }
  }
  EXPECT_GE(sections, 15);  // the analyses and initial fields of the table
  EXPECT_GE(bounds, 8);
}

TEST(SchemaSection, TypesUnknownAndMissingKeysNameTheKey) {
  std::string key;
  // An integer row given a fraction, a number row given text, a choice outside its choices.
  EXPECT_NE(
      error_of(YAML::Load("{sections: 48.5}"), "analysis.throttled_pipe", &key).find("integer"),
      std::string::npos);
  EXPECT_EQ(key, "analysis.throttled_pipe.sections");
  EXPECT_NE(error_of(YAML::Load("{U: fast}"), "analysis.taylor_green", &key).find("'fast'"),
            std::string::npos);
  EXPECT_EQ(key, "analysis.taylor_green.U");
  EXPECT_NE(error_of(YAML::Load("{velocity: still}"), "initial.throttled_pipe", &key)
                .find("rest | lubrication"),
            std::string::npos);
  EXPECT_EQ(key, "initial.throttled_pipe.velocity");
  // An analysis without parameters takes none; a parameter list is not a map.
  EXPECT_NE(error_of(YAML::Load("{omega: 1}"), "analysis.couette", &key).find("unknown key"),
            std::string::npos);
  EXPECT_EQ(key, "analysis.couette.omega");
  EXPECT_NE(error_of(YAML::Load("[1, 2]"), "analysis.hydrostatic", &key).find("expected a map"),
            std::string::npos);
  EXPECT_EQ(key, "analysis.hydrostatic");
  // A required parameter left out, also when the whole section is empty.
  EXPECT_NE(error_of(YAML::Load("{bottom: 0}"), "initial.hydrostatic", &key).find("missing"),
            std::string::npos);
  EXPECT_EQ(key, "initial.hydrostatic.depth");
  EXPECT_NE(error_of(YAML::Node(), "analysis.dam_break", &key).find("missing"), std::string::npos);
  EXPECT_EQ(key, "analysis.dam_break.experiment");
  // Sections without required parameters accept nothing at all.
  EXPECT_EQ(error_of(YAML::Node(), "analysis.taylor_green"), "");
  EXPECT_EQ(error_of(YAML::Load("{}"), "analysis.poiseuille"), "");
}

class SchemaSectionRun : public testing::CommandTest {};

// Infinity passed the Taylor–Green field's own check (U > 0); the row's finiteness refuses it
// before any particle is made: exit 2 naming the case file and the key.
TEST_F(SchemaSectionRun, InfiniteInitialVelocityIsExit2NamingFileAndKey) {
  const auto tg = std::filesystem::path(CURVSPH_SOURCE_DIR) / "cases" / "taylor_green_2d.yaml";
  const int code = run_curvsph("run " + tg.string() + " --out " + (dir_ / "out").string() +
                               " --quiet --threads 1 --set resolution.dx=0.05"
                               " --set initial.taylor_green.U=.inf");
  EXPECT_EQ(code, 2) << err_;
  EXPECT_NE(err_.find("taylor_green_2d.yaml: key 'initial.taylor_green.U'"), std::string::npos)
      << err_;
  EXPECT_NE(err_.find("finite"), std::string::npos) << err_;
}

}  // namespace
}  // namespace curvsph
