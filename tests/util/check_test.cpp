// CHECK and DCHECK (util/check.h): a failure names the place, the expression and the values,
// then aborts; each argument is evaluated once; DCHECK follows the build.
#include "util/check.h"

#include <gtest/gtest.h>

#include <string>

namespace util {
namespace {

// Death tests fork; "threadsafe" re-runs the binary instead, which also suits ThreadSanitizer.
class CheckDeathTest : public testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(CheckDeathTest, CheckAbortsNamingThePlaceAndTheExpression) {
  const bool ready = false;
  EXPECT_DEATH(CHECK(ready), "check_test\\.cpp:[0-9]+: CHECK failed: ready\n");
}

TEST_F(CheckDeathTest, ComparisonsAbortWithBothValues) {
  const int two = 2;
  const double half = 0.5;
  const std::string name = "box";
  EXPECT_DEATH(CHECK_EQ(two, 3), "check_test\\.cpp:[0-9]+: CHECK failed: two == 3 \\(two = 2, 3 = 3\\)");
  EXPECT_DEATH(CHECK_NE(two, 2), "CHECK failed: two != 2 \\(two = 2, 2 = 2\\)");
  EXPECT_DEATH(CHECK_LT(half, 0.1), "CHECK failed: half < 0.1 \\(half = 0.5, 0.1 = 0.10000000000000001\\)");
  EXPECT_DEATH(CHECK_LE(two, 1), "CHECK failed: two <= 1 \\(two = 2, 1 = 1\\)");
  EXPECT_DEATH(CHECK_GT(name.size(), 3u), "CHECK failed: name.size\\(\\) > 3u \\(name.size\\(\\) = 3, 3u = 3\\)");
  EXPECT_DEATH(CHECK_GE(name, std::string("car")), "CHECK failed: name >= std::string\\(\"car\"\\) \\(name = box");
}

TEST(Check, PassingChecksEvaluateEachArgumentOnce) {
  int calls = 0;
  const auto count = [&] { return ++calls; };
  CHECK(count() == 1);
  CHECK_EQ(count(), 2);
  CHECK_NE(count(), 0);
  CHECK_LT(count(), 5);
  CHECK_LE(count(), 5);
  CHECK_GT(count(), 0);
  CHECK_GE(count(), 7);
  EXPECT_EQ(calls, 7);
}

#if WALKRAD_DCHECK_IS_ON
TEST_F(CheckDeathTest, DcheckIsOnInDebugAndSanitizerBuilds) {
  const int two = 2;
  EXPECT_DEATH(DCHECK_EQ(two, 3), "CHECK failed: two == 3 \\(two = 2, 3 = 3\\)");
  EXPECT_DEATH(DCHECK(two > 2), "CHECK failed: two > 2");
}
#else
TEST(Check, DcheckIsCompiledOutOfReleaseBuilds) {
  int calls = 0;
  const auto count = [&] { return ++calls; };
  DCHECK(count() == 0);
  DCHECK_EQ(count(), 0);
  DCHECK_GT(count(), 100);
  EXPECT_EQ(calls, 0);
}
#endif

}  // namespace
}  // namespace util
