/* The one zlib function the board uses (crc32, for snapshot files: emu/board/snapshot_file.cpp),
 * for the web build: Debian's emscripten has no zlib and its port would be a download. The same
 * CRC-32 (ISO-HDLC: reflected polynomial EDB88320H, initial and final XOR FFFFFFFFH) as zlib's,
 * so a snapshot saved by the page opens in alp85 and back (tests/web checks one both ways). */
#ifndef ALP85_WEB_ZLIB_H
#define ALP85_WEB_ZLIB_H
#ifdef __cplusplus
extern "C" {
#endif
typedef unsigned long uLong;
typedef unsigned int uInt;
typedef unsigned char Bytef;
#define Z_NULL 0
uLong crc32(uLong crc, const Bytef* buf, uInt len);
#ifdef __cplusplus
}
#endif
#endif
