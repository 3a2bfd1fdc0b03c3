#include "emu/dap/framing.h"

#include <cerrno>
#include <charconv>

#include <poll.h>
#include <unistd.h>

#include "emu/util/text.h"

namespace alp85::dap {
namespace {

constexpr std::string_view kEnd = "\r\n\r\n";
constexpr std::string_view kLength = "content-length:";

bool header_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '\r' || c == '\n' ||
           std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

}  // namespace

// After a frame that could not be read, its body (if it has one) is no message: everything up to
// the next "Content-Length:" goes. False while that header has not come yet.
bool FrameReader::resynchronise() {
    const std::size_t at = to_lower(buffer_).find(kLength);
    if (at == std::string::npos) {
        // Keep a tail that may be the header's beginning, cut where these bytes ended.
        buffer_.erase(0, buffer_.size() - std::min(buffer_.size(), kLength.size() - 1));
        return false;
    }
    buffer_.erase(0, at);
    resync_ = false;
    return true;
}

std::optional<Frame> FrameReader::refuse(std::string why) {
    buffer_.erase(0, 1);  // this block's own Content-Length, if it had one, is not the next frame's
    resync_ = true;
    resynchronise();      // what is here already goes now: a long run of junk is never kept
    return Frame{{}, std::move(why)};
}

std::optional<Frame> FrameReader::next() {
    if (skip_ > 0) {
        const std::size_t n = std::min(skip_, buffer_.size());
        buffer_.erase(0, n);
        skip_ -= n;
        if (skip_ > 0) return std::nullopt;
    }
    if (resync_ && !resynchronise()) return std::nullopt;
    // A header's name is a token (RFC 7230's tchar); a frame may begin with blank lines. Anything
    // else here is known at once to be no frame: bytes after a body longer than its Content-Length.
    if (!buffer_.empty() && !header_start(buffer_.front())) return refuse("bytes outside a frame (one begins with its Content-Length header)");
    const std::size_t end = buffer_.find(kEnd);
    // Lines ended by LF alone: the block ends at the first empty line, without its CR LF CR LF.
    if (const std::size_t lf = buffer_.find("\n\n"); lf != std::string::npos && lf < end)
        return refuse("a header block whose lines end in LF alone (the base protocol ends them with CR LF)");
    if (end == std::string::npos) {
        // A header block never ends if a peer sends garbage without a blank line: drop what
        // cannot be a header once it is longer than any header could be.
        if (buffer_.size() > 4096) return refuse("a header block of more than 4096 bytes without an end (\\r\\n\\r\\n)");
        return std::nullopt;
    }
    const std::string header = to_lower(std::string_view(buffer_).substr(0, end));
    std::optional<std::size_t> length;
    std::size_t pos = 0;
    while (pos <= header.size()) {
        std::size_t eol = header.find("\r\n", pos);
        if (eol == std::string::npos) eol = header.size();
        std::string_view line = std::string_view(header).substr(pos, eol - pos);
        if (line.starts_with(kLength)) {
            line.remove_prefix(kLength.size());
            while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
            while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
            std::size_t n = 0;
            const auto [p, ec] = std::from_chars(line.data(), line.data() + line.size(), n);
            if (ec != std::errc{} || p != line.data() + line.size() || line.empty())
                return refuse("a Content-Length that is not a number");
            length = n;
        }
        pos = eol + 2;
    }
    if (!length) return refuse("a header block without Content-Length");
    buffer_.erase(0, end + kEnd.size());
    if (*length > kMaxBody) {
        skip_ = *length;
        return Frame{{}, "a message of " + std::to_string(*length) + " bytes (at most " +
                             std::to_string(kMaxBody) + " are read)"};
    }
    if (buffer_.size() < *length) {
        // Not all there yet: put the header back in a form that parses the same.
        buffer_.insert(0, "Content-Length: " + std::to_string(*length) + std::string(kEnd));
        return std::nullopt;
    }
    Frame f{buffer_.substr(0, *length), {}};
    buffer_.erase(0, *length);
    return f;
}

std::string frame(std::string_view body) {
    std::string out = "Content-Length: " + std::to_string(body.size()) + std::string(kEnd);
    out += body;
    return out;
}

bool Channel::fill(int timeout_ms) {
    pollfd p{in_, POLLIN, 0};
    int r = ::poll(&p, 1, timeout_ms);
    while (r < 0 && errno == EINTR) r = ::poll(&p, 1, timeout_ms);
    if (r < 0) return false;
    if (r == 0) return true;
    char buf[65536];
    ssize_t n = ::read(in_, buf, sizeof buf);
    while (n < 0 && errno == EINTR) n = ::read(in_, buf, sizeof buf);
    if (n <= 0) return false;
    reader_.feed(std::string_view(buf, static_cast<std::size_t>(n)));
    return true;
}

bool Channel::send(std::string_view body) {
    const std::string out = frame(body);
    std::size_t done = 0;
    while (done < out.size()) {
        const ssize_t n = ::write(out_, out.data() + done, out.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace alp85::dap
