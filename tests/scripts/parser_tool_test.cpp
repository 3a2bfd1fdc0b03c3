// The machine tool's commands and the other commands added with it (docs/scripting.md, "The
// machine tool"): their shapes, defaults and errors with columns.
#include <gtest/gtest.h>

#include "emu/script/parser.h"
#include "tests/scripts/parse_helpers.h"

namespace alp85::script {
namespace {

using test::error_of;
using test::one;

TEST(ScriptTool, MotorAndFeedback) {
    EXPECT_EQ(one("motor ideal").op, Op::Motor);
    EXPECT_EQ(one("motor ideal").real, 0);
    EXPECT_EQ(one("MOTOR Physical").real, 1);
    EXPECT_EQ(one("feedback commanded").op, Op::Feedback);
    EXPECT_EQ(one("feedback commanded").real, 1);
    EXPECT_EQ(one("feedback scale").real, 0);
    const ParseError e = error_of("motor fast");
    EXPECT_EQ(e.where.col, 7);
    EXPECT_EQ(e.message, "unknown motor model 'fast' (ideal or physical)");
    EXPECT_EQ(error_of("feedback").message, "expected a feedback (scale or commanded)");
}

TEST(ScriptTool, NewWorkpiece) {
    EXPECT_EQ(one("new workpiece").op, Op::NewWorkpiece);
    EXPECT_EQ(one("NEW Workpiece").op, Op::NewWorkpiece);
    const ParseError e = error_of("new table");
    EXPECT_EQ(e.where.col, 5);
    EXPECT_EQ(e.message, "unknown 'table' after new (new workpiece)");
    EXPECT_EQ(error_of("new").message, "expected 'workpiece' (new workpiece)");
    EXPECT_EQ(error_of("new workpiece now").message, "unexpected 'now'");
}

TEST(ScriptTool, ExpectAxisInStepsAndMm) {
    const Command s = one("expect axis y steps -120");
    EXPECT_EQ(s.op, Op::ExpectAxis);
    EXPECT_EQ(s.axis, 1);
    EXPECT_FALSE(s.in_mm);
    EXPECT_EQ(s.compare, Compare::Eq);
    EXPECT_EQ(s.integer, -120);
    const Command ge = one("expect axis Z steps >= 0CH");
    EXPECT_EQ(ge.axis, 2);
    EXPECT_EQ(ge.compare, Compare::Ge);
    EXPECT_EQ(ge.integer, 12);
    const Command mm = one("expect axis X mm 10.25 within 0.01");
    EXPECT_TRUE(mm.in_mm);
    EXPECT_DOUBLE_EQ(mm.real, 10.25);
    EXPECT_DOUBLE_EQ(mm.within, 0.01);
    EXPECT_DOUBLE_EQ(one("expect axis X mm < 3").within, 0.0005);  // the default tolerance
    EXPECT_EQ(one("expect axis X mm < 3").compare, Compare::Lt);
    EXPECT_EQ(error_of("expect axis W steps 1").message, "unknown axis 'W' (X, Y or Z)");
    EXPECT_EQ(error_of("expect axis X mm ten").where.col, 18);
    EXPECT_EQ(error_of("expect axis X inches 1").where.col, 15);
}

TEST(ScriptTool, CountLostAndRunUntilAxis) {
    const Command c = one("expect count X > 5");
    EXPECT_EQ(c.op, Op::ExpectCount);
    EXPECT_EQ(c.compare, Compare::Gt);
    EXPECT_EQ(c.integer, 5);
    EXPECT_EQ(one("expect lost Y -20").integer, -20);
    EXPECT_EQ(one("expect lost Y -20").op, Op::ExpectLost);
    const Command r = one("run until axis X steps >= 200 timeout 2s");
    EXPECT_EQ(r.op, Op::RunUntilAxis);
    EXPECT_EQ(r.compare, Compare::Ge);
    EXPECT_EQ(r.integer, 200);
    EXPECT_EQ(r.time, 2u * 3'072'000);
    EXPECT_EQ(one("run until axis Z steps 3").time, kDefaultUntil);
    EXPECT_EQ(one("run until axis Z steps 3").op, Op::RunUntilAxis);
    EXPECT_EQ(one("run until 0800H").op, Op::RunUntil);  // an address is still an address
}

TEST(ScriptTool, RecordAndPlot) {
    const Command r = one("record out.csv every 2ms");
    EXPECT_EQ(r.op, Op::Record);
    EXPECT_EQ(r.text, "out.csv");
    EXPECT_EQ(r.period, 6144u);
    EXPECT_EQ(one("record out.csv").period, kDefaultRecordPeriod);
    EXPECT_EQ(one("record stop").op, Op::RecordStop);
    const Command p = one("plot toolpath path.svg from 0,0 to 10,7.5");
    EXPECT_EQ(p.op, Op::Plot);
    EXPECT_EQ(p.name, "TOOLPATH");
    ASSERT_TRUE(p.ideal_line);
    EXPECT_DOUBLE_EQ((*p.ideal_line)[3], 7.5);
    EXPECT_FALSE(one("plot time t.png").ideal_line);
    EXPECT_EQ(error_of("plot toolpath path.pdf").message, "a plot is written as .svg or .png");
    EXPECT_EQ(error_of("plot toolpath p.svg from 0;0 to 1,1").message, "expected a point X,Y in mm, found '0;0'");
    EXPECT_EQ(error_of("record x.csv every 0t").message, "a sampling period is not zero");
}

// record signals FILE.vcd [PIN...] [every T] (docs/signals.md): the pins as written, with their
// columns for the session's check; "signals" quoted is a CSV file of that name.
TEST(ScriptTool, RecordSignals) {
    const Command r = one("record signals pins.vcd PA0 x.pulse 8279 every 48t");
    EXPECT_EQ(r.op, Op::Record);
    EXPECT_TRUE(r.signals);
    EXPECT_EQ(r.text, "pins.vcd");
    ASSERT_EQ(r.pins.size(), 3u);
    EXPECT_EQ(r.pins[1].text, "x.pulse");
    EXPECT_EQ(r.pins[1].col, 29);  // "record signals pins.vcd PA0 " is 28 characters
    EXPECT_EQ(r.period, 48u);
    EXPECT_EQ(one("record signals pins.vcd").period, kDefaultSignalPeriod);
    EXPECT_TRUE(one("record signals pins.vcd").pins.empty());
    EXPECT_FALSE(one("record \"signals\"").signals);
    EXPECT_EQ(error_of("record signals").message, "expected a VCD file name");
    EXPECT_EQ(error_of("record signals p.vcd \"PA0\"").message, "a pin name is a word, not a string: PA0");
}

TEST(ScriptTool, PrintAxesTimeMarkAndFirmware) {
    EXPECT_EQ(one("print axes").op, Op::PrintAxes);
    EXPECT_EQ(one("print time").op, Op::PrintTime);
    EXPECT_EQ(one("print hello").op, Op::Print);
    EXPECT_EQ(one("mark").op, Op::Mark);
    const Command f = one("firmware thesis-fixed");
    EXPECT_EQ(f.op, Op::Firmware);
    EXPECT_EQ(f.text, "thesis-fixed");
}

}  // namespace
}  // namespace alp85::script
