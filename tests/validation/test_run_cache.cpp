// The run cache of the long validation studies: a kept run comes back only for the same case
// file and the same overrides; anything else (another case, another override, a damaged or
// missing record) means the run is redone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "curvsph/validation/run_cache.hpp"

namespace curvsph {
namespace {

class RunCache : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() /
        ("curvsph_run_cache_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
  const std::vector<std::string> overrides_ = {"resolution.dx=0.01", "time.end=4.5"};
  const nlohmann::json metrics_ = {{"kinetic_energy_max", 6.0558e-06}, {"escaped_particles", 0}};
};

TEST_F(RunCache, KeptRunComesBackForTheSameCaseAndOverrides) {
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", overrides_).is_null());  // nothing kept yet
  store_run(dir_, "0123456789abcdef", overrides_, metrics_);
  const nlohmann::json m = cached_run(dir_, "0123456789abcdef", overrides_);
  ASSERT_FALSE(m.is_null());
  EXPECT_EQ(m, metrics_);
  EXPECT_DOUBLE_EQ(m["kinetic_energy_max"].get<double>(), 6.0558e-06);
}

TEST_F(RunCache, AnotherCaseOrOverrideIsAMiss) {
  store_run(dir_, "0123456789abcdef", overrides_, metrics_);
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdee", overrides_).is_null());
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", {"resolution.dx=0.01", "time.end=9"}).is_null());
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", {"resolution.dx=0.01"}).is_null());
  // The order of the overrides is part of the key (a later override wins over an earlier one).
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", {overrides_[1], overrides_[0]}).is_null());
}

TEST_F(RunCache, DamagedRecordIsAMiss) {
  std::ofstream(dir_ / "study_run.json") << "{\"case_key\": \"0123456789abcdef\", \"metr";
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", overrides_).is_null());
  std::ofstream(dir_ / "study_run.json") << "[1, 2, 3]";
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", overrides_).is_null());
}

TEST_F(RunCache, RunStoppedBySignalIsNotKept) {
  // A study stopped with Ctrl-C (or SIGTERM) ends its current run gracefully with "stopped":
  // 1; kept, that partial run would come back as finished.
  nlohmann::json stopped = metrics_;
  stopped["stopped"] = 1;
  EXPECT_THROW(store_run(dir_, "0123456789abcdef", overrides_, stopped), std::runtime_error);
  EXPECT_TRUE(cached_run(dir_, "0123456789abcdef", overrides_).is_null());
  stopped["stopped"] = 0;
  store_run(dir_, "0123456789abcdef", overrides_, stopped);
  EXPECT_FALSE(cached_run(dir_, "0123456789abcdef", overrides_).is_null());
}

}  // namespace
}  // namespace curvsph
