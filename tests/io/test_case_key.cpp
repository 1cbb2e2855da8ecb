// The case fingerprint against the published FNV-1a 64 test vectors (Fowler, Noll & Vo:
// "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c, "foobar" -> 85944171f73967e8), and a
// key that changes with one byte of the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "curvsph/core/error.hpp"
#include "curvsph/io/case_key.hpp"

namespace curvsph {
namespace {

TEST(CaseKey, Fnv1a64TestVectors) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
}

TEST(CaseKey, FollowsEveryByteOfTheFile) {
  const auto dir =
      std::filesystem::temp_directory_path() /
      ("curvsph_case_key_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  const auto f = dir / "case.yaml";
  std::ofstream(f) << "foobar";
  EXPECT_EQ(case_key(f), "85944171f73967e8");
  std::ofstream(f) << "eos: {p0: 2.0}\n";
  const std::string a = case_key(f);
  std::ofstream(f) << "eos: {p0: 2.1}\n";
  EXPECT_NE(case_key(f), a);
  EXPECT_THROW(case_key(dir / "missing.yaml"), InputError);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace curvsph
