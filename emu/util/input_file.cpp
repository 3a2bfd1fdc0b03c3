#include "emu/util/input_file.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace alp85 {
namespace {

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

std::string type_problem(const std::filesystem::path& path, mode_t mode) {
    if (S_ISDIR(mode)) return quoted(path) + " is a directory, not a file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return quoted(path) + " is a device, not a file";
    if (S_ISSOCK(mode)) return quoted(path) + " is a socket, not a file";
    return {};
}

std::string cap_text(std::uintmax_t bytes) {
    if (bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes >> 10) + " KiB";
}

std::string too_large(const std::filesystem::path& path, FileKind kind) {
    return quoted(path) + " is larger than " + cap_text(input_cap(kind)) + ", the most " + file_kind_name(kind) +
           " may be";
}

}  // namespace

std::uintmax_t input_cap(FileKind kind) {
    switch (kind) {
        case FileKind::Script: return 4u << 20;
        case FileKind::HexImage: return 4u << 20;
        case FileKind::Binary: return 64u << 10;
        case FileKind::Source:
        case FileKind::Snapshot:
        case FileKind::Map:
        case FileKind::GCode:
        case FileKind::Tape: return 16u << 20;
    }
    return 0;
}

const char* file_kind_name(FileKind kind) {
    switch (kind) {
        case FileKind::Script: return "a script";
        case FileKind::Source: return "a source file";
        case FileKind::HexImage: return "an Intel HEX file";
        case FileKind::Binary: return "a binary image";
        case FileKind::Snapshot: return "a snapshot";
        case FileKind::Map: return "a symbol map";
        case FileKind::GCode: return "a G-code file";
        case FileKind::Tape: return "a tape";
    }
    return "an input";
}

std::string input_problem(const std::filesystem::path& path) {
    if (path.empty()) return "an empty file name";
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        const int err = errno;
        struct stat link {};
        if (err == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
            std::error_code ec;
            const auto target = std::filesystem::read_symlink(path, ec);
            return quoted(path) + " is a symbolic link to " + (ec ? std::string("a file") : quoted(target)) +
                   ", which does not exist";
        }
        if (err == ENOENT) return "no such file " + quoted(path);
        return "cannot read " + quoted(path) + ": " + std::strerror(err);
    }
    if (std::string why = type_problem(path, st.st_mode); !why.empty()) return why;
    if (::access(path.c_str(), R_OK) != 0) return "cannot read " + quoted(path) + ": " + std::strerror(errno);
    return {};
}

std::string program_file_problem(const std::filesystem::path& path) {
    if (std::string why = input_problem(path); !why.empty()) return why;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode))
        return quoted(path) + " is a FIFO, not a file (a program is read more than once)";
    return {};
}

std::string read_input(const std::filesystem::path& path, FileKind kind) {
    if (std::string why = input_problem(path); !why.empty()) throw InputError(why);
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError("cannot read " + quoted(path) + ": " + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError("cannot read " + quoted(path) + ": " + std::strerror(errno));
    if (std::string why = type_problem(path, st.st_mode); !why.empty()) throw InputError(why);  // replaced meanwhile
    const std::uintmax_t cap = input_cap(kind);
    if (S_ISREG(st.st_mode) && static_cast<std::uintmax_t>(st.st_size) > cap) throw InputError(too_large(path, kind));
    // A FIFO (or a file still growing) is read up to one byte past the cap: that byte says it is too large.
    std::string bytes;
    bytes.reserve(S_ISREG(st.st_mode) ? static_cast<std::size_t>(st.st_size) : 0);
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError("cannot read " + quoted(path) + ": " + std::strerror(errno));
        }
        if (n == 0) break;
        bytes.append(buf, static_cast<std::size_t>(n));
        if (bytes.size() > cap) throw InputError(too_large(path, kind));
    }
    return bytes;
}

}  // namespace alp85
