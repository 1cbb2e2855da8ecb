// `curvsph validate NAME|all [--quick] [--out DIR] [--threads N] [--seeds K]`
#include <fmt/format.h>
#include <omp.h>

#include <iostream>

#include "curvsph/app/command.hpp"
#include "curvsph/app/thread_option.hpp"
#include "curvsph/core/error.hpp"
#include "curvsph/solver/stop_signal.hpp"
#include "curvsph/validation/study.hpp"
#include "curvsph_build_paths.hpp"

namespace curvsph::app {
namespace {

struct ValidateArgs {
  std::string name;
  bool quick = false;
  std::string out = "docs/validation";
  std::string source = CURVSPH_SOURCE_DIR;
  int threads = 0;
  int seeds = 0;
};

const CommandRegistration reg{
    Command{"validate",
            "Run a validation study against its analytic or experimental reference (tables, plots)",
            [](CLI::App& sub) -> std::function<int()> {
              auto a = std::make_shared<ValidateArgs>();
              std::string names;
              for (const auto& s : validation_studies())
                names += "\n  " + s.name + ": " + s.description;
              sub.add_option("name", a->name, "study name or 'all'; studies:" + names)->required();
              sub.add_flag("--quick", a->quick, "reduced resolution and duration (smoke test)");
              sub.add_option("--out", a->out, "root of the study outputs (docs/validation)")
                  ->capture_default_str();
              sub.add_option("--source", a->source, "repository root (cases/, scripts/)")
                  ->capture_default_str();
              add_threads_option(sub, a->threads);
              sub.add_option("--seeds", a->seeds,
                             "random initialisations per configuration, for studies that have them "
                             "(0: the study's default)");
              return [a] {
                // SIGINT / SIGTERM: the current run ends after its step and writes its
                // outputs, then no further run or study starts; exit 128 + signal.
                stop_ends_program(true);
                const int threads = checked_threads(a->threads);
                bool found = false;
                for (const auto& s : validation_studies()) {
                  if (a->name != "all" && a->name != s.name) continue;
                  found = true;
                  StudyContext ctx{std::filesystem::path(a->out) / s.name, a->source, a->quick,
                                   threads, a->seeds};
                  if (threads > 0) omp_set_num_threads(threads);
                  std::cerr << "validate " << s.name << (a->quick ? " (quick)" : "") << " -> "
                            << ctx.out_dir.string() << "\n";
                  const StudyResult r = s.run(ctx);
                  write_study_outputs(ctx, r);
                  std::cout << "## " << s.name << "\n\n" << summary_markdown(r.summary) << "\n";
                }
                if (!found)
                  throw InputError("", "validate " + a->name, "unknown study (see --help)");
                return 0;
              };
            },
            40}};

}  // namespace
}  // namespace curvsph::app
