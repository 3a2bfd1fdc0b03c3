// Base64 (RFC 4648, with padding): DAP's readMemory/writeMemory carry bytes this way.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace alp85::dap {

std::string base64_encode(std::string_view bytes);
// nullopt for a character outside the alphabet or a length that is not a whole number of quads
// (whitespace is skipped).
std::optional<std::string> base64_decode(std::string_view text);

}  // namespace alp85::dap
