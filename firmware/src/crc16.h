/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_CRC16_H
#define TACTUS_FW_CRC16_H
#include "fw.h"

/* Entry i of a nibble table of 16-bit words, indexed through its bytes:
 * SDCC indexes a uint16_t array with MUL AB, and the image must have no MUL
 * or DIV (step.asm: they lengthen the step interrupt's latency). */
#define NIB(t, i) (*(FW_CODE uint16_t *)((FW_CODE uint8_t *)(t) + (uint8_t)((uint8_t)(i) << 1)))

/* CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF), the frame check of
 * docs/protocol.md: byte-wise in assembly on the chip, a 16-entry nibble
 * table on the host (crc16.c). crc16_block is for host builds only. */
uint16_t crc16_update(uint16_t crc, uint8_t b);
uint16_t crc16_block(const FW_IDATA uint8_t *p, uint8_t n, uint16_t crc);

#endif
