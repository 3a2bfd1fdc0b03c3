// A register added to the CPU's description in one line shows up in every front end that shows
// registers, with no front-end code of its own: this binary links tests/debug/toy_register.cpp (the
// 8085's description plus the toy SPH, the stack pointer's high byte) in place of the library's,
// and drives the unchanged console, expression evaluator, script commands, DAP view and the GUI's
// Registers pane. The screenshot test gui:toy-register-pane shows the pane drawn.
#include <gtest/gtest.h>

#include <algorithm>

#include "emu/core/cpu_registers.h"
#include "emu/dap/machine_view.h"
#include "emu/gui/debug_panes.h"
#include "emu/script/debug_shell.h"
#include "emu/script/parser.h"

namespace alp85::test {
namespace {

constexpr auto npos = std::string::npos;

class ToyRegister : public ::testing::Test {
protected:
    script::DebugShell shell{script::SessionOptions{}};
    Registers& regs() { return shell.session().machine().cpu().regs(); }
    // Runs a line that must not fail; returns its text.
    std::string run(const std::string& line) {
        const int before = shell.console().errors();
        std::string out = shell.execute(line);
        EXPECT_EQ(shell.console().errors(), before) << line << "\n" << out;
        return out;
    }
    void SetUp() override {
        ASSERT_NE(cpu::description().find("SPH"), nullptr) << "not linked with the toy description";
        regs().sp = 0x20AE;  // SPH = 20H
        regs().pc = 0x0800;
    }
};

TEST_F(ToyRegister, InfoRegistersListsItBesideSpAndPc) {
    const std::string info = run("info registers");
    EXPECT_NE(info.find("SP 20AEH   PC 0800H   SPH 20H\n"), npos) << info;
    EXPECT_NE(info.find("A  00H   F  00H   S=0 Z=0 AC=0 P=0 CY=0  V=0 K=0\n"), npos) << info;  // the rest as ever
}

TEST_F(ToyRegister, TheExpressionEvaluatorReadsAndSetsIt) {
    EXPECT_EQ(run("print/x SPH"), "$1 = 20H\n");
    EXPECT_EQ(run("print $SPH + 1"), "$2 = 21H (33)\n");  // 20H + 1
    const debug::Debugger::Value v = shell.debugger().evaluate("sph");
    EXPECT_EQ(v.value, 0x20);
    EXPECT_EQ(v.width, 8);  // a byte register
    run("set SPH = 12H");
    EXPECT_EQ(regs().sp, 0x12AE);  // the high byte replaced, the low kept
    run("set SPH = 1234H");        // a register keeps its width's low bits: 34H
    EXPECT_EQ(regs().sp, 0x34AE);
}

TEST_F(ToyRegister, TheScriptExpectsAndSetsIt) {
    run("expect reg SPH 20H");
    run("set reg sph 12H");
    EXPECT_EQ(regs().sp, 0x12AE);
    const int before = shell.console().errors();
    const std::string out = shell.execute("expect reg SPH 13H");
    EXPECT_GT(shell.console().errors(), before) << out;
    EXPECT_NE(out.find("SPH = 13H"), npos) << out;
    // A script is checked before it runs: 100H does not fit the toy's 8 bits, 0FFH does.
    std::vector<script::ParseError> errors;
    const auto commands = script::parse_script("set reg SPH 100H\nset reg SPH 0FFH\n", "toy.alp", errors);
    ASSERT_TRUE(errors.empty());
    shell.session().check(commands, errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].where.line, 1);
    EXPECT_NE(errors[0].message.find("value"), npos) << errors[0].message;
}

TEST_F(ToyRegister, DapListsItWithTheBytesAndSetsIt) {
    const auto vars = dap::list_variables(shell.debugger(), dap::kRegisterScope);
    std::vector<std::string> names;
    for (const dap::Variable& x : vars) names.push_back(x.name);
    // The byte registers in the description's order (the toy last among them), F, then the
    // registers holding an address.
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "C", "D", "E", "H", "L", "SPH", "F", "BC", "DE", "HL", "SP", "PC",
                                               "interrupts"}));
    const auto sph = std::find_if(vars.begin(), vars.end(), [](const dap::Variable& x) { return x.name == "SPH"; });
    ASSERT_NE(sph, vars.end());
    EXPECT_EQ(sph->value, "20H");
    EXPECT_EQ(sph->type, "byte");
    EXPECT_FALSE(sph->read_only);
    EXPECT_EQ(dap::assign_variable(shell.debugger(), dap::kRegisterScope, "SPH", 0x12), "");
    EXPECT_EQ(regs().sp, 0x12AE);
    EXPECT_EQ(dap::assign_variable(shell.debugger(), dap::kRegisterScope, "SPH", 0x100), "256 does not fit in 8 bits");
    std::string error;
    EXPECT_EQ(dap::expression_value(shell.debugger(), "SPH", error), "12H (18)") << error;  // the debug console, hovers
}

TEST_F(ToyRegister, TheGuiRegistersPaneHasARowForIt) {
    regs().h = 0x1B;
    regs().l = 0x30;
    const std::string text = gui::registers_text(shell.debugger());
    // The pairs' bytes on the left; SP, PC, the toy, [HL] and HALTED (blank: running) on the right,
    // one a row: the toy takes [HL]'s row and [HL] HALTED's, which gets a row of its own.
    EXPECT_NE(text.find("D 00H  E 00H   SPH 20H\nH 1BH  L 30H   [HL] "), npos) << text;
    EXPECT_NE(text.find("\n               \nS=0 Z=0 AC=0 P=0 CY=0 V=0 K=0\n"), npos) << text;
}

}  // namespace
}  // namespace alp85::test
