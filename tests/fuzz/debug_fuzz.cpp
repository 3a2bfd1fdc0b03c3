// libFuzzer target: the debugger's expressions and its console must answer any text with a value
// or an error - never a crash, a hang or undefined behaviour. The first byte picks: an expression
// (parsed both ways a bare name can be read, evaluated, assigned), or console lines (commands
// that only look, set, step once or run a few T-states; breakpoint commands ... end that resume
// the run; no unbounded run, no files written).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "emu/debug/expr.h"
#include "emu/script/debug_shell.h"

namespace {

using namespace alp85;

// The console commands fed to it: looking, breakpoints and their commands, setting, single steps,
// runs of a few T-states. Runs that go on until something happens (continue, finish, a long run,
// wait ...) and commands that write files are left out: they are bounded by machine time, not by
// the fuzzer's patience.
bool allowed(std::string_view line) {
    const auto a = line.find_first_not_of(" \t");
    if (a == std::string_view::npos) return true;
    const auto b = line.find_first_of(" \t", a);
    const std::string_view word = line.substr(a, b == std::string_view::npos ? std::string_view::npos : b - a);
    const bool bare = b == std::string_view::npos || line.find_first_not_of(" \t", b) == std::string_view::npos;
    for (std::string_view w : {"break", "b", "tbreak", "watch", "rwatch", "awatch", "delete", "d", "enable", "disable",
                               "condition", "ignore", "print", "p", "set", "display", "undisplay", "x", "list", "l",
                               "disassemble", "backtrace", "bt", "info", "i", "history", "expect", "help", "show", "end",
                               "commands", "silent", "echo", "output"})
        if (word == w) return true;
    // One instruction: a count could ask for billions. step and next (to the next source line)
    // are left out: without source lines, or on a halted CPU, they run up to the debugger's
    // limit of machine time (seconds of host time each). So is nexti: over a CALL that never
    // returns (the monitor's key loop, once a line has set the PC there) it runs to that limit
    // too - 10 minutes of machine time, bounded but long (a 1-hour run's one "timeout").
    for (std::string_view w : {"stepi", "si", "reverse-stepi", "rsi"})
        if (word == w) return bare;
    // A run of at most 9999 T-states (run 24t): bounded however the program was changed. Given at
    // a breakpoint's stop by its commands, it resumes the run, and the stop it reaches runs its
    // own commands in turn (the little program's loop hits a breakpoint at 2 again and again).
    if (word == "run" && !bare) {
        const std::string_view t = line.substr(line.find_first_not_of(" \t", b));
        const auto digits = t.find_first_not_of("0123456789");
        return digits > 0 && digits <= 4 && digits != std::string_view::npos && (t.substr(digits) == "t" || t.substr(digits) == "T");
    }
    return false;
}

script::DebugShell& shell() {
    static script::DebugShell* s = [] {
        auto* sh = new script::DebugShell(script::SessionOptions{});
        // A little program at 0 to step through: MVI A,5; DCR A; JNZ 2; HLT. (The script's set mem
        // takes the bytes after the address; "set mem 0 = 3EH" was refused, and memory stayed empty.)
        sh->execute("set mem 0 3EH 05H 3DH 0C2H 02H 00H 76H");
        sh->execute("set PC = 0");
        return sh;
    }();
    return *s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 16 * 1024) return 0;
    const unsigned mode = data[0] % 2;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    script::DebugShell& sh = shell();
    if (mode == 0) {
        debug::Expr::Variables vars{{"T0", -1}, {"X", 0x7FFF'FFFF'FFFF'FFFF}};
        for (const auto names : {debug::Expr::Names::RegistersFirst, debug::Expr::Names::SymbolsFirst}) {
            debug::ExprError err;
            const auto e = debug::Expr::parse(text, sh.debugger().program(), err, names, 0, &vars);
            if (!e) continue;
            try {
                const std::int64_t v = e->eval(sh.session().machine());
                (void)e->width();
                if (e->assignable()) (void)e->assign(sh.session().machine(), v);
            } catch (const debug::ExprError&) {
            }
        }
        return 0;
    }
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t nl = text.find('\n', pos);
        const std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
        if (allowed(line)) (void)sh.execute(std::string(line));
        if (nl == std::string_view::npos) break;
        pos = nl + 1;
    }
    return 0;
}
