// Output files appear whole or not at all, and devices and links are written through, never
// replaced (asm/files/atomic_file.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "asm/files/atomic_file.h"

namespace alp85::test {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("alp85_atomic_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {})); }
    fs::path dir;
};

TEST_F(AtomicFile, WritesTheWholeFileAndNothingElse) {
    write_atomic(dir / "out.txt", std::string_view("hello\n"));
    EXPECT_EQ(read(dir / "out.txt"), "hello\n");
    EXPECT_EQ(entries(), 1u);  // no temporary left beside it
}

TEST_F(AtomicFile, ReplacesAnOldFileOnlyOnCommit) {
    write_atomic(dir / "out.txt", std::string_view("old"));
    {
        AtomicOutput out(dir / "out.txt");
        out.stream() << "new, but never committed";
    }
    EXPECT_EQ(read(dir / "out.txt"), "old");
    EXPECT_EQ(entries(), 1u);
    AtomicOutput out(dir / "out.txt");
    out.stream() << "new";
    EXPECT_EQ(read(dir / "out.txt"), "old");  // not yet
    out.commit();
    EXPECT_EQ(read(dir / "out.txt"), "new");
}

TEST_F(AtomicFile, WritesThroughASymbolicLink) {
    write_atomic(dir / "target.txt", std::string_view("old"));
    fs::create_symlink(dir / "target.txt", dir / "link.txt");
    write_atomic(dir / "link.txt", std::string_view("through"));
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.txt")));
    EXPECT_EQ(read(dir / "target.txt"), "through");
}

TEST_F(AtomicFile, AMissingDirectoryIsAnErrorNamingThePath) {
    try {
        write_atomic(dir / "no" / "such.txt", std::string_view("x"));
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("such.txt"), std::string::npos) << e.what();
    }
    EXPECT_EQ(entries(), 0u);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

TEST_F(AtomicFile, AGroupIsWrittenWholeOrNotAtAll) {
    write_atomic(dir / "a.txt", std::string_view("old a"));
    write_atomic(dir / "blocker", std::string_view("a file where a folder is wanted"));
    AtomicFileGroup bad;
    bad.add(dir / "a.txt", "new a");
    bad.add(dir / "b.txt", "new b");
    bad.add(dir / "blocker" / "c.txt", "cannot be");
    try {
        bad.commit();
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("c.txt"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read(dir / "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
    EXPECT_EQ(entries(), 2u);  // a.txt and blocker: no temporaries

    AtomicFileGroup good;
    good.add(dir / "a.txt", "new a");
    good.add(dir / "b.txt", "new b");
    good.commit();
    EXPECT_EQ(read(dir / "a.txt"), "new a");
    EXPECT_EQ(read(dir / "b.txt"), "new b");
    EXPECT_EQ(entries(), 3u);
}

}  // namespace
}  // namespace alp85::test
