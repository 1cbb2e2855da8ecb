// The built `curvsph shepard` binary on a small circle case: columns, the values of every
// mode, and exit code 2 with a clear message for bad arguments.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "../support/command_fixture.hpp"

namespace {

namespace fs = std::filesystem;

class ShepardCommand : public curvsph::testing::CommandTest {
 protected:
  void SetUp() override {
    CommandTest::SetUp();
    geom_ = write("circle.yaml",
                  "dimension: 2\nwalls:\n  - {shape: circle, center: [0, 0], radius: 2, "
                  "fluid: inside}\n");
    // Centre, on the wall, 0.1h inside the wall (h = 0.05).
    points_ = write("p.csv", "x,y\n0,0\n2,0\n0,-1.995\n");
  }
  int run(const std::string& args) { return run_curvsph("shepard " + args); }
  // gamma column of the CSV text, after checking the header.
  static std::vector<double> gammas(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "x,y,z,gamma");
    std::vector<double> g;
    while (std::getline(in, line)) g.push_back(std::stod(line.substr(line.rfind(',') + 1)));
    return g;
  }
  std::string base(const std::string& mode) const {
    return geom_.string() + " --points " + points_.string() + " --h 0.05 --dx 0.025 --mode " + mode;
  }

  fs::path geom_, points_;
};

TEST_F(ShepardCommand, CircleAllModes) {
  ASSERT_EQ(run(base("geometric")), 0) << err_;
  auto g = gammas(out_);
  ASSERT_EQ(g.size(), 3u);
  EXPECT_NEAR(g[0], 1.0, 1e-12);
  EXPECT_NEAR(g[1], 0.5, 0.005);
  EXPECT_NEAR(g[2], 0.573815, 0.005);  // 0.1h from a flat wall (DESIGN §4); R = 20h here

  const fs::path out = dir_ / "out.csv";
  ASSERT_EQ(run(base("volume") + " --out " + out.string()), 0) << err_;
  EXPECT_EQ(out_, "");
  g = gammas(read(out));
  ASSERT_EQ(g.size(), 3u);
  EXPECT_NEAR(g[0], 1.0, 0.01);
  EXPECT_NEAR(g[1], 0.5, 0.05);

  ASSERT_EQ(run(base("monolithic")), 0) << err_;
  g = gammas(out_);
  EXPECT_NEAR(g[0], 1.0, 1e-12);
  ASSERT_EQ(run(base("monolithic") + " --contour-half"), 0) << err_;
  EXPECT_NEAR(gammas(out_)[1], 0.5, 0.05);
  ASSERT_EQ(run(base("none")), 0) << err_;
  EXPECT_EQ(gammas(out_), std::vector<double>(3, 1.0));
}

TEST_F(ShepardCommand, BadArgumentsExitWith2) {
  EXPECT_EQ(run(base("fancy")), 2);
  EXPECT_NE(err_.find("unknown Shepard mode 'fancy'"), std::string::npos) << err_;
  EXPECT_EQ(
      run(geom_.string() + " --points " + points_.string() + " --h 0 --dx 0.025 --mode geometric"),
      2);
  EXPECT_NE(err_.find("--h"), std::string::npos) << err_;
  EXPECT_EQ(
      run(geom_.string() + " --points " + points_.string() + " --h 0.05 --dx -1 --mode geometric"),
      2);
  EXPECT_NE(err_.find("--dx"), std::string::npos) << err_;
  EXPECT_EQ(run(geom_.string() + " --points " + points_.string() + " --h 0.05 --mode geometric"),
            2);  // --dx missing
}

}  // namespace
