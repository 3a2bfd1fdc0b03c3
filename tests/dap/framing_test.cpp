// The DAP base protocol's framing, base64 and the breakpoint options, from their definitions
// (the DAP specification's "Base Protocol"; RFC 4648's test vectors).
#include <gtest/gtest.h>

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
    r.feed("Content-Length: 1x\r\n\r\n");
    auto f = r.next();
    ASSERT_TRUE(f);
    EXPECT_NE(f->error.find("not a number"), std::string::npos);
    r.feed("X: y\r\n\r\n");
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_NE(f->error.find("without Content-Length"), std::string::npos);
    r.feed(frame("{}"));
    f = r.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->body, "{}");
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
    EXPECT_TRUE(r.empty());
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
