// The one input reader (emu/util/input_file): the caps hold to the byte, and what is no file is
// refused by name before anything is read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "emu/util/input_file.h"

namespace alp85 {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("alp85_input_file_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d / name;
}

void write_bytes(const fs::path& p, std::size_t n) {
    std::ofstream(p, std::ios::binary) << std::string(n, 'A');
}

std::string refusal(const fs::path& p, FileKind kind) {
    try {
        read_input(p, kind);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

TEST(InputFile, ABinaryImageIsAtMostTheAddressSpace) {
    // 64 KiB = 65536 bytes: the 8085's whole address space (16 address lines).
    const fs::path p = scratch("full.bin");
    write_bytes(p, 65536);
    EXPECT_EQ(read_input(p, FileKind::Binary).size(), 65536u);
    write_bytes(p, 65537);
    EXPECT_NE(refusal(p, FileKind::Binary).find("larger than 64 KiB"), std::string::npos) << refusal(p, FileKind::Binary);
    fs::remove_all(p.parent_path());
}

TEST(InputFile, AScriptIsAtMostFourMebibytes) {
    const fs::path p = scratch("big.alp");
    write_bytes(p, 4u << 20);  // 4,194,304 bytes: accepted
    EXPECT_EQ(read_input(p, FileKind::Script).size(), 4u << 20);
    write_bytes(p, (4u << 20) + 1);
    EXPECT_NE(refusal(p, FileKind::Script).find("larger than 4 MiB, the most a script may be"), std::string::npos);
    fs::remove_all(p.parent_path());
}

TEST(InputFile, WhatIsNoFileIsNamedForWhatItIs) {
    EXPECT_EQ(refusal("/dev/zero", FileKind::Script), "'/dev/zero' is a device, not a file");
    EXPECT_EQ(refusal("/dev/null", FileKind::HexImage), "'/dev/null' is a device, not a file");
    const fs::path d = scratch("dir.asm");
    fs::create_directories(d);
    EXPECT_EQ(refusal(d, FileKind::Source), "'" + d.string() + "' is a directory, not a file");
    const fs::path loop = scratch("loop.hex");
    fs::create_symlink(loop.filename(), loop);
    EXPECT_NE(refusal(loop, FileKind::HexImage).find("Too many levels of symbolic links"), std::string::npos);
    const fs::path dangling = scratch("dangling.hex");
    fs::create_symlink("gone.hex", dangling);
    EXPECT_EQ(refusal(dangling, FileKind::HexImage), "'" + dangling.string() + "' is a symbolic link to 'gone.hex', which does not exist");
    EXPECT_EQ(refusal(scratch("none.hex"), FileKind::HexImage), "no such file '" + scratch("none.hex").string() + "'");
    EXPECT_NE(refusal(scratch(std::string(300, 'n')), FileKind::Map).find("File name too long"), std::string::npos);
    const fs::path fifo = scratch("p.hex");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(input_problem(fifo), "");  // read, with the cap
    EXPECT_NE(program_file_problem(fifo).find("is a FIFO"), std::string::npos);
    fs::remove_all(d.parent_path());
}

}  // namespace
}  // namespace alp85
