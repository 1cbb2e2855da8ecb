#include <gtest/gtest.h>

#include "curvsph/analysis/median.hpp"

namespace curvsph {

// The timing studies' median, against hand-sorted samples.
TEST(Median, OddEvenAndUnsortedSamples) {
  EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(median({1.04, 0.97, 1.02, 1.01, 5.0}), 1.02);  // one outlier does not move it
  EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(median({7.5}), 7.5);
  EXPECT_EQ(median({}), 0.0);
}

}  // namespace curvsph
