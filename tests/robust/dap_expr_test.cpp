// The DAP adapter given the expressions that crashed the evaluator (issue 23, item 1): each gets
// an error response or an unverified breakpoint with a message, and the session goes on (the
// next request is answered). adapter.h: nothing a client sends can end the session.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emu/dap/adapter.h"
#include "emu/program/firmware.h"

namespace alp85::dap {
namespace {

class Hostile : public ::testing::Test {
protected:
    std::vector<Json> sent;
    Adapter a{[this](const Json& m) { sent.push_back(m); }};
    int seq = 0;

    // The response to one request.
    Json request(const std::string& command, Json args = Json::object()) {
        const int s = ++seq;
        sent.clear();
        a.receive(Json{{"seq", s}, {"type", "request"}, {"command", command}, {"arguments", std::move(args)}}.dump());
        for (const Json& m : sent)
            if (m.value("type", "") == "response" && m.value("request_seq", 0) == s) return m;
        ADD_FAILURE() << "no response to " << command;
        return Json::object();
    }
    void SetUp() override {
        if (!firmware::have_monitor() || !firmware::find("thesis-fixed")) GTEST_SKIP() << "built without the firmware";
        ASSERT_TRUE(request("initialize", {{"adapterID", "alp85"}})["success"].get<bool>());
        ASSERT_TRUE(request("launch", {{"firmware", "thesis-fixed"}, {"stopOnEntry", true}, {"realTime", false}})["success"].get<bool>());
        ASSERT_TRUE(request("configurationDone")["success"].get<bool>());
    }
    void still_alive() {
        const Json r = request("evaluate", {{"expression", "6*7"}, {"context", "watch"}});
        ASSERT_TRUE(r.value("success", false)) << r.dump();
        EXPECT_NE(r["body"]["result"].get<std::string>().find("(42)"), std::string::npos) << r.dump();
    }
};

std::string nested(int n) { return std::string(static_cast<std::size_t>(n), '(') + "1" + std::string(static_cast<std::size_t>(n), ')'); }
std::string chain(int n) {
    std::string s = "1";
    for (int i = 1; i < n; ++i) s += "+1";
    return s;
}

TEST_F(Hostile, EvaluateAnswersWithAnErrorAndTheSessionGoesOn) {
    for (const char* context : {"watch", "hover", "repl"}) {
        for (const std::string& text : {nested(3000), chain(200000), std::string("1/0")}) {
            const Json r = request("evaluate", {{"expression", text}, {"context", context}});
            EXPECT_FALSE(r.value("success", true)) << context << ": " << text.substr(0, 20);
            EXPECT_FALSE(r.value("message", "").empty());
        }
        // No trap: the wrapped value, then the session still answers.
        const Json r = request("evaluate", {{"expression", "(1<<63)/-1"}, {"context", context}});
        EXPECT_TRUE(r.value("success", false)) << context << ": " << r.dump();
        still_alive();
    }
}

TEST_F(Hostile, AConditionThatCannotBeParsedLeavesTheBreakpointUnverified) {
    for (const std::string& text : {nested(3000), chain(200000)}) {
        const Json r = request("setFunctionBreakpoints", {{"breakpoints", Json::array({{{"name", "OUT"}, {"condition", text}}})}});
        ASSERT_TRUE(r.value("success", false)) << r.dump().substr(0, 200);
        const Json& bp = r["body"]["breakpoints"][0];
        EXPECT_FALSE(bp.value("verified", true));
        EXPECT_NE(bp.value("message", "").find("condition"), std::string::npos) << bp.dump().substr(0, 200);
    }
    still_alive();
}

TEST_F(Hostile, AConditionThatTrapsAtRunTimeStopsWithAMessage) {
    // (1<<63)/-1 and %-1 in a condition: evaluated when the key poll is reached, no trap.
    const Json r = request("setFunctionBreakpoints",
                           {{"breakpoints", Json::array({{{"name", "ANWEIN"}, {"condition", "(1<<63)/-1 + (1<<63)%-1 == (1<<63)"}}})}});
    ASSERT_TRUE(r.value("success", false)) << r.dump();
    EXPECT_TRUE(r["body"]["breakpoints"][0].value("verified", false)) << r.dump();
    const Json c = request("continue", {{"threadId", 1}});
    EXPECT_TRUE(c.value("success", false)) << c.dump();
    for (int i = 0; i < 2000 && a.running(); ++i) (void)a.advance();
    EXPECT_FALSE(a.running()) << "the condition is true at ANWEIN (the key poll): the run stops there";
    request("pause", {{"threadId", 1}});
    still_alive();
}

}  // namespace
}  // namespace alp85::dap
