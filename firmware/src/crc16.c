/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "crc16.h"

#if FW_TARGET
/* On the chip: the byte-wise form of poly 0x1021 (no table), with
 * x = (crc >> 8) ^ b, x ^= x >> 4:
 *   crc' = (crc << 8) ^ (x << 12) ^ (x << 5) ^ x
 * 22 machine cycles a byte with the call, against about 120 for the nibble
 * table in C: the main loop folds every received byte through it, and at the
 * top step rate it has about 320 of its own cycles a byte at 9600 baud
 * (firmware/README.md, "Main loop"). The native build below keeps the
 * textbook form the unit tests compare it with. */
uint16_t crc16_update(uint16_t crc, uint8_t b) __naked {
    (void)crc;
    (void)b;
    __asm
        mov   a, dph
        xrl   a, _crc16_update_PARM_2
        mov   r7, a
        swap  a
        anl   a, #0x0f
        xrl   a, r7
        mov   r7, a          ; x
        swap  a
        rl    a
        mov   r6, a          ; x rotated left by 5
        anl   a, #0xe0
        xrl   a, r7
        mov   r5, a          ; low byte: (x << 5) ^ x
        mov   a, r6
        anl   a, #0x1f       ; x >> 3
        xrl   a, dpl
        mov   r6, a
        mov   a, r7
        swap  a
        anl   a, #0xf0       ; x << 4
        xrl   a, r6
        mov   dph, a         ; high byte: low ^ (x << 4) ^ (x >> 3)
        mov   dpl, r5
        ret
    __endasm;
}
#else
static FW_CODE uint16_t crc_nib[16] = {
    0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50A5, 0x60C6, 0x70E7,
    0x8108, 0x9129, 0xA14A, 0xB16B, 0xC18C, 0xD1AD, 0xE1CE, 0xF1EF
};

uint16_t crc16_update(uint16_t crc, uint8_t b) {
    crc = (uint16_t)((uint16_t)(crc << 4) ^ NIB(crc_nib, (crc >> 12) ^ (b >> 4)));
    crc = (uint16_t)((uint16_t)(crc << 4) ^ NIB(crc_nib, (crc >> 12) ^ (b & 0x0F)));
    return crc;
}

/* Host builds only (unit tests): the chip folds byte by byte (decoder.c). */
uint16_t crc16_block(const FW_IDATA uint8_t *p, uint8_t n, uint16_t crc) {
    while (n--) crc = crc16_update(crc, *p++);
    return crc;
}
#endif
