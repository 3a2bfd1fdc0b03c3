/* CRC-32 as zlib's crc32() computes it (see zlib.h here): bit by bit through a 256-entry table. */
#include "zlib.h"

static unsigned long table[256];
static int ready = 0;

static void make_table(void) {
    for (unsigned long n = 0; n < 256; ++n) {
        unsigned long c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320UL ^ (c >> 1) : c >> 1;
        table[n] = c;
    }
    ready = 1;
}

uLong crc32(uLong crc, const Bytef* buf, uInt len) {
    if (buf == Z_NULL) return 0;
    if (!ready) make_table();
    crc = ~crc & 0xFFFFFFFFUL;
    while (len--) crc = table[(crc ^ *buf++) & 0xFF] ^ (crc >> 8);
    return ~crc & 0xFFFFFFFFUL;
}
