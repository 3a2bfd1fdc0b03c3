#include "asm/files/atomic_file.h"

#include <atomic>
#include <memory>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>

#include <unistd.h>

namespace alp85 {

namespace {

// The live temporaries. A slot is free (0), being filled (1) or live (2); the handler reads only
// live ones, and a path is written before its slot is published.
constexpr int kSlots = 64;  // asm85's group needs 8 (four files and their backups)
struct Slot {
    std::atomic<int> state{0};
    char path[4096];
};
static_assert(std::atomic<int>::is_always_lock_free);
Slot g_slots[kSlots];

extern "C" void remove_temporaries(int sig) {
    for (Slot& s : g_slots)
        if (s.state.load() == 2) ::unlink(s.path);
    // SA_RESETHAND restored the default action: re-raised, the signal ends the process as it
    // would have without us once this handler returns.
    ::raise(sig);
}

void install_handlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction old {};
            if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO)) continue;
            struct sigaction sa {};
            sa.sa_handler = remove_temporaries;
            sigemptyset(&sa.sa_mask);
            for (const int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, other);  // one cleanup at a time
            sa.sa_flags = SA_RESETHAND;
            ::sigaction(sig, &sa, nullptr);
        }
    });
}

bool write_through(const std::filesystem::path& path) {
    std::error_code ec;
    const auto st = std::filesystem::symlink_status(path, ec);
    return !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st);
}
}  // namespace

void TemporaryGuard::guard(const std::filesystem::path& path) {
    release();
    std::error_code ec;
    const std::string abs = std::filesystem::absolute(path, ec).string();  // the handler may run after a chdir
    if (ec || abs.size() >= sizeof(Slot::path)) return;
    install_handlers();
    for (int i = 0; i < kSlots; ++i) {
        int free = 0;
        if (!g_slots[i].state.compare_exchange_strong(free, 1)) continue;
        std::memcpy(g_slots[i].path, abs.c_str(), abs.size() + 1);
        g_slots[i].state.store(2);
        slot_ = i;
        return;
    }
}

void TemporaryGuard::release() {
    if (slot_ >= 0) g_slots[slot_].state.store(0);
    slot_ = -1;
}

AtomicOutput::AtomicOutput(std::filesystem::path path) : path_(std::move(path)) {
    if (!write_through(path_)) {
        tmp_ = path_;
        tmp_ += ".tmp" + std::to_string(::getpid());
        guard_.guard(tmp_);  // before the file exists: no moment when it is there unguarded
    }
    out_.open(tmp_.empty() ? path_ : tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write '" + path_.string() + "'");
}

AtomicOutput::~AtomicOutput() {
    if (done_ || tmp_.empty()) return;
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(tmp_, ignored);
    guard_.release();
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
        guard_.release();
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
        std::unique_ptr<TemporaryGuard> tmp_guard = std::make_unique<TemporaryGuard>(),
                                        backup_guard = std::make_unique<TemporaryGuard>();
    };
    std::vector<Staged> staged;
    staged.reserve(files_.size());
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
        staged.back().tmp_guard->guard(tmp);
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
            s.backup_guard->guard(backup);
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
        s.tmp_guard->release();
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
