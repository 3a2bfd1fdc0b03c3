#include "emu/script/runner.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <set>

#include <fmt/format.h>

#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85::script {
namespace {


SessionOptions session_options(const std::filesystem::path& file, const RunnerOptions& o) {
    SessionOptions s;
    s.base_dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    s.monitor_rom = o.monitor_rom;
    s.out = o.out;
    s.verbose = o.verbose;
    s.max_time = o.max_time;
    return s;
}

}  // namespace

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
    Session checker(session_options(file, options));
    checker.set_out_dir(options.out_dir);
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
    Session session(session_options(file, options));
    session.set_out_dir(options.out_dir);
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
