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

void AtomicFileGroup::add(std::filesystem::path path, std::string bytes) {
    files_.push_back({std::move(path), std::move(bytes)});
}

void AtomicFileGroup::commit() {
    namespace fs = std::filesystem;
    struct Staged {
        const File* file;
        fs::path tmp;     // empty: written through
        fs::path backup;  // the target's old contents while renaming (empty: there was none)
        bool renamed = false;
    };
    std::vector<Staged> staged;
    const std::string suffix = ".tmp" + std::to_string(::getpid()) + ".";
    std::error_code ignored;
    const auto undo = [&] {
        for (auto it = staged.rbegin(); it != staged.rend(); ++it) {
            if (it->renamed) {
                if (!it->backup.empty()) fs::rename(it->backup, it->file->path, ignored);
                else fs::remove(it->file->path, ignored);
            } else if (!it->backup.empty()) {
                fs::remove(it->backup, ignored);
            }
            if (!it->tmp.empty()) fs::remove(it->tmp, ignored);
        }
    };
    const auto write = [](const fs::path& to, const std::string& bytes) {
        std::ofstream out(to, std::ios::binary | std::ios::trunc);
        if (!out) return false;
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        return !out.fail();
    };
    // 1. Every file to a temporary.
    for (std::size_t i = 0; i < files_.size(); ++i) {
        const File& f = files_[i];
        if (write_through(f.path)) continue;
        fs::path tmp = f.path;
        tmp += suffix + std::to_string(i);
        staged.push_back({&f, tmp, {}});
        if (!write(tmp, f.bytes)) {
            undo();
            throw std::runtime_error("cannot write '" + f.path.string() + "'");
        }
    }
    // 2. Devices and links.
    for (const File& f : files_)
        if (write_through(f.path) && !write(f.path, f.bytes)) {
            undo();
            throw std::runtime_error("cannot write '" + f.path.string() + "'");
        }
    // 3. The renames; an old target is kept (a hard link) until all are done.
    for (Staged& s : staged) {
        std::error_code ec;
        if (fs::is_regular_file(fs::symlink_status(s.file->path, ec))) {
            fs::path backup = s.tmp;
            backup += ".old";
            fs::create_hard_link(s.file->path, backup, ec);
            if (!ec) s.backup = backup;
        }
        fs::rename(s.tmp, s.file->path, ec);
        if (ec) {
            undo();
            throw std::runtime_error("cannot write '" + s.file->path.string() + "': " + ec.message());
        }
        s.renamed = true;
        s.tmp.clear();
    }
    for (const Staged& s : staged)
        if (!s.backup.empty()) fs::remove(s.backup, ignored);
    files_.clear();
}

void write_atomic(const std::filesystem::path& path, std::string_view bytes) {
    AtomicOutput out(path);
    out.stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.commit();
}

}  // namespace alp85
