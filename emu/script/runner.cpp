#include "emu/script/runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <fstream>
#include <iterator>
#include <set>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85::script {
namespace {


SessionOptions session_options(const std::filesystem::path& file, const RunnerOptions& o, const std::vector<Command>& commands) {
    SessionOptions s;
    // The board: a script's first command `board NAME`, else --board.
    s.board = !commands.empty() && commands.front().op == Op::Board ? board::find_board(commands.front().name) : o.board;
    if (!s.board) s.board = o.board;
    s.base_dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    s.monitor_rom = o.monitor_rom;
    s.out = o.out;
    s.verbose = o.verbose;
    s.max_time = o.max_time;
    return s;
}

// Whether files can be made in `dir`: access() first, then a file made and removed, since root
// passes access() in a folder whose file system refuses new files (/proc, a read-only mount).
bool can_write_in(const std::filesystem::path& dir) {
    if (::access(dir.c_str(), W_OK) != 0) return false;
    static std::atomic<unsigned> probes{0};
    const std::filesystem::path probe = dir / fmt::format(".alp85-write-test-{}-{}", ::getpid(), probes++);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    ::close(fd);
    ::unlink(probe.c_str());
    return true;
}

// Where a script's save, restore, record and plot files go: --out-dir; else the script's folder,
// unless the script writes files and cannot write there (an installed example under /usr/share,
// run by a user): then the current folder, and `note` says so.
std::filesystem::path output_dir(const std::filesystem::path& file, const std::vector<Command>& commands,
                                 const RunnerOptions& o, std::string* note = nullptr) {
    if (!o.out_dir.empty()) return o.out_dir;
    const bool writes = std::any_of(commands.begin(), commands.end(), [](const Command& c) {
        return c.op == Op::Save || c.op == Op::Record || c.op == Op::Plot;
    });
    const std::filesystem::path dir = session_options(file, o, {}).base_dir;
    if (!writes || can_write_in(dir)) return {};
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::current_path(ec);
    if (ec || std::filesystem::equivalent(here, dir, ec)) return {};  // nowhere better: the write will say why
    if (note)
        *note = fmt::format("{}: note: its folder {} is not writable; the files it writes (save, record, plot) go "
                            "to the current folder, {} (--out-dir DIR chooses another)\n",
                            file.string(), dir.string(), here.string());
    return here;
}

// The files a script writes or reads back (save, restore, record, plot), as its session resolves
// them: relative to --out-dir, else to the script's folder.
std::vector<std::string> shared_files(const std::filesystem::path& file, const std::vector<Command>& commands,
                                      const RunnerOptions& o) {
    std::vector<std::string> paths;
    std::filesystem::path dir = output_dir(file, commands, o);
    if (dir.empty()) dir = session_options(file, o, {}).base_dir;
    for (const Command& c : commands) {
        if (c.op != Op::Save && c.op != Op::Restore && c.op != Op::Record && c.op != Op::Plot) continue;
        std::filesystem::path p(c.text);
        if (!p.is_absolute()) p = dir / p;
        std::error_code ec;
        const std::filesystem::path key = std::filesystem::weakly_canonical(p, ec);
        paths.push_back((ec ? p.lexically_normal() : key).string());
    }
    return paths;
}

}  // namespace

