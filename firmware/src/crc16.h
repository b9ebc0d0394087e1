/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_CRC16_H
#define TACTUS_FW_CRC16_H
#include "fw.h"

/* CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF), the frame check of
 * docs/protocol.md, with a 16-entry nibble table. */
uint16_t crc16_update(uint16_t crc, uint8_t b);
uint16_t crc16_block(const FW_IDATA uint8_t *p, uint8_t n, uint16_t crc);

#endif
