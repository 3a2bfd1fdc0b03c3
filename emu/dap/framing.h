// The Debug Adapter Protocol's base protocol: messages framed by a "Content-Length: N" header
// block and a blank line, over a pair of file descriptors (stdin/stdout, or one TCP socket).
// Reads never block past what poll() allows, so the adapter can run the machine between
// messages and still answer `pause` at once.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace alp85::dap {

// One framed message taken from the input, or a header block that could not be read (then
// `error` says why and `body` is empty: the adapter answers with an error response and goes on).
// After a block that could not be read the reader resynchronises: the bytes up to the next
// "Content-Length:" header (the refused frame's body, stray bytes) are dropped unread, so one bad
// frame costs one error response and the frames after it are read as sent.
struct Frame {
    std::string body;
    std::string error;
};

// Splits a byte stream into frames. Pure (no I/O): the tests feed it bytes in any pieces.
class FrameReader {
public:
    // A body larger than this is refused (its bytes are skipped), so no header can make the
    // adapter allocate without bound.
    static constexpr std::size_t kMaxBody = 16u << 20;

    void feed(std::string_view bytes) { buffer_.append(bytes); }
    // The next complete frame, or nullopt until more bytes arrive.
    std::optional<Frame> next();
    std::size_t buffered() const { return buffer_.size(); }  // bytes kept for frames to come

private:
    std::optional<Frame> refuse(std::string why);  // the block at the front is unreadable
    bool resynchronise();

    std::string buffer_;
    std::size_t skip_ = 0;  // bytes of a refused body still to drop
    bool resync_ = false;   // dropping bytes up to the next Content-Length header
};

std::string frame(std::string_view body);  // "Content-Length: N\r\n\r\n" + body

// A connection: frames in from `in`, frames out to `out` (the same descriptor for a socket).
class Channel {
public:
    Channel(int in, int out) : in_(in), out_(out) {}
    // Waits up to timeout_ms (0: a poll, -1: until something comes) for bytes and takes those
    // there are. False when the input has ended (EOF or an error).
    bool fill(int timeout_ms);
    std::optional<Frame> next() { return reader_.next(); }
    // Writes one whole frame; false when the peer has gone.
    bool send(std::string_view body);

private:
    int in_, out_;
    FrameReader reader_;
};

}  // namespace alp85::dap
