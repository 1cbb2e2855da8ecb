#include "curvsph/validation/run_cache.hpp"

#include <fstream>

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
  const nlohmann::json j = {
      {"case_key", case_fingerprint}, {"overrides", overrides}, {"metrics", metrics}};
  std::ofstream(dir / kFile) << j.dump(2) << '\n';
}

}  // namespace curvsph
