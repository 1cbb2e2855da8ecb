#include "curvsph/validation/run_cache.hpp"

#include <fstream>
#include <iostream>
#include <stdexcept>

#include "curvsph/io/case_file.hpp"
#include "curvsph/io/case_key.hpp"

namespace curvsph {
namespace {

constexpr const char* kFile = "study_run.json";

}  // namespace

nlohmann::json cached_run(const std::filesystem::path& dir, const std::string& case_fingerprint,
                          const std::vector<std::string>& overrides) {
  std::ifstream in(dir / kFile);
  if (!in) return nullptr;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object() || !j.contains("metrics")) return nullptr;
  if (j.value("case_key", "") != case_fingerprint) return nullptr;
  if (j.value("overrides", nlohmann::json()) != nlohmann::json(overrides)) return nullptr;
  return j["metrics"];
}

void store_run(const std::filesystem::path& dir, const std::string& case_fingerprint,
               const std::vector<std::string>& overrides, const nlohmann::json& metrics) {
  // A run ended by SIGINT / SIGTERM (metrics "stopped") is partial: kept, it would be reused
  // as finished by the next invocation. Refusing also ends the study, which is what the signal
  // asked for (the run itself stops gracefully and the study would go on to the next run).
  if (metrics.value("stopped", 0) != 0)
    throw std::runtime_error("the run in " + dir.string() +
                             " was stopped by a signal: not kept for reuse; the study stops");
  const nlohmann::json j = {
      {"case_key", case_fingerprint}, {"overrides", overrides}, {"metrics", metrics}};
  std::ofstream(dir / kFile) << j.dump(2) << '\n';
}

nlohmann::json run_or_reuse(const std::filesystem::path& case_path,
                            const std::vector<std::string>& overrides, const RunOptions& o) {
  const std::string fingerprint = case_key(case_path);
  nlohmann::json m = cached_run(o.out_dir, fingerprint, overrides);
  if (!m.is_null()) {
    std::cerr << o.out_dir.filename().string() << ": reusing the finished run in "
              << o.out_dir.string() << "\n";
    return m;
  }
  std::filesystem::create_directories(o.out_dir);
  m = run_case(read_case(case_path, overrides), o);
  store_run(o.out_dir, fingerprint, overrides, m);
  return m;
}

}  // namespace curvsph
