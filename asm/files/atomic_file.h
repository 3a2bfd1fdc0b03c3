// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file beside the target, which is renamed over it only when everything was written. A target
// that exists and is not a regular file (/dev/null, a pipe, a symbolic link) is written through
// instead: renaming over it would replace the device or the link itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace alp85 {

// A temporary file that this process removes if SIGINT, SIGTERM or SIGHUP ends it: a process-wide
// table of live temporaries, emptied by a handler that uses async-signal-safe calls only (unlink)
// and then re-raises the signal with its default action, so that the exit status still says which
// signal ended the process. The handler is installed, at the first temporary, only for the signals
// whose action is still the default: a front end's own handler (alp85 debug's Ctrl-C, which stops
// a run) and an ignored signal (nohup) are left as they are.
class TemporaryGuard {
public:
    TemporaryGuard() = default;
    explicit TemporaryGuard(const std::filesystem::path& path) { guard(path); }
    TemporaryGuard(const TemporaryGuard&) = delete;
    TemporaryGuard& operator=(const TemporaryGuard&) = delete;
    ~TemporaryGuard() { release(); }
    void guard(const std::filesystem::path& path);  // at most one path per guard
    // The file is gone or renamed to its target: the handler must no longer remove it.
    void release();

private:
    int slot_ = -1;  // -1: nothing guarded (or the table was full)
};

// For output written piece by piece (traces): write to stream(), then commit(). Destroyed
// without commit() (an error, an exception), it removes the temporary file.
class AtomicOutput {
public:
    explicit AtomicOutput(std::filesystem::path path);  // throws std::runtime_error
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    std::ostream& stream() { return out_; }
    void commit();  // throws std::runtime_error naming the path (disk full, rename failed)

private:
    std::filesystem::path path_, tmp_;  // tmp_ empty when writing through
    TemporaryGuard guard_;
    std::ofstream out_;
    bool done_ = false;
};

// Several output files that appear together or not at all (asm85's .hex, .bin, .lst and .map:
// make and other build tools take any of them as proof that the step succeeded). add() only
// keeps the bytes; commit() writes every file to a temporary beside its target, and renames them
// over their targets only when all were written. When anything fails, the temporaries are
// removed, a target replaced already gets its old contents back, and the error names the path.
// Devices and links are written through (after every temporary was written, before any rename):
// what went into a device cannot be taken back.
class AtomicFileGroup {
public:
    void add(std::filesystem::path path, std::string bytes);
    void commit();  // throws std::runtime_error naming the path that failed
    bool empty() const { return files_.empty(); }

private:
    struct File {
        std::filesystem::path path;
        std::string bytes;
    };
    std::vector<File> files_;
};

// Throws std::runtime_error naming the path and the reason; no temporary file is left behind.
void write_atomic(const std::filesystem::path& path, std::string_view bytes);
inline void write_atomic(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    write_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace alp85
