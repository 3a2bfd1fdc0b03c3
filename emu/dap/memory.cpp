// readMemory, writeMemory, disassemble: the 64 KB address space through the bus's side-effect-free
// view (peek) and the debugger's poke, and asm85's disassembler with the program's symbols.
#include <fmt/format.h>

#include "emu/dap/adapter.h"
#include "emu/dap/base64.h"
#include "emu/script/parser.h"

namespace alp85::dap {
std::uint16_t Adapter::address_of(const std::string& reference) const {
    if (!session_) throw RequestError("no program yet: send 'launch' first");
    if (const auto v = session_->debugger().program().value_of(reference)) return *v;
    const auto n = script::parse_number(reference);
    if (!n || *n < 0 || *n > 0xFFFF) throw RequestError(fmt::format("'{}' is not an address (0x1B32, 1B32H or a symbol)", reference));
    return static_cast<std::uint16_t>(*n);
}

void Adapter::read_memory(const Json& args, Json& body) {
    session();
    const std::int64_t base = address_of(need_string(args, "memoryReference")) + opt_int(args, "offset").value_or(0);
    const std::int64_t count = need_int(args, "count");
    if (count < 0) throw RequestError("argument 'count' must not be negative");
    // The address space ends at FFFFH: what lies beyond (or before 0) is unreadable.
    const std::int64_t first = std::clamp<std::int64_t>(base, 0, 0x10000);
    const std::int64_t last = std::clamp<std::int64_t>(base + count, 0, 0x10000);
    std::string bytes;
    for (std::int64_t a = first; a < last; ++a) bytes += static_cast<char>(session_->peek(static_cast<std::uint16_t>(a)));
    body = {{"address", hex4(static_cast<std::uint16_t>(std::min<std::int64_t>(first, 0xFFFF)))},
            {"data", base64_encode(bytes)}};
    if (const std::int64_t missing = count - (last - first); missing > 0) body["unreadableBytes"] = missing;
}

void Adapter::write_memory(const Json& args, Json& body) {
    require_stopped();
    const std::int64_t base = address_of(need_string(args, "memoryReference")) + opt_int(args, "offset").value_or(0);
    const auto data = base64_decode(need_string(args, "data"));
    if (!data) throw RequestError("argument 'data' is not base64");
    if (base < 0 || base + static_cast<std::int64_t>(data->size()) > 0x10000)
        throw RequestError("the bytes would run outside 0000H-FFFFH");
    std::int64_t written = 0;
    for (const char c : *data) {
        if (!session_->poke(static_cast<std::uint16_t>(base + written), static_cast<std::uint8_t>(c))) break;
        ++written;
    }
    if (written == 0 && !data->empty())
        throw RequestError(fmt::format("nothing is mapped at {:04X}H to write", static_cast<std::uint16_t>(base)));
    body = {{"bytesWritten", written}};
    if (written > 0) event("memory", {{"memoryReference", hex4(static_cast<std::uint16_t>(base))}, {"offset", 0}, {"count", written}});
}

void Adapter::disassemble(const Json& args, Json& body) {
    const debug::Debugger& dbg = session().debugger();
    const SymbolTable& symbols = dbg.program();
    std::int64_t addr = address_of(need_string(args, "memoryReference")) + opt_int(args, "offset").value_or(0);
    std::int64_t skip = std::clamp<std::int64_t>(opt_int(args, "instructionOffset").value_or(0), -65536, 65536);
    const std::int64_t count = need_int(args, "instructionCount");
    if (count < 0 || count > 65536) throw RequestError("argument 'instructionCount' must be 0 to 65536");
    const bool resolve = opt_bool(args, "resolveSymbols").value_or(true);
    // Backwards: the previous instruction is the one of 1-3 bytes that ends here, preferring one
    // that begins a source line.
    for (; skip < 0 && addr > 0; ++skip) {
        std::int64_t prev = addr - 1;
        for (int len = 3; len >= 1; --len) {
            if (addr - len < 0) continue;
            const auto a = static_cast<std::uint16_t>(addr - len);
            if (dbg.disassemble(a, !resolve).length != len) continue;
            prev = a;
            if (symbols.line_of(a) && (a == 0 || symbols.line_of(a) != symbols.line_of(static_cast<std::uint16_t>(a - 1)))) break;
        }
        addr = prev;
    }
    for (; skip > 0; --skip) addr += dbg.disassemble(static_cast<std::uint16_t>(addr & 0xFFFF), !resolve).length;
    Json out = Json::array();
    std::optional<SourceLine> last;
    for (std::int64_t i = 0; i < count; ++i) {
        if (addr < 0 || addr > 0xFFFF) {  // outside the address space: DAP wants the count all the same
            out.push_back({{"address", fmt::format("0x{:X}", addr & 0x1FFFF)}, {"instruction", "??"}, {"presentationHint", "invalid"}});
            ++addr;
            continue;
        }
        const auto a = static_cast<std::uint16_t>(addr);
        const auto d = dbg.disassemble(a, !resolve);
        std::string bytes;
        for (int k = 0; k < d.length; ++k) bytes += fmt::format("{}{:02X}", k ? " " : "", d.bytes[k]);
        Json j = {{"address", hex4(a)}, {"instructionBytes", bytes}, {"instruction", d.text}};
        if (const auto label = symbols.label_at(a)) j["symbol"] = *label;
        if (const auto line = symbols.line_of(a); line && line != last) {
            j["location"] = source_of(line->file);
            j["line"] = line->line - (lines_start_at_1_ ? 0 : 1);
            last = line;
        }
        out.push_back(std::move(j));
        addr += d.length;
    }
    body = {{"instructions", out}};
}

}  // namespace alp85::dap
