// A GoogleTest program with a case of each verdict, for gtest-verdicts:report
// (tests/gtest_case_test.cmake): it is never registered with alp85_gtests, since a case fails.
#include <gtest/gtest.h>

#include <cstdlib>

TEST(Verdicts, Passes) { EXPECT_EQ(2 + 2, 4); }
TEST(Verdicts, Fails) { EXPECT_EQ(2 + 2, 5) << "four is not five"; }
TEST(Verdicts, IsSkipped) { GTEST_SKIP() << "not here"; }
// Ends the program when VERDICTS_CRASH is set: the cases after it get no verdict.
TEST(Verdicts, MayCrash) {
  if (std::getenv("VERDICTS_CRASH")) std::abort();
}
TEST(Verdicts, RunsLast) { SUCCEED(); }

class Sized : public testing::TestWithParam<int> {};
TEST_P(Sized, IsPositive) { EXPECT_GT(GetParam(), 0); }
INSTANTIATE_TEST_SUITE_P(Small, Sized, testing::Values(1, 2));
