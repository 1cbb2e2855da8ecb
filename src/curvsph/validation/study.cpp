#include "curvsph/validation/study.hpp"

#include <fmt/format.h>
#include <sys/wait.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "curvsph/solver/stop_signal.hpp"

namespace curvsph {

void write_study_outputs(const StudyContext& ctx, const StudyResult& r) {
  std::filesystem::create_directories(ctx.out_dir);
  std::ofstream(ctx.out_dir / "metrics.json") << r.metrics.dump(2) << '\n';
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : r.summary)
    rows.push_back({{"figure", s.figure},
                    {"value", s.value},
                    {"target", s.target},
                    {"reference", s.reference},
                    {"pass", s.pass}});
  std::ofstream(ctx.out_dir / "summary.json") << rows.dump(2) << '\n';
}

void run_plot_script(const StudyContext& ctx, const std::string& script,
                     const std::vector<std::string>& args) {
  const auto path = ctx.source_dir / "scripts" / script;
  std::string cmd = "/usr/bin/python3 '" + path.string() + "'";
  for (const auto& a : args) cmd += " '" + a + "'";
  const int rc = std::system(cmd.c_str());
  // Ctrl-C reaches the script, which std::system keeps from this process: pass it on.
  if (WIFSIGNALED(rc) && (WTERMSIG(rc) == SIGINT || WTERMSIG(rc) == SIGTERM))
    throw Interrupted{WTERMSIG(rc)};
  if (rc != 0) std::cerr << "warning: plotting failed (" << cmd << "), exit " << rc << "\n";
}

std::string summary_markdown(const std::vector<SummaryRow>& rows) {
  std::string s = "| figure | measured | target | reference | |\n|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    // A figure without a target (reported for comparison) is neither a pass nor a miss.
    const bool reported = r.target.rfind("reported", 0) == 0;
    s += fmt::format("| `{}` | {:.4g} | {} | {} | {} |\n", r.figure, r.value, r.target, r.reference,
                     r.pass ? (reported ? "reported" : "pass") : "**miss**");
  }
  return s;
}

}  // namespace curvsph
