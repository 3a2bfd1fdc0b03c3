// libFuzzer target: the DAP server's input. Two kinds of input, by the first byte:
//  - below 80H: bytes on the wire - framing (Content-Length headers), then each body given to
//    the adapter. The seed corpus holds real sessions (initialize, launch of a small program,
//    breakpoints, steps, evaluate), so that the fuzzer mutates requests the adapter gets that
//    far with.
//  - 80H and above: the rest drives a request generator. The bytes choose a command from the
//    adapter's own list (Adapter::commands) or another word, and fill seq, command, arguments and
//    the fields inside them (the argument names DAP uses, the objects and arrays they hold) with
//    values of every JSON type: the requests are well formed JSON whose fields have any type.
// Either way the adapter's runs advance a bounded number of slices after each request. Nothing a
// client sends may end the session: every frame is answered or ignored, never a crash; and (the
// generator's oracle) every request with an integer seq gets exactly one response naming it.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "emu/dap/adapter.h"
#include "emu/dap/framing.h"

namespace {

using alp85::dap::Adapter;
using alp85::dap::Json;

constexpr const char* kProgram = "/tmp/alp85-dap-fuzz.asm";

// Argument names the adapter's requests read or DAP defines, and strings that mean something to
// it (the program, its symbols and lines, addresses, expressions, console lines that run).
const char* const kKeys[] = {
    "threadId", "frameId", "source", "path", "name", "sourceReference", "breakpoints", "line", "column",
    "endLine", "condition", "hitCondition", "logMessage", "instructionReference", "offset", "dataId",
    "accessType", "filters", "variablesReference", "value", "expression", "context", "memoryReference",
    "count", "data", "instructionOffset", "instructionCount", "resolveSymbols", "startFrame", "levels",
    "granularity", "targetId", "singleThread", "restart", "terminateDebuggee", "arguments", "program",
    "firmware", "monitor", "stopOnEntry", "realTime", "defines", "motor", "keys", "bootTime", "script",
    "cwd", "map", "stopOnRunaway", "linesStartAt1", "adapterID", "supportsMemoryReferences", "format",
};
const char* const kStrings[] = {
    "", "x", kProgram, "alp85-dap-fuzz.asm", "START", "LOOP", "SUB", "0x0800", "0800H", "0x1B32", "1B32H:2",
    "A", "HL", "A+1", "word[SP]", "A == 3", "1/0", "3", ">=2", "%0", "runaway", "repl", "watch", "hover",
    "instruction", "read", "write", "readWrite", "AAEC", "====", "stepi 3", "step 2", "next", "continue",
    "finish", "until", "advance SUB", "jump LOOP", "run 1s", "run 100000s", "run for 10ms", "run x",
    "info registers", "print A", "x/4xb 0800H", "break SUB", "commands", "end", "set $N = 3", "reverse-step",
    "ideal", "physical", "thesis-fixed", "500ms", "R 7 0800 EXEC", "{A}",
};

Json value_of(FuzzedDataProvider& in, int depth);

Json object_of(FuzzedDataProvider& in, int depth) {
    Json o = Json::object();
    const int n = in.ConsumeIntegralInRange(0, 5);
    for (int i = 0; i < n; ++i) o[kKeys[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kKeys) - 1)]] = value_of(in, depth + 1);
    return o;
}

// A value of any JSON type; nested arrays and objects down to a few levels.
Json value_of(FuzzedDataProvider& in, int depth) {
    switch (in.ConsumeIntegralInRange(0, depth > 3 ? 5 : 8)) {
        case 0: return nullptr;
        case 1: return in.ConsumeBool();
        case 2: return in.ConsumeIntegralInRange<std::int64_t>(-2, 0x10001);
        case 3: return in.ConsumeIntegral<std::int64_t>();
        case 4: return in.ConsumeFloatingPoint<double>();
        case 5: return kStrings[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kStrings) - 1)];
        case 6: return in.ConsumeRandomLengthString(24);
        case 7: {
            Json a = Json::array();
            const int n = in.ConsumeIntegralInRange(0, 4);
            for (int i = 0; i < n; ++i) a.push_back(in.ConsumeBool() ? object_of(in, depth + 1) : value_of(in, depth + 1));
            return a;
        }
        default: return object_of(in, depth);
    }
}

