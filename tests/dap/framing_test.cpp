// The DAP base protocol's framing, base64 and the breakpoint options, from their definitions
// (the DAP specification's "Base Protocol"; RFC 4648's test vectors).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "emu/dap/base64.h"
#include "emu/dap/breakpoints.h"
#include "emu/debug/debugger.h"
#include "emu/dap/framing.h"

namespace alp85::dap {
namespace {

TEST(Framing, AMessageInPiecesComesOutWhole) {
    FrameReader r;
    const std::string wire = frame(R"({"seq":1})") + frame("{}");
    for (char c : wire.substr(0, 10)) r.feed(std::string(1, c));
    EXPECT_FALSE(r.next());
    r.feed(wire.substr(10));
    auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, R"({"seq":1})");
    EXPECT_EQ(f->error, "");
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, "{}");
    EXPECT_FALSE(r.next());
}

TEST(Framing, HeaderNamesAreCaseInsensitiveAndOtherHeadersAreIgnored) {
    FrameReader r;
    r.feed("content-length: 2\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n{}");
    const auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, "{}");
}

TEST(Framing, LengthIsInBytesNotCharacters) {
    FrameReader r;
    const std::string body = "\"\xC3\xBC\"";  // "ü": 4 bytes, 3 characters
    r.feed("Content-Length: 4\r\n\r\n" + body);
    const auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, body);
}

TEST(Framing, BadHeadersAreReportedAndTheStreamGoesOn) {
    FrameReader r;
    r.feed("X: y\r\n\r\n");
    auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_NE(f->error.find("without Content-Length"), std::string::npos);
    r.feed("Content-Length: 1x\r\n\r\n");
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_NE(f->error.find("not a number"), std::string::npos);
    r.feed(frame("{}"));
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, "{}");
}

// Everything the reader makes of `wire`: bodies as they are, errors as "!".
std::vector<std::string> frames_of(const std::string& wire, bool byte_by_byte) {
    FrameReader r;
    std::vector<std::string> out;
    auto take = [&] {
        while (auto f = r.next()) out.push_back(f->error.empty() ? f->body : "!");
    };
    if (byte_by_byte) {
        for (const char c : wire) {
            r.feed(std::string(1, c));
            take();
        }
    } else {
        r.feed(wire);
        take();
    }
    return out;
}

// A bad frame that has a body: one error, and the frames after it read as sent - the reader
// drops the refused frame's body and anything else up to the next Content-Length header (the
// DAP specification's "Base Protocol": a header block of "Content-Length: N" lines ended by
// CR LF, a blank line, then N bytes). The body holds no "Content-Length:" of its own.
TEST(Framing, AfterABadFrameWithABodyTheNextFramesAreReadAsSent) {
    const std::string body = R"({"seq": 7, "type": "request", "command": "threads"})";
    const std::string next1 = R"({"seq": 8, "type": "request", "command": "threads"})";
    const std::string next2 = R"({"seq": 9, "type": "request", "command": "disconnect"})";
    const std::string n = std::to_string(body.size());
    const std::pair<const char*, std::string> bad[] = {
        {"no Content-Length", "Content-Type: application/vscode-jsonrpc\r\n\r\n" + body},
        {"abc", "Content-Length: abc\r\n\r\n" + body},
        {"-5", "Content-Length: -5\r\n\r\n" + body},
        {"+2", "Content-Length: +" + n + "\r\n\r\n" + body},
        {"1e3", "Content-Length: 1e3\r\n\r\n" + body},
        {"a tab", "Content-Length:\t" + n + "\r\n\r\n" + body},
        {"a number and text", "Content-Length: " + n + " bytes\r\n\r\n" + body},
        {"LF-only header", "Content-Length: " + n + "\n\n" + body},
        {"CR LF then LF", "Content-Length: " + n + "\r\n\n" + body},
        {"extra bytes after a body", frame(body) + "}}garbage"},
        {"a lower-case header and extra bytes", "content-length: 2\r\n\r\n{}" + body},
    };
    for (const auto& [what, wire] : bad) {
        for (const bool pieces : {false, true}) {
            SCOPED_TRACE(std::string(what) + (pieces ? ", fed byte by byte" : ", fed at once"));
            const auto got = frames_of(wire + frame(next1) + frame(next2), pieces);
            std::vector<std::string> want = {"!", next1, next2};
            if (std::string_view(what) == "extra bytes after a body") want = {body, "!", next1, next2};
            if (std::string_view(what) == "a lower-case header and extra bytes") want = {"{}", "!", next1, next2};
            EXPECT_EQ(got, want);
        }
    }
}

