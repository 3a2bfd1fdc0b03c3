// Little-endian byte writer/reader for chip snapshots (save/load into a byte vector).
// Every chip writes a tag and a version first, so the board's machine file can be checked.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace alp85::periph {

// Thrown by load() when a snapshot is truncated, has the wrong tag/version or an invalid field.
class SnapshotError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
    void u8(std::uint8_t v) { out_.push_back(v); }
    void boolean(bool v) { u8(v ? 1 : 0); }
    void u16(std::uint16_t v) { for (int i = 0; i < 2; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i))); }
    void u32(std::uint32_t v) { for (int i = 0; i < 4; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i))); }
    void u64(std::uint64_t v) { for (int i = 0; i < 8; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i))); }
    void bytes(std::span<const std::uint8_t> b) { out_.insert(out_.end(), b.begin(), b.end()); }
    // Every part's state opens with two tag characters and a version byte.
    void header(char a, char b, std::uint8_t version) {
        u8(static_cast<std::uint8_t>(a));
        u8(static_cast<std::uint8_t>(b));
        u8(version);
    }

private:
    std::vector<std::uint8_t>& out_;
};

class ByteReader {
public:
    ByteReader(std::span<const std::uint8_t> in, std::string what) : in_(in), what_(std::move(what)) {}
    std::uint8_t u8() {
        if (pos_ >= in_.size()) fail("truncated");
        return in_[pos_++];
    }
    bool boolean() {
        const std::uint8_t v = u8();
        if (v > 1) fail("invalid boolean");
        return v != 0;
    }
    std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
    std::uint32_t u32() {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(u8()) << (8 * i);
        return v;
    }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(u8()) << (8 * i);
        return v;
    }
    void bytes(std::span<std::uint8_t> dst) {
        for (auto& b : dst) b = u8();
    }
    // The header ByteWriter::header wrote; fails with "not a <what> snapshot" or the version.
    void expect_header(char a, char b, std::uint8_t version) {
        if (u8() != static_cast<std::uint8_t>(a) || u8() != static_cast<std::uint8_t>(b)) fail("not " + what_ + " state");
        if (u8() != version) fail("unsupported version");
    }
    void expect_end() const {
        if (pos_ != in_.size()) fail("trailing bytes");
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw SnapshotError(what_ + " snapshot: " + why + " at byte " + std::to_string(pos_));
    }

private:
    std::span<const std::uint8_t> in_;
    std::size_t pos_ = 0;
    std::string what_;
};

}  // namespace alp85::periph
