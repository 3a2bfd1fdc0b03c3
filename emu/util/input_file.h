// Reading an input file whole, the same way for every command: a regular file up to a cap for its
// kind, a FIFO read up to that cap, and everything else (a directory, a device such as /dev/zero,
// a link to nothing, a link loop, a name too long) refused at once with a sentence that names it.
// No call here throws std::filesystem::filesystem_error: every problem is an InputError whose
// text says what the path is and why it cannot be read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace alp85 {

// What an input is, for its cap and for the message. The caps are far above any real input (the
// largest file in the repository is under 1 MiB) and far below what exhausts a machine; the table
// is in docs/testing.md ("Input caps").
enum class FileKind : std::uint8_t {
    Script,    // alp85 script, include, debug --script, a DAP launch script: 4 MiB
    Source,    // assembly source (asm85, pisa-asm, `load x.asm`): 16 MiB
    HexImage,  // Intel HEX: 4 MiB (64 KiB of data in one-byte records is 0.9 MB)
    Binary,    // a .bin/.rom image or a CP/M .com program: 64 KiB, the 8085's address space
    Snapshot,  // a saved machine: 16 MiB
    Map,       // an asm85 --map JSON: 16 MiB
    GCode,     // a G-code program: 16 MiB
    Tape,      // a PISA tape: 16 MiB
};

std::uintmax_t input_cap(FileKind kind);
const char* file_kind_name(FileKind kind);  // "script", "Intel HEX file", ...

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "" when `path` names a regular file or a FIFO that can be opened; otherwise the sentence
// ("no such file 'x.alp'", "'d.asm' is a directory, not a file", "'/dev/zero' is a device, not a
// file", "'l.asm' is a symbolic link to 'gone.asm', which does not exist", "cannot read 'x':
// Too many levels of symbolic links"). Does not read the file.
std::string input_problem(const std::filesystem::path& path);

// input_problem(), and a FIFO refused too: for a program, which is read when a script is checked
// and again when it runs (a FIFO would give its bytes once, then wait for a writer).
std::string program_file_problem(const std::filesystem::path& path);

// The whole file. Throws InputError with input_problem()'s sentence, or "'x' is larger than N
// bytes, the most a KIND may be", or the read's error.
std::string read_input(const std::filesystem::path& path, FileKind kind);

}  // namespace alp85
