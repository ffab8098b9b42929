// DCHECK as a release build compiles it, in every build (tests/CMakeLists.txt turns it off for
// this file): its arguments are never evaluated, so a check may cost what it likes.
#include "util/check.h"

#include <gtest/gtest.h>

static_assert(WALKRAD_DCHECK_IS_ON == 0, "this file is built as release builds are");

namespace util {
namespace {

TEST(DcheckInRelease, ArgumentsAreNotEvaluatedAndNothingFails) {
  int calls = 0;
  const auto count = [&] { return ++calls; };
  DCHECK(count() == 0);
  DCHECK_EQ(count(), 0);
  DCHECK_NE(count(), count());
  DCHECK_LT(count(), 0);
  DCHECK_LE(count(), 0);
  DCHECK_GT(count(), 100);
  DCHECK_GE(count(), 100);
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace util
