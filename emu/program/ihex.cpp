#include "emu/program/ihex.h"

#include <vector>

namespace alp85 {

namespace {
int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}
}  // namespace

std::optional<IntelHexError> read_intel_hex(std::string_view text,
                                            const std::function<void(std::uint16_t, std::uint8_t)>& store) {
    struct Byte {
        std::uint16_t addr;
        std::uint8_t value;
    };
    std::vector<Byte> bytes;
    bool ended = false;
    int line_no = 0;
    bool any_record = false;
    std::size_t pos = 0;
    while (pos < text.size() && !ended) {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string_view::npos) eol = text.size();
        std::string_view line = text.substr(pos, eol - pos);
        pos = eol + 1;
        ++line_no;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
        if (line.empty()) continue;
        any_record = true;
        // Columns: ':' 1, byte count 2, address 4, type 8, data 10, checksum last two.
        const auto fail = [&](int col, std::string why) { return IntelHexError{line_no, col, std::move(why)}; };
        if (line[0] != ':') return fail(1, "record does not start with ':'");
        if (line.size() < 11 || (line.size() - 1) % 2 != 0)
            return fail(static_cast<int>(line.size()) + 1, "truncated record");
        std::vector<std::uint8_t> rec;
        for (std::size_t i = 1; i + 1 < line.size(); i += 2) {
            const int hi = hex_digit(line[i]), lo = hex_digit(line[i + 1]);
            if (hi < 0 || lo < 0) return fail(static_cast<int>(hi < 0 ? i : i + 1) + 1, "not a hexadecimal digit");
            rec.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
        }
        const unsigned count = rec[0];
        if (rec.size() != count + 5u) return fail(2, "byte count does not match the record length");
        unsigned sum = 0;
        for (std::uint8_t b : rec) sum += b;
        if ((sum & 0xFF) != 0) return fail(static_cast<int>(line.size()) - 1, "checksum mismatch");
        const unsigned addr = (rec[1] << 8) | rec[2];
        switch (rec[3]) {
            case 0x00:
                if (addr + count > 0x10000u) return fail(4, "data beyond FFFFH");
                for (unsigned i = 0; i < count; ++i)
                    bytes.push_back({static_cast<std::uint16_t>(addr + i), rec[4 + i]});
                break;
            case 0x01: ended = true; break;
            case 0x02:
            case 0x04:
                if (count != 2 || rec[4] != 0 || rec[5] != 0) return fail(10, "segment/linear address beyond 64 KiB");
                break;
            case 0x03:
            case 0x05: break;  // start address: not needed to load
            default: return fail(8, "unknown record type");
        }
    }
    if (!any_record) return IntelHexError{1, 1, "empty file: no Intel HEX records"};
    if (!ended) return IntelHexError{line_no + 1, 1, "no end-of-file record (:00000001FF)"};
    for (const Byte& b : bytes) store(b.addr, b.value);
    return std::nullopt;
}

std::string load_intel_hex(std::string_view text, const std::function<void(std::uint16_t, std::uint8_t)>& store) {
    const auto e = read_intel_hex(text, store);
    return e ? "line " + std::to_string(e->line) + ": " + e->message : std::string();
}

}  // namespace alp85
