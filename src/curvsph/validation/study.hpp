#pragma once
// Validation studies (`curvsph validate NAME|all [--quick]`): each runs its cases, compares
// with the analytic or experimental reference and writes, under docs/validation/NAME/, CSV
// data, PNG plots (scripts/plot_*.py), a markdown table (README.md) and metrics.json.
// It also returns summary rows that `make validate` collects into docs/validation/README.md.
// A new study is one new file plus one line in registry.cpp.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace curvsph {

struct StudyContext {
  std::filesystem::path out_dir;     // docs/validation/NAME
  std::filesystem::path source_dir;  // repository root (cases/, scripts/)
  bool quick = false;                // a reduced run for smoke testing
  int threads = 0;
  int seeds = 0;  // random initialisations per configuration where a study has them; 0: its default
};

// One row of the validation summary: a figure, its measured value and its target.
struct SummaryRow {
  std::string figure;
  double value = 0;
  std::string target;     // e.g. "<= 0.05"
  std::string reference;  // where the target or reference value comes from
  bool pass = false;
};

struct StudyResult {
  nlohmann::json metrics = nlohmann::json::object();
  std::vector<SummaryRow> summary;
};

struct Study {
  std::string name;
  std::string description;
  std::function<StudyResult(const StudyContext&)> run;
};

const std::vector<Study>& validation_studies();

// Writes metrics.json and summary.json into ctx.out_dir.
void write_study_outputs(const StudyContext& ctx, const StudyResult& r);
// Runs a plotting script with Debian's python3 (matplotlib); warns instead of failing when
// python3-matplotlib is missing, so a solver-only machine can still validate.
void run_plot_script(const StudyContext& ctx, const std::string& script,
                     const std::vector<std::string>& args);
// Markdown table of summary rows.
std::string summary_markdown(const std::vector<SummaryRow>& rows);

}  // namespace curvsph
