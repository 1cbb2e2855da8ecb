// Where a data file named in a case is found (io/data_file.hpp): beside the case file, as an
// absolute name, and the exit-2 message listing every place looked in when it is nowhere.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "curvsph/core/error.hpp"
#include "curvsph/io/data_file.hpp"

namespace curvsph {
namespace {
namespace fs = std::filesystem;

class DataFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("curvsph_data_file_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "case" / "parts");
    std::ofstream(dir_ / "case" / "parts" / "a.csv") << "1\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(DataFile, RelativeNameIsFoundBesideTheCaseFile) {
  EXPECT_EQ(resolve_data_file("parts/a.csv", dir_ / "case", "c.yaml", "k"),
            dir_ / "case" / "parts" / "a.csv");
}

TEST_F(DataFile, AbsoluteNameIsTakenAsItIs) {
  const fs::path abs = dir_ / "case" / "parts" / "a.csv";
  EXPECT_EQ(resolve_data_file(abs.string(), dir_ / "elsewhere", "c.yaml", "k"), abs);
}

TEST_F(DataFile, MissingFileNamesKeyAndEveryPlaceLooked) {
  try {
    resolve_data_file("parts/b.csv", dir_ / "case", "c.yaml", "walls.0.file");
    FAIL() << "no error for a missing file";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.file(), "c.yaml");
    EXPECT_EQ(e.key(), "walls.0.file");
    EXPECT_NE(m.find((dir_ / "case" / "parts" / "b.csv").string()), std::string::npos) << m;
    for (const fs::path& d : data_dirs())
      EXPECT_NE(m.find((d / "parts" / "b.csv").string()), std::string::npos) << m;
  }
}

// The first installed folder is the one beside the running binary (an install at any prefix
// finds its own data), the compiled-in one last.
TEST(DataDirs, FirstIsBesideTheRunningBinary) {
  const auto dirs = data_dirs();
  ASSERT_FALSE(dirs.empty());
  const fs::path exe = fs::read_symlink("/proc/self/exe").parent_path();
  EXPECT_EQ(dirs.front(), (exe / ".." / "share" / "curvsph" / "data").lexically_normal());
  EXPECT_EQ(dirs.back().filename(), "data");
}

}  // namespace
}  // namespace curvsph
