// alp85 script -j N: scripts run at once on sessions of their own, reported in file order, and
// scripts that share a file run one after another.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/runner.h"

namespace alp85::script {
namespace {

namespace fs = std::filesystem;

struct Scripts {
    explicit Scripts(const std::string& name) : dir(fs::temp_directory_path() / name) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scripts() { fs::remove_all(dir); }
    void add(const std::string& name, const std::string& text) {
        files.push_back(dir / name);
        std::ofstream(files.back()) << text;
        std::vector<ParseError> errors;
        programs.push_back(parse_script(text, files.back().string(), errors));
        EXPECT_TRUE(errors.empty()) << name;
    }
    fs::path dir;
    std::vector<fs::path> files;
    std::vector<std::vector<Command>> programs;
};

// Two scripts whose `monitor` waits until both have reached it: they pass only when they run at
// the same time (one after the other, the first would wait out the 20 s and fail).
TEST(ScriptJobs, TwoJobsRunTwoScriptsAtOnce) {
    Scripts s("alp85 jobs at once");
    s.add("a.alp", "monitor\nreset\nrun 1ms\n");
    s.add("b.alp", "monitor\nreset\nrun 1ms\n");
    std::mutex m;
    std::condition_variable cv;
    int arrived = 0;
    bool met = true;
    RunnerOptions o;
    o.monitor_rom = [&] {
        std::unique_lock lock(m);
        ++arrived;
        cv.notify_all();
        if (!cv.wait_for(lock, std::chrono::seconds(20), [&] { return arrived >= 2; })) met = false;
        return firmware::monitor();
    };
    std::vector<std::string> order;
    const auto results = execute_all(s.files, s.programs, o, 2, [&](const ScriptResult& r, const std::string&) {
        order.push_back(fs::path(r.file).filename().string());
    });
    EXPECT_TRUE(met) << "the second script did not start while the first was running";
    ASSERT_EQ(results.size(), 2u);
    EXPECT_TRUE(results[0].passed && results[1].passed);
    EXPECT_EQ(order, (std::vector<std::string>{"a.alp", "b.alp"}));
}

// The first script's `monitor` takes 300 ms of host time (the others take about 1 ms each), so with
// three jobs it ends last; the report still comes in file order, each with its own print lines.
TEST(ScriptJobs, OutputIsGroupedPerScriptInFileOrder) {
    Scripts s("alp85 jobs order");
    s.add("slow.alp", "print slow one\nmonitor\nreset\nrun 5ms\nprint slow two\n");
    s.add("quick.alp", "print quick one\nreset\nrun 5ms\nprint quick two\n");
    s.add("fails.alp", "print fails one\nreset\nrun 5ms\nexpect halted\n");
    RunnerOptions o;
    o.monitor_rom = [] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        return firmware::monitor();
    };
    std::vector<std::pair<std::string, std::string>> reports;
    const auto results = execute_all(s.files, s.programs, o, 3, [&](const ScriptResult& r, const std::string& out) {
        reports.emplace_back(fs::path(r.file).filename().string(), out);
    });
    ASSERT_EQ(reports.size(), 3u);
    EXPECT_EQ(reports[0].first, "slow.alp");
    EXPECT_EQ(reports[1].first, "quick.alp");
    EXPECT_EQ(reports[2].first, "fails.alp");
    EXPECT_EQ(reports[0].second, "slow one\nslow two\n");
    EXPECT_EQ(reports[1].second, "quick one\nquick two\n");
    EXPECT_EQ(reports[2].second, "fails one\n");
    ASSERT_EQ(results.size(), 3u);
    EXPECT_TRUE(results[0].passed);
    EXPECT_TRUE(results[1].passed);
    EXPECT_FALSE(results[2].passed);
    EXPECT_EQ(results[0].file, s.files[0].string());
}

// A script that restores what another saves runs after it, in one job, in file order; the third
// shares nothing and runs beside them.
TEST(ScriptJobs, ScriptsSharingAFileRunOneAfterAnother) {
    Scripts s("alp85 jobs shared");
    s.add("save.alp", "reset\nrun 2ms\nsave state.snap\n");
    s.add("other.alp", "reset\nrun 1ms\nsave other.snap\n");
    s.add("restore.alp", "restore state.snap\nexpect time >= 2ms\n");
    EXPECT_EQ(script_groups(s.files, s.programs, {}),
              (std::vector<std::vector<std::size_t>>{{0, 2}, {1}}));
    const auto results = execute_all(s.files, s.programs, {}, 3, [](const ScriptResult&, const std::string&) {});
    ASSERT_EQ(results.size(), 3u);
    for (const auto& r : results) EXPECT_TRUE(r.passed) << r.file << "\n" << r.failure;
    // The same names under --out-dir are one file there too.
    RunnerOptions o;
    o.out_dir = s.dir / "out";
    EXPECT_EQ(script_groups(s.files, s.programs, o), (std::vector<std::vector<std::size_t>>{{0, 2}, {1}}));
}

}  // namespace
}  // namespace alp85::script
