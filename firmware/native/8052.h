/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_NATIVE_8052_H
#define TACTUS_FW_NATIVE_8052_H
/* The 8052's port pins as variables, for the executor (exec.c) compiled on a
 * PC: board.h includes <8052.h>, and this directory comes first on the
 * native build's include path. The harness that runs the firmware's C in
 * virtual time (tests/firmware/native_firmware.cpp) defines them, reads the
 * outputs and sets the sensors. SDCC's bit type is a byte here. */
#include <stdint.h>

#ifndef __SDCC
#define __bit uint8_t
#endif

#ifdef __cplusplus
extern "C" {
#endif
extern volatile uint8_t P1_0, P1_1, P1_2, P1_3, P1_4, P1_5, P1_6, P1_7;
extern volatile uint8_t P3_2, P3_3, P3_4, P3_5, P3_6, P3_7;
/* Port 2 is written whole and bit by bit (the parallel port's status lines,
 * lpt.c): one byte here too, its bits as bit-fields (bit 0 first). */
union native_port {
    uint8_t byte;
    struct {
        uint8_t b0 : 1, b1 : 1, b2 : 1, b3 : 1, b4 : 1, b5 : 1, b6 : 1, b7 : 1;
    } bit;
};
extern volatile union native_port native_p2;
extern volatile uint8_t P0; /* the parallel port's data lines */
#define P2 native_p2.byte
#define P2_0 native_p2.bit.b0
#define P2_1 native_p2.bit.b1
#define P2_2 native_p2.bit.b2
#define P2_3 native_p2.bit.b3
#define P2_4 native_p2.bit.b4
#define P2_5 native_p2.bit.b5
#ifdef __cplusplus
}
#endif

#endif
