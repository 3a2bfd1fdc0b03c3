#include "emu/board/snapshot_file.h"

#include "asm/files/atomic_file.h"
#include "emu/util/input_file.h"

#include <zlib.h>

#include <fstream>
#include <iterator>

namespace alp85::snapshot {
namespace {

constexpr std::string_view kMagic = "ALP85SNP";
constexpr std::size_t kHeaderSize = 8 + 4 + 4 + 4;

std::uint32_t crc32_of(const std::uint8_t* p, std::size_t n) {
    uLong crc = crc32(0L, Z_NULL, 0);
    // zlib takes uInt lengths; feed large payloads in pieces.
    while (n > 0) {
        const uInt chunk = n > 0x40000000u ? 0x40000000u : static_cast<uInt>(n);
        crc = crc32(crc, p, chunk);
        p += chunk;
        n -= chunk;
    }
    return static_cast<std::uint32_t>(crc);
}

}  // namespace

std::vector<std::uint8_t> encode(const std::vector<Section>& sections) {
    std::vector<std::uint8_t> payload;
    ByteWriter w(payload);
    for (const Section& s : sections) {
        if (s.tag.size() != 4) throw SnapshotError("snapshot section tag '" + s.tag + "' is not 4 characters");
        for (char c : s.tag) w.u8(static_cast<std::uint8_t>(c));
        w.u32(static_cast<std::uint32_t>(s.data.size()));
        w.bytes(s.data);
    }
    std::vector<std::uint8_t> file;
    ByteWriter h(file);
    for (char c : kMagic) h.u8(static_cast<std::uint8_t>(c));
    h.u32(kFormatVersion);
    h.u32(static_cast<std::uint32_t>(payload.size()));
    h.u32(crc32_of(payload.data(), payload.size()));
    h.bytes(payload);
    return file;
}

std::vector<Section> decode(const std::vector<std::uint8_t>& file) {
    if (file.size() < kHeaderSize || !std::equal(kMagic.begin(), kMagic.end(), file.begin()))
        throw SnapshotError("not an ALP85 snapshot (no ALP85SNP header)");
    const std::span<const std::uint8_t> all(file);
    ByteReader r{all.subspan(8, 12), "ALP85"};
    const std::uint32_t version = r.u32();
    const std::uint32_t length = r.u32();
    const std::uint32_t crc = r.u32();
    if (version != kFormatVersion)
        throw SnapshotError("snapshot format version " + std::to_string(version) +
                            " is not supported (this ALP85 reads version " +
                            std::to_string(kFormatVersion) + ")");
    if (file.size() - kHeaderSize != length)
        throw SnapshotError("snapshot is truncated or has trailing bytes (header says " +
                            std::to_string(length) + " payload bytes, file has " +
                            std::to_string(file.size() - kHeaderSize) + ")");
    if (crc32_of(file.data() + kHeaderSize, length) != crc)
        throw SnapshotError("snapshot is corrupt (CRC-32 mismatch)");

    std::vector<Section> sections;
    ByteReader p{all.subspan(kHeaderSize), "ALP85"};
    std::size_t left = length;
    while (left > 0) {
        if (left < 8) p.fail("section header cut short");
        Section s;
        for (int i = 0; i < 4; ++i) s.tag.push_back(static_cast<char>(p.u8()));
        const std::uint32_t n = p.u32();
        left -= 8;
        if (n > left) p.fail("section '" + s.tag + "' runs past the end");
        s.data.resize(n);
        p.bytes(s.data);
        left -= n;
        sections.push_back(std::move(s));
    }
    return sections;
}

void write_atomic(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    try {
        alp85::write_atomic(path, bytes);
    } catch (const std::runtime_error& e) {
        throw SnapshotError(std::string("snapshot: ") + e.what());
    }
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    try {
        const std::string bytes = read_input(path, FileKind::Snapshot);
        return {bytes.begin(), bytes.end()};
    } catch (const InputError& e) {
        throw SnapshotError(std::string("snapshot: ") + e.what());
    }
}

const Section& find(const std::vector<Section>& sections, std::string_view tag) {
    for (const Section& s : sections)
        if (s.tag == tag) return s;
    throw SnapshotError("snapshot has no '" + std::string(tag) + "' section");
}

}  // namespace alp85::snapshot