TEST(Framing, AnOversizedBodyIsSkippedNotKept) {
    FrameReader r;
    const std::size_t n = FrameReader::kMaxBody + 5;
    r.feed("Content-Length: " + std::to_string(n) + "\r\n\r\n");
    auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_NE(f->error.find("at most"), std::string::npos);
    r.feed(std::string(n, 'x'));  // the refused body, dropped as it comes
    EXPECT_FALSE(r.next());
    r.feed(frame("{}"));
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, "{}");
}

TEST(Framing, AHeaderThatNeverEndsIsDropped) {
    FrameReader r;
    r.feed(std::string(5000, 'a'));
    const auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_FALSE(f->error.empty());
    // What is kept is at most a "Content-Length:" cut short (15 bytes less one), however much comes.
    EXPECT_LT(r.buffered(), 15u);
    for (int i = 0; i < 100; ++i) {
        r.feed(std::string(1000, 'a'));
        EXPECT_FALSE(r.next());
    }
    EXPECT_LT(r.buffered(), 15u);
    r.feed(frame("{}"));
    const auto g = r.next();
    ASSERT_TRUE(g);
    EXPECT_EQ(g->body, "{}");
}

TEST(Base64, Rfc4648Vectors) {
    const std::pair<std::string, std::string> v[] = {{"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},
                                                     {"foo", "Zm9v"},  {"foob", "Zm9vYg=="},  {"fooba", "Zm9vYmE="},
                                                     {"foobar", "Zm9vYmFy"}};
    for (const auto& [plain, coded] : v) {
        EXPECT_EQ(base64_encode(plain), coded);
        EXPECT_EQ(base64_decode(coded), plain);
    }
    EXPECT_EQ(base64_encode(std::string("\x00\xFF", 2)), "AP8=");
}

TEST(Base64, RefusesWhatIsNotBase64) {
    EXPECT_FALSE(base64_decode("Zm9"));     // not whole quads
    EXPECT_FALSE(base64_decode("Zm9*"));    // outside the alphabet
    EXPECT_FALSE(base64_decode("Zg==Zm8="));  // data after the padding
}

// DAP's hit conditions are the Debugger's (issue 22 moved them): the same forms, read the same way.
std::optional<bool> hit_condition_met(const std::string& text, std::uint64_t hits) {
    const auto h = debug::HitCondition::parse(text);
    if (!h) return std::nullopt;
    return h->met(hits);
}

TEST(HitCondition, DapForms) {
    EXPECT_EQ(hit_condition_met("3", 3), true);
    EXPECT_EQ(hit_condition_met("3", 4), false);
    EXPECT_EQ(hit_condition_met("==3", 3), true);
    EXPECT_EQ(hit_condition_met(">= 3", 2), false);
    EXPECT_EQ(hit_condition_met(">=3", 3), true);
    EXPECT_EQ(hit_condition_met(">3", 3), false);
    EXPECT_EQ(hit_condition_met("<3", 2), true);
    EXPECT_EQ(hit_condition_met("<=3", 4), false);
    EXPECT_EQ(hit_condition_met("%4", 8), true);
    EXPECT_EQ(hit_condition_met("%4", 6), false);
    EXPECT_EQ(hit_condition_met("%0", 6), false);
    EXPECT_FALSE(hit_condition_met("x", 1));
    EXPECT_FALSE(hit_condition_met(">=", 1));
}

TEST(DataId, RoundTripAndRefusals) {
    EXPECT_EQ(data_id(0x1B32, 2), "1B32H:2");
    const auto p = parse_data_id("1B32H:2");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->first, 0x1B32);
    EXPECT_EQ(p->second, 2);
    EXPECT_FALSE(parse_data_id("1B32:2"));
    EXPECT_FALSE(parse_data_id("1B32H:0"));
    EXPECT_FALSE(parse_data_id("1B32H:999"));
    EXPECT_FALSE(parse_data_id("ZZZZH:1"));
    EXPECT_FALSE(parse_data_id(""));
}

}  // namespace
}  // namespace alp85::dap