std::vector<std::vector<std::size_t>> script_groups(const std::vector<std::filesystem::path>& files,
                                                    const std::vector<std::vector<Command>>& programs,
                                                    const RunnerOptions& o) {
    std::vector<std::size_t> leader(files.size());
    std::iota(leader.begin(), leader.end(), std::size_t{0});
    auto find = [&](std::size_t i) {
        while (leader[i] != i) i = leader[i] = leader[leader[i]];
        return i;
    };
    std::map<std::string, std::size_t> first_user;
    for (std::size_t i = 0; i < files.size(); ++i)
        for (const std::string& f : shared_files(files[i], programs[i], o)) {
            const auto [it, fresh] = first_user.emplace(f, i);
            if (!fresh) {
                const std::size_t a = find(it->second), b = find(i);
                leader[std::max(a, b)] = std::min(a, b);  // the earlier script leads
            }
        }
    std::vector<std::vector<std::size_t>> groups;
    std::map<std::size_t, std::size_t> group_of;  // leader -> index in groups
    for (std::size_t i = 0; i < files.size(); ++i) {
        const auto [it, fresh] = group_of.emplace(find(i), groups.size());
        if (fresh) groups.emplace_back();
        groups[it->second].push_back(i);
    }
    return groups;
}

bool prepare(const std::filesystem::path& file, std::vector<Command>& commands, std::vector<ParseError>& errors,
             const RunnerOptions& options, std::vector<NamedPath>* inputs) {
    std::string text;
    try {
        text = read_input(file, FileKind::Script);
    } catch (const InputError& e) {
        const std::string why = e.what();
        errors.push_back({{file.string(), 0, 0}, why.rfind("no such file", 0) == 0 ? "no such script" : why, ""});
        return false;
    }
    if (const auto nul = text.find('\0'); nul != std::string::npos) {  // an image or a binary, not a script
        const auto line_start = text.rfind('\n', nul);
        const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n'));
        const int col = static_cast<int>(nul - (line_start == std::string::npos ? 0 : line_start + 1)) + 1;
        errors.push_back({{file.string(), line, col}, "not a script: binary data (a NUL byte)", ""});
        return false;
    }
    const std::size_t before = errors.size();
    std::vector<std::string> included;
    commands = parse_script(text, file.string(), errors, &included);
    for (std::size_t i = 1; i < commands.size(); ++i)
        if (commands[i].op == Op::Board)
            errors.push_back({commands[i].where, "board must be the script's first command (the machine is built before any other)",
                              commands[i].line});
    Session checker(session_options(file, options, commands));
    std::string note;
    checker.set_out_dir(output_dir(file, commands, options, &note));
    if (options.err) *options.err << note;
    checker.add_input(file, "the script");
    for (const std::string& f : included) checker.add_input(f, "an included script");
    for (const NamedPath& o : options.outputs) checker.add_output(o.path, o.role);
    checker.check(commands, errors);  // the lines that parsed: files, symbols, ranges
    if (options.err)
        for (const std::string& w : checker.warnings()) *options.err << w;
    if (inputs) *inputs = checker.inputs();
    std::stable_sort(errors.begin() + static_cast<std::ptrdiff_t>(before), errors.end(),
                     [](const ParseError& a, const ParseError& b) { return a.where.line < b.where.line; });
    return errors.size() == before;
}

