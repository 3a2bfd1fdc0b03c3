// libFuzzer target: `alp85 run`'s arguments as the command line gives them: --keys (a key list:
// "R 7 0800 EXEC"), FILE@ADDR's address, and the --boot/--for times. Each is read or refused
// with a message and an offset inside the text.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "emu/script/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 4096) return 0;
    using namespace alp85::script;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    std::string why;
    switch (data[0] % 3) {
        case 0: {
            std::size_t at = 0;
            const auto keys = parse_key_list(text, why, at);
            if (!keys && (why.empty() || at > text.size())) __builtin_trap();
            break;
        }
        case 1: {  // FILE@ADDR: what follows the last '@'
            const auto a = text.rfind('@');
            const std::string_view addr = a == std::string_view::npos ? text : text.substr(a + 1);
            int col = 1;
            const auto v = parse_value(addr, "an address", true, why, col);
            if (!v && (why.empty() || col < 1 || static_cast<std::size_t>(col) > addr.size() + 1)) __builtin_trap();
            break;
        }
        case 2:
            (void)parse_time(text);
            break;
    }
    return 0;
}
