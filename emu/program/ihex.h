// Intel HEX reading (record types 00 data, 01 end of file; 02-05 accepted and ignored where they
// carry no address for a 64 KiB machine). Used to load assembled images into emulated memory.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace alp85 {

// Calls store(addr, byte) for every data byte. Returns an empty string on success, else an error
// "line N: why"; nothing is stored from a file that fails its checks (the whole text is verified
// first).
std::string load_intel_hex(std::string_view text, const std::function<void(std::uint16_t, std::uint8_t)>& store);

}  // namespace alp85
