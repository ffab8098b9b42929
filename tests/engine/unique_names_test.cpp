#include "engine/io/unique_names.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

TEST(UniqueNames, EqualNamesAreNumbered) {
  UniqueNames names;
  EXPECT_EQ(names.add("paint"), "paint");
  EXPECT_EQ(names.add("paint 3"), "paint 3");
  EXPECT_EQ(names.add("paint"), "paint 2");
  EXPECT_EQ(names.add("paint"), "paint 4");  // "paint 3" is taken
  EXPECT_EQ(names.add("paint 2"), "paint 2 2");
  EXPECT_EQ(names.add(""), "");
  EXPECT_EQ(names.add(""), " 2");
}

// n equal names take n tries (a model may give 40,000 materials one name), and names that take
// the numbers first cost at most a try more each.
TEST(UniqueNames, TheWorkIsLinear) {
  constexpr size_t kNames = 40000;
  UniqueNames same;
  for (size_t i = 0; i < kNames; ++i) same.add("paint");
  EXPECT_EQ(same.tries(), kNames);
  UniqueNames mixed;
  for (size_t i = 2; i < kNames; i += 2) mixed.add("paint " + std::to_string(i));
  for (size_t i = 0; i < kNames; ++i) mixed.add("paint");
  for (size_t i = 2; i < kNames; i += 2) mixed.add("paint " + std::to_string(i));
  EXPECT_LE(mixed.tries(), 3 * kNames);
}

}  // namespace
}  // namespace engine