struct Client {
    Adapter adapter;
    std::vector<Json> out;  // what the adapter sent during the last request
    Client() : adapter([this](const Json& m) { out.push_back(m); }) {}

    void run_a_little() {
        // Three slices a request (an unpaced slice is 20 ms of host time): enough for a run to go,
        // stop or be paused; more only made each input take seconds.
        for (int i = 0; i < 3 && adapter.running(); ++i) (void)adapter.advance();
    }
    // One request through the framing; the oracle: one response, naming it when it has a seq.
    void send(const Json& request) {
        alp85::dap::FrameReader r;
        // As the server writes: bytes that are not UTF-8 replaced (a fuzzed string may hold any).
        r.feed(alp85::dap::frame(request.dump(-1, ' ', false, Json::error_handler_t::replace)));
        const auto f = r.next();
        if (!f || !f->error.empty()) __builtin_trap();  // a frame the adapter wrote itself
        out.clear();
        adapter.receive(f->body);
        std::size_t responses = 0;
        for (const Json& m : out) {
            if (m.value("type", "") != "response") continue;
            ++responses;
            if (!m.value("success", false) && !m.contains("message")) __builtin_trap();
            const auto seq = request.find("seq");
            if (seq != request.end() && seq->is_number_integer() && m["request_seq"] != *seq) __builtin_trap();
        }
        const auto type = request.find("type");
        if (type != request.end() && *type == "request" && responses != 1) __builtin_trap();
        run_a_little();
    }
};

Json well_formed(int seq, const char* command, Json args) {
    return {{"seq", seq}, {"type", "request"}, {"command", command}, {"arguments", std::move(args)}};
}

void generated(FuzzedDataProvider& in) {
    Client c;
    const std::vector<std::string_view> commands = Adapter::commands();
    int seq = 1;
    // Most inputs get the session's start right, so that the requests after it reach the machine.
    const unsigned start = in.ConsumeIntegral<std::uint8_t>();
    if (start & 1) c.send(well_formed(seq++, "initialize", {{"adapterID", "alp85"}}));
    if (start & 2)
        c.send(well_formed(seq++, "launch", {{"program", kProgram}, {"monitor", false}, {"stopOnEntry", (start & 8) == 0}, {"realTime", false}}));
    if (start & 4) c.send(well_formed(seq++, "configurationDone", Json::object()));
    for (int i = 0; i < 48 && in.remaining_bytes() > 0 && !c.adapter.finished(); ++i) {
        Json r = Json::object();
        const unsigned shape = in.ConsumeIntegral<std::uint8_t>();
        r["type"] = shape & 1 ? value_of(in, 2) : Json("request");
        r["seq"] = shape & 2 ? value_of(in, 2) : Json(seq++);
        if (shape & 4) r["command"] = value_of(in, 2);
        else r["command"] = std::string(commands[in.ConsumeIntegralInRange<std::size_t>(0, commands.size() - 1)]);
        if (!(shape & 8)) r["arguments"] = shape & 16 ? value_of(in, 0) : object_of(in, 0);
        if (shape & 32) r.erase(std::string(in.ConsumeBool() ? "seq" : "type"));
        c.send(r);
    }
}

void wire(const std::uint8_t* data, std::size_t size) {
    std::size_t sent = 0;
    Adapter a([&sent](const Json&) { ++sent; });
    alp85::dap::FrameReader r;
    r.feed(std::string_view(reinterpret_cast<const char*>(data), size));
    int frames = 0;
    while (auto f = r.next()) {
        if (++frames > 64) break;
        if (!f->error.empty()) a.refuse_frame(f->error);
        else a.receive(f->body);
        for (int i = 0; i < 3 && a.running(); ++i) (void)a.advance();
        if (a.finished()) break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // The program the seeds launch (a loop with a call, so that there is a stack to look at).
    std::ofstream(kProgram) << "\tORG 0800H\nSTART:\tLXI SP,2000H\nLOOP:\tMVI A,5\n\tCALL SUB\n"
                               "\tJMP LOOP\nSUB:\tDCR A\n\tJNZ SUB\n\tRET\n\tEND START\n";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 64 * 1024) return 0;
    if (data[0] < 0x80) {
        wire(data, size);
    } else {
        FuzzedDataProvider in(data + 1, size - 1);
        generated(in);
    }
    return 0;
}
