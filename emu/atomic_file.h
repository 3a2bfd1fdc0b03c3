// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file beside the target, which is renamed over it only when everything was written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace alp85 {

// Throws std::runtime_error naming the path and the reason; no temporary file is left behind.
void write_atomic(const std::filesystem::path& path, std::string_view bytes);
inline void write_atomic(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    write_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace alp85
