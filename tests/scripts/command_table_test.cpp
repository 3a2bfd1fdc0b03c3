// One command language: the debugger's prompt lists the console's commands and the script's in
// one table, its help and completion come from that table, and the docs' command tables list
// exactly its commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "emu/script/debug_shell.h"
#include "emu/script/parser.h"
#include "emu/script/session.h"

namespace alp85::script {
namespace {

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The command words a docs table's first column names: the first word in backquotes of each item
// (items apart by ", " or " / "; what stands in parentheses are examples, not commands).
std::set<std::string> documented(const std::string& doc, const std::string& section_start, const std::string& section_end) {
    const auto from = doc.find(section_start);
    const auto to = doc.find(section_end, from + section_start.size());
    std::set<std::string> out;
    std::istringstream lines(doc.substr(from, to - from));
    const std::regex item(R"((^|, | / )`([a-z][a-z-]*)[` ])");
    for (std::string l; std::getline(lines, l);) {
        if (!l.starts_with("| `")) continue;
        std::string cell = l.substr(2, l.find(" | ", 2) - 2);
        cell = std::regex_replace(cell, std::regex(R"(\([^)]*\))"), "");
        for (std::sregex_iterator m(cell.begin(), cell.end(), item), end; m != end; ++m) out.insert((*m)[2]);
    }
    return out;
}

class CommandTable : public ::testing::Test {
protected:
    CommandTable() : shell(SessionOptions{ALP85_BOARD_PROGRAMS, Variant::I8085, {}, nullptr, false}) {}
    DebugShell shell;
};

TEST_F(CommandTable, HoldsTheConsolesCommandsAndEveryScriptCommand) {
    const auto& table = shell.console().commands();
    auto has = [&](std::string_view name, bool own) {
        return std::any_of(table.begin(), table.end(), [&](const auto& c) { return c.name == name && (c.handler != nullptr) == own; });
    };
    for (const CommandInfo& c : commands()) EXPECT_TRUE(has(c.name, false)) << c.name;
    for (const char* own : {"break", "continue", "print", "info", "reverse-step", "timing", "quit"}) EXPECT_TRUE(has(own, true)) << own;
    // 26 script commands (load ... plot, and board), as docs/scripting.md's two tables list them.
    EXPECT_EQ(commands().size(), 26u);
}

TEST_F(CommandTable, HelpListsEveryCommandWithItsOwnText) {
    const std::string h = shell.execute("help");
    for (const auto& c : shell.console().commands()) {
        EXPECT_NE(h.find("\n  " + std::string(c.name)), std::string::npos) << c.name;
        const std::string one = shell.execute("help " + std::string(c.name));
        EXPECT_NE(one.find(std::string(c.help)), std::string::npos) << c.name << ": " << one;
        EXPECT_EQ(std::count(one.begin(), one.end(), '\n'), 1) << c.name << ": " << one;  // one text, one line
    }
    // help for a script command that shares no name with the debugger's: its own text.
    EXPECT_EQ(shell.execute("help keydown"), "keydown KEY: a key down now, without running\n");
    // A name both have: the debugger's text, then the script's, as one text (so that `help`, which
    // wraps each command's text, holds `help COMMAND` whole: Gdb.HelpShowsEveryCommandsWholeText).
    const std::string print = shell.execute("help p");
    EXPECT_TRUE(print.starts_with("print[/x|d|t|c] EXPR:")) << print;
    EXPECT_NE(print.find("; as in scripts: print display [text] | print axes"), std::string::npos) << print;
    std::istringstream lines(h);
    for (std::string l; std::getline(lines, l);) EXPECT_LE(l.size(), 100u) << l;
}

TEST_F(CommandTable, CompletionOffersTheScriptsCommandsFromTheTable) {
    // "ne": the debugger's next and nexti, the script's new (new workpiece).
    EXPECT_EQ(shell.console().complete("ne", true), (std::vector<std::string>{"new", "next", "nexti"}));
    const auto fi = shell.console().complete("fi", true);
    EXPECT_NE(std::find(fi.begin(), fi.end(), "firmware"), fi.end());
    EXPECT_NE(std::find(fi.begin(), fi.end(), "finish"), fi.end());
}

TEST_F(CommandTable, DocsListExactlyTheTablesCommands) {
    const std::string dir = ALP85_DOCS;
    const std::set<std::string> debugging = documented(read(dir + "/debugging.md"), "\n## Commands\n", "\n## ");
    const std::set<std::string> scripting = documented(read(dir + "/scripting.md"), "\n## Commands\n", "\n## Example");
    ASSERT_FALSE(debugging.empty());
    ASSERT_FALSE(scripting.empty());
    std::set<std::string> own, script;
    for (const auto& c : shell.console().commands()) (c.handler ? own : script).insert(std::string(c.name));
    for (const std::string& n : own) EXPECT_TRUE(debugging.count(n)) << n << " is missing from docs/debugging.md's Commands";
    for (const std::string& n : script) EXPECT_TRUE(scripting.count(n)) << n << " is missing from docs/scripting.md's Commands";
    for (const std::string& n : debugging) EXPECT_TRUE(own.count(n) || script.count(n)) << "docs/debugging.md lists '" << n << "', no command";
    for (const std::string& n : scripting) EXPECT_TRUE(script.count(n)) << "docs/scripting.md lists '" << n << "', no command";
}

}  // namespace
}  // namespace alp85::script
