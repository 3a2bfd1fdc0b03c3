// Saved state as bytes: little-endian writer and reader, and the field visitor that lets every
// part list its fields once for both save and load.
//
//   template <class S, class Io> static void fields(S& s, Io& io) { io(s.count); io(s.mode, 3); ... }
//   StateWriter w(out); fields(state, w);          // save (S = const State)
//   StateReader r(in, "8155"); fields(scratch, r);  // load, then validate scratch, then commit
//
// io(field) handles bool, integers, enums, double (bit-exact), std::array and std::vector of
// those; io(field, max) also refuses, on load, a value above max (enums, counts).
// Every section opens with two tag characters and a version byte (header / expect_header).
#pragma once

#include <array>
#include <cstring>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace alp85 {

// Thrown when saved state is truncated, has the wrong tag or version, or an invalid field.
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
    // The header ByteWriter::header wrote; fails with "not <what> state" or the version.
    void expect_header(char a, char b, std::uint8_t version) {
        if (u8() != static_cast<std::uint8_t>(a) || u8() != static_cast<std::uint8_t>(b)) fail("not " + what_ + " state");
        if (u8() != version) fail("unsupported version");
    }
    std::size_t remaining() const { return in_.size() - pos_; }
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

namespace state_io_detail {
template <class T> struct is_array : std::false_type {};
template <class T, std::size_t N> struct is_array<std::array<T, N>> : std::true_type {};
template <class T> struct is_vector : std::false_type {};
template <class T, class A> struct is_vector<std::vector<T, A>> : std::true_type {};
}  // namespace state_io_detail

// The save side of a field list.
class StateWriter : public ByteWriter {
public:
    using ByteWriter::ByteWriter;

    template <class T>
    void operator()(const T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            boolean(v);
        } else if constexpr (std::is_enum_v<T>) {
            (*this)(static_cast<std::underlying_type_t<T>>(v));
        } else if constexpr (std::is_same_v<T, double>) {
            // memcpy, not std::bit_cast: emscripten's libc++ (clang 14, the web build) lacks it.
            std::uint64_t bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            u64(bits);
        } else if constexpr (std::is_integral_v<T>) {
            using U = std::make_unsigned_t<T>;
            const U u = static_cast<U>(v);
            for (std::size_t i = 0; i < sizeof(T); ++i) u8(static_cast<std::uint8_t>(u >> (8 * i)));
        } else if constexpr (state_io_detail::is_array<T>::value) {
            for (const auto& e : v) (*this)(e);
        } else if constexpr (state_io_detail::is_vector<T>::value) {
            u32(static_cast<std::uint32_t>(v.size()));
            for (const auto& e : v) (*this)(e);
        } else {
            static_assert(sizeof(T) == 0, "StateWriter: unsupported field type");
        }
    }
    template <class T, class M>
    void operator()(const T& v, M /*max*/) { (*this)(v); }
};

// The load side of a field list: reads into a scratch state; the part validates and commits.
class StateReader : public ByteReader {
public:
    using ByteReader::ByteReader;

    template <class T>
    void operator()(T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            v = boolean();
        } else if constexpr (std::is_enum_v<T>) {
            std::underlying_type_t<T> raw{};
            (*this)(raw);
            v = static_cast<T>(raw);
        } else if constexpr (std::is_same_v<T, double>) {
            const std::uint64_t bits = u64();
            std::memcpy(&v, &bits, sizeof v);
        } else if constexpr (std::is_integral_v<T>) {
            using U = std::make_unsigned_t<T>;
            U u = 0;
            for (std::size_t i = 0; i < sizeof(T); ++i) u = static_cast<U>(u | static_cast<U>(U{u8()} << (8 * i)));
            v = static_cast<T>(u);
        } else if constexpr (state_io_detail::is_array<T>::value) {
            for (auto& e : v) (*this)(e);
        } else if constexpr (state_io_detail::is_vector<T>::value) {
            const std::uint32_t n = u32();
            if (n > remaining()) fail("invalid length");  // every element takes at least a byte
            v.assign(n, typename T::value_type{});
            for (auto& e : v) (*this)(e);
        } else {
            static_assert(sizeof(T) == 0, "StateReader: unsupported field type");
        }
    }
    // A field with an upper bound (an enum's last value, a count's maximum).
    template <class T, class M>
    void operator()(T& v, M max) {
        (*this)(v);
        if constexpr (std::is_enum_v<T>) {
            if (static_cast<std::underlying_type_t<T>>(v) > static_cast<std::underlying_type_t<T>>(max))
                fail("field out of range");
        } else {
            if (v > static_cast<T>(max)) fail("field out of range");
        }
    }
    void check(bool ok, const char* why) const {
        if (!ok) fail(why);
    }
};

}  // namespace alp85
