// Tests that run on both variants, with the data-sheet T-states of each.
#pragma once

#include <gtest/gtest.h>

#include "tests/cpu/rig.h"

namespace alp85::test {

class Both : public ::testing::TestWithParam<Variant> {
protected:
    Rig rig{GetParam()};
    // T-states: 8085 figure, 8080 figure.
    std::uint64_t T(std::uint64_t t85, std::uint64_t t80) const { return rig.is8080() ? t80 : t85; }
    std::uint8_t F(std::uint8_t f85) const { return rig.flags(f85); }
    // Flags that differ between the variants beyond bit 1: give both.
    std::uint8_t F(std::uint8_t f85, std::uint8_t f80) const { return rig.is8080() ? f80 : f85; }
};

inline std::string variant_name(const ::testing::TestParamInfo<Variant>& info) {
    return info.param == Variant::I8085 ? "i8085" : "i8080";
}

}  // namespace alp85::test
