// Each GoogleTest program's cases, run together in one process, each leave a verdict in a file
// of its own, which the case's own CTest test reads (tests/CMakeLists.txt: alp85_gtests;
// tests/gtest_case.sh). Active only when ALP85_GTEST_RESULTS names the folder for them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace {

namespace fs = std::filesystem;

// A file a case in the folder (which the run's launcher emptied), and .complete once every case
// has ended: a status of 1 with it is the cases' failures, not a sanitizer's report or a crash.
class ResultFiles : public testing::EmptyTestEventListener {
 public:
  explicit ResultFiles(fs::path dir) : dir_(std::move(dir)) {}

  void OnTestProgramEnd(const testing::UnitTest&) override { std::ofstream(dir_ / ".complete") << "complete\n"; }
  void OnTestStart(const testing::TestInfo&) override { failures_.clear(); }
  void OnTestPartResult(const testing::TestPartResult& part) override {
    if (!part.failed()) return;
    failures_ += (part.file_name() ? part.file_name() : "(unknown file)");
    failures_ += ':' + std::to_string(part.line_number()) + ": Failure\n" + part.message() + '\n';
  }
  void OnTestEnd(const testing::TestInfo& info) override {
    // Parameterized names hold '/': each part is a folder, as the case's test names the file.
    const fs::path file = dir_ / (std::string(info.test_suite_name()) + '.' + info.name());
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    std::ofstream out(file);
    const testing::TestResult& result = *info.result();
    if (result.Failed())
      out << "FAILED\n" << failures_;
    else if (result.Skipped())
      out << "SKIPPED\n[  SKIPPED ] " << info.test_suite_name() << '.' << info.name() << '\n';
    else
      out << "PASSED\n";
  }

 private:
  fs::path dir_;
  std::string failures_;
};

const bool kResultFilesRegistered = [] {
  if (const char* dir = std::getenv("ALP85_GTEST_RESULTS"); dir && *dir)
    testing::UnitTest::GetInstance()->listeners().Append(new ResultFiles(dir));
  return true;
}();

}  // namespace
