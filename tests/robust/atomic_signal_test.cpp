// Whole-or-nothing writers killed mid-write (issue 23, item 3): SIGINT, SIGTERM and SIGHUP end
// the process as they would (the parent sees death by that signal) and leave no temporary file;
// a signal the process ignores stays ignored; a committed file survives a later signal.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "asm/files/atomic_file.h"

namespace alp85 {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("alp85-signal-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::vector<std::string> files_in(const fs::path& d) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(d)) out.push_back(e.path().filename().string());
    return out;
}

// Runs `child` in a forked process; returns its wait status.
template <class F>
int in_child(F child) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        child();
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

class Killed : public ::testing::TestWithParam<int> {};

TEST_P(Killed, WhilePieceByPieceLeavesNoTemporary) {
    const int sig = GetParam();
    const fs::path d = fresh_dir("output" + std::to_string(sig));
    const int status = in_child([&] {
        AtomicOutput out(d / "trace.csv");
        out.stream() << std::string(100000, 'x');
        out.stream().flush();
        ::raise(sig);
        ::_exit(7);  // not reached: the signal ends the process
    });
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_TRUE(files_in(d).empty()) << files_in(d).front();
    fs::remove_all(d);
}

TEST_P(Killed, WhileAGroupIsStagedLeavesNoTemporary) {
    const int sig = GetParam();
    const fs::path d = fresh_dir("group" + std::to_string(sig));
    { std::ofstream(d / "old.hex") << "the old contents\n"; }
    ASSERT_EQ(::mkfifo((d / "fifo").c_str(), 0600), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
        AtomicFileGroup g;
        g.add(d / "old.hex", "new\n");
        g.add(d / "new.lst", "listing\n");
        g.add(d / "fifo", "to a device\n");  // opened for writing after the temporaries: blocks
        g.commit();
        ::_exit(7);
    }
    // Until both temporaries are on disk and the writer waits on the FIFO.
    for (int i = 0; i < 400 && files_in(d).size() < 4; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(files_in(d).size(), 4u);
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), sig);
    auto left = files_in(d);
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"fifo", "old.hex"}));
    std::ifstream old(d / "old.hex");
    std::string line;
    std::getline(old, line);
    EXPECT_EQ(line, "the old contents");
    fs::remove_all(d);
}

INSTANTIATE_TEST_SUITE_P(Signals, Killed, ::testing::Values(SIGINT, SIGTERM, SIGHUP));

TEST(Signals, AnIgnoredSignalStaysIgnoredAndTheFileIsWritten) {
    const fs::path d = fresh_dir("ignored");
    const int status = in_child([&] {
        std::signal(SIGHUP, SIG_IGN);  // nohup
        AtomicOutput out(d / "t.csv");
        out.stream() << "a,b\n";
        ::raise(SIGHUP);
        out.commit();
    });
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(files_in(d), std::vector<std::string>{"t.csv"});
    fs::remove_all(d);
}

TEST(Signals, ACommittedFileSurvivesALaterSignal) {
    const fs::path d = fresh_dir("committed");
    const int status = in_child([&] {
        write_atomic(d / "a.hex", std::string_view(":00000001FF\n"));
        AtomicOutput second(d / "b.csv");  // the handler is installed; a.hex is no temporary
        second.commit();
        ::raise(SIGTERM);
    });
    ASSERT_TRUE(WIFSIGNALED(status));
    auto left = files_in(d);
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"a.hex", "b.csv"}));
    fs::remove_all(d);
}

}  // namespace
}  // namespace alp85
