/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_MOTION_H
#define TACTUS_FW_MOTION_H
#include "fw.h"

/* Moves and timed waits on timer 2 (step.asm runs them). One at a time: the
 * feed and the carriage never move together on this firmware. */

/* Pins (firmware/README.md, "Pin map"). */
#define PIN_CSTEP 0x01 /* P1.0 */
#define PIN_FSTEP 0x04 /* P1.2 */
#define PIN_CVX 0x10   /* P1.4 */
#define PIN_CCV 0x20   /* P1.5 */

extern volatile __bit mv_done, mv_limit;

void motion_init(void);
/* A carriage table move of n steps (n >= 1) in the direction already set. */
#define move_carriage(n) move_table(0, (n))
/* A feed table move of n steps. */
#define move_feed(n) move_table(1, (n))
/* Both, without a call level between (README, "Stack"). */
void move_table(uint8_t feed, uint16_t n);
/* n steps at the homing interval (CONFIGURE) on the pin mask (seek). */
void move_constant(uint8_t pin, uint16_t n);
/* Toward the limit switch at the homing interval, at most n steps. */
void move_home(uint16_t n);
/* Timed from the last event of the phase before (to the cycle, when the main
 * loop gets here in time): the hammers on `pins` (0: none, a skipped strike)
 * come down CONFIGURE's settle later; both go up its hammer pulse later. A
 * move's first step comes START_GAP + T[0] after that event (ramp.h). */
void hammer_down_after_settle(uint8_t pins);
void hammer_up_after_pulse(void);
void motion_stop(void);

#endif
