#include "emu/util/atomic_file.h"

#include <string>
#include <system_error>
#include <unistd.h>

namespace alp85 {

namespace {
bool write_through(const std::filesystem::path& path) {
    std::error_code ec;
    const auto st = std::filesystem::symlink_status(path, ec);
    return !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st);
}
}  // namespace

AtomicOutput::AtomicOutput(std::filesystem::path path) : path_(std::move(path)) {
    if (!write_through(path_)) {
        tmp_ = path_;
        tmp_ += ".tmp" + std::to_string(::getpid());
    }
    out_.open(tmp_.empty() ? path_ : tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write '" + path_.string() + "'");
}

AtomicOutput::~AtomicOutput() {
    if (done_ || tmp_.empty()) return;
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(tmp_, ignored);
}

void AtomicOutput::commit() {
    out_.flush();
    const bool ok = static_cast<bool>(out_);
    out_.close();
    if (!ok || out_.fail()) throw std::runtime_error("cannot write '" + path_.string() + "' (disk full?)");
    if (!tmp_.empty()) {
        std::error_code ec;
        std::filesystem::rename(tmp_, path_, ec);
        if (ec) throw std::runtime_error("cannot write '" + path_.string() + "': " + ec.message());
    }
    done_ = true;
}

void write_atomic(const std::filesystem::path& path, std::string_view bytes) {
    AtomicOutput out(path);
    out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.commit();
}

}  // namespace alp85
