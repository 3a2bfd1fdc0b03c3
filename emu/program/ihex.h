// Intel HEX reading (record types 00 data, 01 end of file; 02-05 accepted and ignored where they
// carry no address for a 64 KiB machine). Used to load assembled images into emulated memory.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace alp85 {

// Where a file fails its checks: 1-based line and column (the character at fault, or the field
// of the record that is wrong), and why.
struct IntelHexError {
    int line = 1;
    int col = 1;
    std::string message;
};

// Calls store(addr, byte) for every data byte; nothing is stored from a file that fails its
// checks (the whole text is verified first). An empty file is an error ("empty file").
std::optional<IntelHexError> read_intel_hex(std::string_view text,
                                            const std::function<void(std::uint16_t, std::uint8_t)>& store);

// read_intel_hex with the error as "line N: why"; an empty string on success.
std::string load_intel_hex(std::string_view text, const std::function<void(std::uint16_t, std::uint8_t)>& store);

}  // namespace alp85
