// The window's frame statistics (`walkrad view --stats`): quantiles by the nearest rank.
#include "app/window/frame_times.h"

#include <gtest/gtest.h>

namespace app {
namespace {

TEST(FrameTimes, QuantilesByNearestRank) {
  FrameTimes times;
  EXPECT_EQ(times.quantile(0.5), 0);
  for (double ms : {40.0, 10.0, 30.0, 20.0, 500.0}) times.add(ms);
  EXPECT_EQ(times.count(), 5u);
  EXPECT_EQ(times.quantile(0.5), 30);   // the 3rd of 5
  EXPECT_EQ(times.quantile(0.95), 500);  // the 5th: one slow frame in five is above the 95th percentile's rank
  EXPECT_EQ(times.quantile(0), 10);
  EXPECT_EQ(times.quantile(1), 500);
  for (int i = 0; i < 95; ++i) times.add(15);
  EXPECT_EQ(times.quantile(0.5), 15);
  EXPECT_EQ(times.quantile(0.95), 15);  // 96 of 100 frames took at most 15 ms
  EXPECT_EQ(times.quantile(0.97), 20);  // sorted: 10, 95 x 15, 20, 30, 40, 500
  EXPECT_EQ(times.quantile(0.99), 40);
}

}  // namespace
}  // namespace app
