// The machine snapshot file: a versioned container of tagged sections with a CRC-32.
//
//   "ALP85SNP"  magic, 8 bytes
//   u32         format version (kFormatVersion)
//   u32         payload length in bytes
//   u32         CRC-32 (zlib) of the payload
//   payload     sections: 4-byte tag, u32 length, bytes
//
// All integers little-endian. Files are written atomically (a temporary file beside the target,
// flushed, then renamed), so a crash never leaves a half-written snapshot under the real name.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "peripherals/state_io.h"

namespace alp85::snapshot {

using alp85::SnapshotError;

inline constexpr std::uint32_t kFormatVersion = 1;

struct Section {
    std::string tag;  // exactly 4 characters
    std::vector<std::uint8_t> data;
};

std::vector<std::uint8_t> encode(const std::vector<Section>& sections);
// Throws SnapshotError naming what is wrong (not a snapshot, version, length, checksum, layout).
std::vector<Section> decode(const std::vector<std::uint8_t>& file);

// Writes bytes to path atomically; reads a whole file. Both throw SnapshotError naming the path.
void write_atomic(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);
std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path);

const Section& find(const std::vector<Section>& sections, std::string_view tag);

}  // namespace alp85::snapshot
