// alp85_assemble(... BIN ... EMBED_SYMBOL ...) assembled data/embed.asm at build time.
#include <gtest/gtest.h>

#include "asm_embed_demo_embed.h"

namespace {

TEST(Embed, BuildTimeAssemblyIsLinkedIn) {
    // ORG 0E800H: JMP BODY (C3 05 E8), DS 2 (filled by --fill 0), MVI C,9 (0E 09), RET (C9).
    const std::uint8_t expected[] = {0xC3, 0x05, 0xE8, 0x00, 0x00, 0x0E, 0x09, 0xC9};
    ASSERT_EQ(alp85::test::demo_size, sizeof expected);
    for (std::size_t i = 0; i < sizeof expected; ++i) EXPECT_EQ(alp85::test::demo[i], expected[i]) << i;
    EXPECT_EQ(alp85::test::demo_origin, 0xE800);
}

}  // namespace
