/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_EXEC_H
#define TACTUS_FW_EXEC_H
#include "fw.h"

/* The job executor (exec.c on the chip; a stub in the native tests). */

/* Stops motion now (ABORT): the carriage position stays what the steps made it. */
void exec_abort(void);
/* Whether the op at the head of the ring is under way (a pass record's bytes
 * are consumed as its strikes are made). */
uint8_t exec_busy(void);
/* A new session dropped the ring in the middle of a pass: the strike under
 * way ends, then the executor leaves the pass (still active, with its strike
 * count, which the new host skips) and holds still until RESUME. */
void exec_drop_pass(void);
#ifdef FW_EMU
/* A strike was fired (the emulator's reset breakpoint goes on it). */
void fw_strike_fired(void);
#endif

/* The job-stream ops (docs/protocol.md). */
#define OP_JOB_BEGIN 0x10
#define OP_JOB_END 0x11
#define OP_SHEET_BEGIN 0x12
#define OP_SHEET_END 0x13
#define OP_PASS 0x14
#define OP_HOME 0x40
#define OP_SEEK_CARRIAGE 0x42
#define OP_SEEK_FEED 0x43

/* PASS flags. */
#define PF_BACK 0x01       /* the pass embosses the back side (informational) */
#define PF_NO_FEED 0x02    /* restart: the feed was made before the reset */
#define PF_SWEEP_NEG 0x04  /* strikes after the first move toward lower steps */
#define PF_FIRST_NEG 0x08  /* the move to the first strike goes toward lower steps */
#define PF_SKIP 0x10       /* a skip byte follows: strikes already made (restart) */
#define PF_ALL 0x1F

/* Entry byte: hammer, extension, distance in grid units. */
#define E_CONCAVE 0x80
#define E_EXT 0x40
#define E_DIST 0x3F

#endif
