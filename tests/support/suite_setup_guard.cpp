// tests/support/suite_setup_guard.cpp — a failure outside any test (in a
// suite's SetUpTestSuite or TearDownTestSuite, or a global environment) ends
// the test program at once with exit code 1. Otherwise GoogleTest goes on to
// print "[  SKIPPED ]" for every test of that suite, and ctest, whose skip
// expression wins over the exit code, reports the failure as skipped tests.
// Linked into every test program by onetip_test (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace {

// Whether a test is running is kept here: UnitTest::current_test_info() takes the lock that
// GoogleTest holds while it reports a result.
class SuiteSetUpGuard : public testing::EmptyTestEventListener {
  bool in_test_ = false;
  void OnTestStart(const testing::TestInfo&) override { in_test_ = true; }
  void OnTestEnd(const testing::TestInfo&) override { in_test_ = false; }
  void OnTestPartResult(const testing::TestPartResult& result) override {
    if (!result.failed() || in_test_) return;
    std::fprintf(stderr, "%s:%d: a failure outside any test (a suite's set-up or tear-down): %s\n",
                 result.file_name() ? result.file_name() : "(unknown file)", result.line_number(), result.summary());
    std::fflush(nullptr);
    std::_Exit(1);
  }
};

const bool kRegistered = [] {
  testing::UnitTest::GetInstance()->listeners().Append(new SuiteSetUpGuard);
  return true;
}();

}  // namespace
