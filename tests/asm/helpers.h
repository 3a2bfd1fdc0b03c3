// Shared helpers of the asm85 tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "asm/asm85.h"

namespace alp85::asm85::test {

inline Result assemble(const std::string& src, Cpu cpu = Cpu::i8085) {
    Options o;
    o.cpu = cpu;
    o.warn_unused_macros = false;
    return assemble_string(src, o, "t.asm");
}

// The bytes at [addr, addr+n); unwritten bytes read as -1.
inline std::vector<int> bytes(const Result& r, unsigned addr, unsigned n) {
    std::vector<int> out;
    for (unsigned a = addr; a < addr + n; ++a) {
        auto b = r.image.read(static_cast<std::uint16_t>(a));
        out.push_back(b ? *b : -1);
    }
    return out;
}

// Every byte of the image in address order.
inline std::vector<int> all_bytes(const Result& r) {
    std::vector<int> out;
    for (auto& s : r.image.segments())
        for (auto b : s.bytes) out.push_back(b);
    return out;
}

inline std::string diags(const Result& r) {
    std::string s;
    for (auto& d : r.diagnostics) s += format_diagnostic(d);
    return s;
}

// Assembles, expects no error, returns all bytes.
inline std::vector<int> ok_bytes(const std::string& src, Cpu cpu = Cpu::i8085) {
    auto r = assemble(src, cpu);
    EXPECT_TRUE(r.ok()) << diags(r);
    return all_bytes(r);
}

// The first error diagnostic (or an empty one).
inline Diagnostic first_error(const Result& r) {
    for (auto& d : r.diagnostics)
        if (d.severity == Severity::Error) return d;
    return {};
}

}  // namespace alp85::asm85::test
