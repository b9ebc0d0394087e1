/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_LPT_H
#define TACTUS_FW_LPT_H
#include "fw.h"

/* The parallel port's reverse channel and status lines (firmware/README.md,
 * "Parallel port"). Bytes in come through the strobe interrupt (uart.c) in
 * compatibility mode; this module shows the controller's condition on
 * PError, nFault and Select, and answers IEEE 1284 nibble-mode negotiation to
 * send the reply frames back four bits at a time. The state machine is the
 * C++ model's (core/controller/lpt_peripheral.cpp), one pass per call. */

/* Compatibility mode: bytes in on the strobe, the condition shown. */
#define LM_COMPAT 0
#define LM_NEGOTIATING 1
#define LM_IDLE 2
#define LM_LOW_SHOWN 3
#define LM_LOW_DONE 4
#define LM_HIGH_SHOWN 5
#define LM_TERM_ACK 6
#define LM_TERM_DONE 7
extern uint8_t lpt_mode;
/* Set by the strobe interrupt when nStrobe falls while 1284 is active (the
 * negotiation's event 3: not a data byte). */
extern volatile FW_BIT lpt_strobe;
/* Replies go back over the parallel port: the last byte came from it (set by
 * the strobe interrupt, cleared by a byte on the UART). */
extern volatile FW_BIT fw_via_lpt;

void lpt_init(void);
/* One pass of the port poll (main loop): reacts to the host's lines. */
void lpt_poll(void);

#endif
