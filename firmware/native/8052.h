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
extern volatile uint8_t P2_0, P2_1, P2_2;
extern volatile uint8_t P3_3, P3_4, P3_5, P3_6, P3_7;
#ifdef __cplusplus
}
#endif

#endif
