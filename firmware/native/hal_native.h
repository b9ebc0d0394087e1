/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_HAL_NATIVE_H
#define TACTUS_FW_HAL_NATIVE_H
/* The platform under the link code when it runs on the host (unit tests,
 * fuzzing): replies go to a buffer, sensors are variables. */
#include <stddef.h>
#include <stdint.h>

extern uint8_t native_tx[4096];
extern size_t native_tx_len;
extern uint8_t native_paper;
extern unsigned native_aborts;
/* Sends every reply that is due into native_tx. */
void native_drain(void);

#endif
