// pisa-asm's diagnostics, listing and map (asm85's formats), and the tape format's checks.
#include <gtest/gtest.h>

#include "asm/pisa_asm.h"
#include "emu/pisa/interpolator.h"
#include "emu/pisa/tape.h"

#include <random>

namespace alp85::pisa {
namespace {

std::string first_error(std::string_view src) {
    auto r = pisa_asm::assemble_string(src, {}, "t.pasm");
    for (auto& d : r.out.diagnostics)
        if (d.severity == asm85::Severity::Error) return asm85::format_diagnostic(d);
    return "";
}

TEST(PisaAsm, DiagnosticsWithLineAndColumn) {
    EXPECT_EQ(first_error("  ADD 1,2,64\n"),
              "t.pasm:1:11: error: RWM address 64 is outside 0..63\n  ADD 1,2,64\n          ^\n");
    EXPECT_EQ(first_error("\n  FOO 1\n"), "t.pasm:2:3: error: unknown operation 'FOO'\n  FOO 1\n  ^\n");
    EXPECT_EQ(first_error("  JMP NOWHERE\n"),
              "t.pasm:1:7: error: undefined symbol 'NOWHERE'\n  JMP NOWHERE\n      ^\n");
    EXPECT_EQ(first_error("A: STO 1,1\nA: STO 2,1\n"),
              "t.pasm:2:1: error: 'A' is already defined (line 1)\nA: STO 2,1\n^\n");
    EXPECT_NE(first_error("  STO 1000,1\n").find("1:7: error: constant 1000 is outside 0..999"), std::string::npos);
    EXPECT_NE(first_error("  SHL 1,9,2\n").find("1:9: error: shift 9 is outside 0..8"), std::string::npos);
    EXPECT_NE(first_error("  IN 0,0,2\n").find("1:8: error: digit count 0 is outside 1..8"), std::string::npos);
    EXPECT_NE(first_error("  ADD 1,2\n").find("1:10: error: missing operand"), std::string::npos);
    EXPECT_NE(first_error("  ADD 1,2,3,4\n").find("1:12: error: unexpected ','"), std::string::npos);
    EXPECT_NE(first_error("  ORG 4095\n  STO 1,1\n  STO 1,1\n").find("ROM address 4096"), std::string::npos);
}

TEST(PisaAsm, ForwardReferencesExpressionsAndDefines) {
    pisa_asm::Options o;
    o.defines = {{"BASE", "10"}};
    auto r = pisa_asm::assemble_string("  JMP L\nK EQU BASE+2*3\nL: ADD K,K,K\n", o);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.rom[0], 8u << 18 | 1u);                        // JMP 1
    EXPECT_EQ(r.rom[1], 0u << 18 | 16u << 12 | 16u << 6 | 16u);  // ADD 16,16,16
}

TEST(PisaAsm, ListingAndMapInAsm85sLayoutCountingWords) {
    auto r = pisa_asm::assemble_string("; test\nK EQU 9\n  ORG 2\nL: STO 125,K\n  JMP L\n", {}, "t.pasm");
    ASSERT_TRUE(r.ok());
    std::string lst = asm85::write_listing(r.out, pisa_asm::output_format());
    EXPECT_EQ(lst.rfind("pisa-asm", 0), 0u);
    // STO 125,9: 0111 001001 010001011000 = 1C9458 hex; JMP 2 = 200002.
    EXPECT_NE(lst.find("  0002 1C9458        4     L: STO 125,K"), std::string::npos) << lst;
    EXPECT_NE(lst.find("  0003 200002        5       JMP L"), std::string::npos) << lst;
    EXPECT_NE(lst.find("ASSEMBLY COMPLETE, NO ERRORS"), std::string::npos);
    std::string map = asm85::write_json_map(r.out, pisa_asm::output_format());
    EXPECT_NE(map.find("\"format\": \"alp85-asm-map\""), std::string::npos);
    EXPECT_NE(map.find("\"unit\": \"word22\""), std::string::npos);
    EXPECT_NE(map.find("\"start\": 2,\n   \"length\": 2"), std::string::npos) << map;
    EXPECT_EQ(pisa_asm::write_rom_text(r), "0000 00000000\n0001 00000000\n0002 07112130\n0003 10000002\n");
}

TEST(PisaTape, WordsAsTheReaderDeliversThem) {
    auto p = parse_tape("%\nN010 G01 X+012.5 Y-3000 F600 (comment)\n%\n");
    ASSERT_FALSE(p.error) << p.error->message;
    ASSERT_EQ(p.tape.words.size(), 6u);
    EXPECT_EQ(p.tape.words[0].letter, kN);
    EXPECT_EQ(p.tape.words[0].chars, 4);  // N and 3 digits
    EXPECT_EQ(p.tape.words[2].value, 12500u);
    EXPECT_EQ(p.tape.words[2].chars, 8);  // X, sign, 6 digits
    EXPECT_TRUE(p.tape.words[3].negative);
    EXPECT_EQ(p.tape.words[3].value, 3000u);
    EXPECT_EQ(p.tape.words[4].chars, 5);
    EXPECT_EQ(p.tape.words[5].letter, kEob);
    ASSERT_EQ(p.tape.elements.size(), 1u);
    EXPECT_EQ(p.tape.elements[0].x1, 12500);
    EXPECT_EQ(p.tape.elements[0].y1, -3000);
}

TEST(PisaTape, RefusedWithLineAndColumn) {
    struct Case {
        const char* text;
        int line, col;
        const char* message;
    };
    const Case cases[] = {
        {"G01 X10 F600\nG01 X20 M03\n", 2, 9, "'M' is not a word"},
        {"G01 X10 X20 F600\n", 1, 9, "X given twice"},
        {"G04 X10 F600\n", 1, 1, "G04 is not one of"},
        {"G01 X1000.000 F600\n", 1, 5, "beyond 999.999 mm"},
        {"G01 X1234567 F600\n", 1, 5, "beyond 999999"},
        {"G01 X10\n", 1, 1, "no feedrate"},
        {"X10 F600\n", 1, 1, "no G mode"},
        {"G01 X10 F5\n", 1, 9, "feedrate 5 mm/min is outside"},
        {"G01 X10 F1600\n", 1, 9, "feedrate 1600 mm/min is outside 10-1500"},
        {"G01 X10 F600 I5\n", 1, 14, "I and J belong to arcs"},
        {"G02 X10 Y0 I5000 F600\n", 1, 12, "not on one circle"},
        {"G03 X1 Y100 I5000 F600\n", 1, 13, "near-end window"},
        {"G03 X0 Y0 I500 F600\n", 1, 11, "radius 0.500 mm is below"},
        {"G01 X-800.0 F600\n", 1, 5, "outside the tables' travel"},
        {"G02 X0 Y0 J90000 F600\n", 1, 11, "leaves the tables' travel"},
        {"G01 X+-5 F600\n", 1, 7, "X needs a number"},
        {"G01 X5 F600 (open\n", 1, 13, "comment not closed"},
        {"N+5\n", 1, 2, "N takes no sign"},
        {"\n", 1, 1, "no move"},
    };
    for (const auto& c : cases) {
        auto p = parse_tape(c.text);
        ASSERT_TRUE(p.error) << c.text;
        EXPECT_EQ(p.error->line, c.line) << c.text;
        EXPECT_EQ(p.error->col, c.col) << c.text << p.error->message;
        EXPECT_NE(p.error->message.find(c.message), std::string::npos) << c.text << ": " << p.error->message;
    }
}

// Bad input never crashes (the sanitizer build runs these too): text mutated at random through the
// tape parser and the assembler, and random ROM words through the machine.
TEST(PisaRobustness, MutatedTapesAndSourcesAndRandomRoms) {
    std::mt19937 rng(1969);
    const std::string tape = "%\nN010 G01 X+012.5 Y-3000 F600 (c)\nN020 G03 X0 Y0 I-12.5 J1.5\nN030 G00 X0\n%\n";
    const std::string src = "K EQU 9\nL: ADD 1,2,3\n  STO #L,K\n  SHR 1,2,3\n  TRS L,0\n  IN 0,8,9\n  JMI K\n  END\n";
    const std::string alphabet = "NGXYIJFM+-.0123456789 ()%;,#:\n\tLADSTOEQU@$'\"";
    for (int round = 0; round < 3000; ++round) {
        for (const std::string* base : {&tape, &src}) {
            std::string t = *base;
            int edits = 1 + static_cast<int>(rng() % 6);
            for (int e = 0; e < edits && !t.empty(); ++e) {
                std::size_t at = rng() % t.size();
                char c = alphabet[rng() % alphabet.size()];
                switch (rng() % 3) {
                    case 0: t[at] = c; break;
                    case 1: t.insert(at, 1, c); break;
                    default: t.erase(at, 1);
                }
            }
            if (base == &tape) {
                auto p = parse_tape(t);
                if (p.error) {
                    EXPECT_GE(p.error->line, 1);
                }
            } else {
                auto r = pisa_asm::assemble_string(t);
                for (auto& d : r.out.diagnostics) EXPECT_FALSE(asm85::format_diagnostic(d).empty());
            }
        }
    }
    for (int round = 0; round < 200; ++round) {
        std::vector<std::uint32_t> rom(64 + rng() % 200);
        for (auto& w : rom) w = rng() & kWordMask;
        Interpolator m(rom);
        m.reader().load({{kX, true, 12345, 8, 1}, {kEob, false, 0, 1, 1}});
        auto stop = m.run(200'000);
        EXPECT_TRUE(stop.reason == StopReason::End || stop.reason == StopReason::Fault ||
                    stop.reason == StopReason::StepLimit);
    }
}

}  // namespace
}  // namespace alp85::pisa
