/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "crc16.h"

/* Entry n is the CRC register after shifting nibble n through four rounds of
 * poly 0x1021: 32 bytes of flash. A byte-wise table would be four times
 * faster but costs 512 bytes the 8 KB part cannot spare (firmware/README.md,
 * "Size"). */
static FW_CODE uint16_t crc_nib[16] = {
    0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50A5, 0x60C6, 0x70E7,
    0x8108, 0x9129, 0xA14A, 0xB16B, 0xC18C, 0xD1AD, 0xE1CE, 0xF1EF
};

uint16_t crc16_update(uint16_t crc, uint8_t b) {
    crc = (uint16_t)((uint16_t)(crc << 4) ^ NIB(crc_nib, (crc >> 12) ^ (b >> 4)));
    crc = (uint16_t)((uint16_t)(crc << 4) ^ NIB(crc_nib, (crc >> 12) ^ (b & 0x0F)));
    return crc;
}

uint16_t crc16_block(const FW_IDATA uint8_t *p, uint8_t n, uint16_t crc) {
    while (n--) crc = crc16_update(crc, *p++);
    return crc;
}
