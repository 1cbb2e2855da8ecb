#pragma once
// Finished runs of a validation study, kept for the next invocation of the study: runs that
// take hours (the finer hydrostatic tanks) are not redone when only the report, a plot or
// another run changed. RUN/study_run.json holds the case file's fingerprint (io/case_key.hpp),
// the overrides the run was made with and its metrics; a run is reused only while both are
// unchanged. Code changes are not part of the key: delete RUN/ (or the whole study folder) to
// redo a run with a new build.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "curvsph/solver/run.hpp"

namespace curvsph {

// The metrics of the run kept in `dir`, or null when there is none, it is unreadable, or it
// was made from another case file or with other overrides.
nlohmann::json cached_run(const std::filesystem::path& dir, const std::string& case_fingerprint,
                          const std::vector<std::string>& overrides);

// Keeps a finished run's metrics in `dir` (which must exist) for cached_run. A run stopped by a
// signal (metrics "stopped" = 1) is not kept: throws std::runtime_error, ending the study.
void store_run(const std::filesystem::path& dir, const std::string& case_fingerprint,
               const std::vector<std::string>& overrides, const nlohmann::json& metrics);

// The metrics of the run of `case_path` with `overrides` into o.out_dir: the kept one when
// cached_run finds it (said on stderr), otherwise a fresh run, then kept with store_run.
nlohmann::json run_or_reuse(const std::filesystem::path& case_path,
                            const std::vector<std::string>& overrides, const RunOptions& o);

}  // namespace curvsph