ScriptResult execute(const std::filesystem::path& file, const std::vector<Command>& commands,
                     const RunnerOptions& options) {
    ScriptResult r;
    r.file = file.string();
    Session session(session_options(file, options, commands));
    session.set_out_dir(output_dir(file, commands, options));
    session.add_input(file, "the script");
    std::set<std::string> scripts;
    for (const Command& c : commands)
        if (scripts.insert(c.where.file).second) session.add_input(c.where.file, "an included script");
    for (const NamedPath& o : options.outputs) session.add_output(o.path, o.role);
    session.machine().tool().set_model(options.motor);
    if (options.trace) session.set_trace(options.trace);
    const auto start = std::chrono::steady_clock::now();
    r.passed = true;
    for (const Command& c : commands) {
        ++r.commands;
        const Session::Outcome o = session.execute(c);
        if (o.status != Session::Status::Ok) {
            r.passed = false;
            r.failure = o.message;
            break;
        }
    }
    if (const Session::Outcome o = session.finish(); r.passed && o.status != Session::Status::Ok) {
        r.passed = false;
        r.failure = o.message;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.tstates = session.machine().now();
    session.set_trace(nullptr);
    return r;
}

std::vector<ScriptResult> execute_all(const std::vector<std::filesystem::path>& files,
                                      const std::vector<std::vector<Command>>& programs, const RunnerOptions& options,
                                      unsigned jobs,
                                      const std::function<void(const ScriptResult&, const std::string& output)>& report) {
    std::vector<ScriptResult> results(files.size());
    if (jobs <= 1 || files.size() <= 1) {
        for (std::size_t i = 0; i < files.size(); ++i) {
            results[i] = execute(files[i], programs[i], options);
            report(results[i], {});
        }
        return results;
    }
    struct Held {
        std::ostringstream out, trace;
        bool done = false;
        std::exception_ptr error;  // what ended the run instead of a result (out of memory, say)
    };
    std::vector<Held> held(files.size());
    const std::vector<std::vector<std::size_t>> groups = script_groups(files, programs, options);
    std::mutex m;
    std::condition_variable finished;
    std::atomic<std::size_t> next_group{0};
    auto worker = [&] {
        for (std::size_t g; (g = next_group++) < groups.size();) {
            for (const std::size_t i : groups[g]) {
                RunnerOptions o = options;
                o.out = &held[i].out;
                o.trace = options.trace ? &held[i].trace : nullptr;
                ScriptResult r;
                std::exception_ptr error;
                try {
                    r = execute(files[i], programs[i], o);
                } catch (...) {
                    error = std::current_exception();  // rethrown when its turn to be reported comes
                }
                const std::lock_guard lock(m);
                results[i] = std::move(r);
                held[i].error = error;
                held[i].done = true;
                finished.notify_all();
            }
        }
    };
    std::vector<std::thread> threads;
    const std::size_t n = std::min<std::size_t>(jobs, groups.size());
    for (std::size_t t = 0; t < n; ++t) {
        try {
            threads.emplace_back(worker);
        } catch (const std::system_error&) {  // no more threads to be had: run with those there are
            break;
        }
    }
    if (threads.empty()) worker();
    auto join = [&] {
        for (std::thread& t : threads) t.join();
    };
    // Report in file order, each script as soon as it and every one before it are done.
    for (std::size_t i = 0; i < files.size(); ++i) {
        std::unique_lock lock(m);
        finished.wait(lock, [&] { return held[i].done; });
        lock.unlock();
        if (held[i].error) {
            join();
            std::rethrow_exception(held[i].error);
        }
        if (options.trace) *options.trace << held[i].trace.str();
        held[i].trace = {};
        report(results[i], held[i].out.str());
        held[i].out = {};
    }
    join();
    return results;
}

std::string junit_xml(const std::vector<ScriptResult>& results) {
    int failures = 0;
    double total = 0;
    for (const auto& r : results) {
        failures += r.passed ? 0 : 1;
        total += r.seconds;
    }
    std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x += fmt::format("<testsuites tests=\"{}\" failures=\"{}\" time=\"{:.6f}\">\n", results.size(), failures, total);
    x += fmt::format("  <testsuite name=\"alp85 script\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.6f}\">\n",
                     results.size(), failures, total);
    for (const auto& r : results) {
        x += fmt::format("    <testcase classname=\"alp85.script\" name=\"{}\" time=\"{:.6f}\"", xml_escape(r.file), r.seconds);
        if (r.passed) {
            x += fmt::format(">\n      <system-out>{} commands, {:.3f} ms simulated</system-out>\n    </testcase>\n",
                             r.commands, board::ms_from_tstates(r.tstates));
        } else {
            const std::string first = r.failure.substr(0, r.failure.find('\n'));
            x += fmt::format(">\n      <failure message=\"{}\">{}</failure>\n    </testcase>\n", xml_escape(first),
                             xml_escape(r.failure));
        }
    }
    x += "  </testsuite>\n</testsuites>\n";
    return x;
}

}  // namespace alp85::script
