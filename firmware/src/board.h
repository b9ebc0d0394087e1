/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_BOARD_H
#define TACTUS_FW_BOARD_H
/* Pin map of the reference board (firmware/README.md). */
#include <8052.h>

#define CSTEP P1_0    /* carriage STEP (driver steps on the rising edge) */
#define CDIR P1_1     /* carriage DIR: 1 = toward higher steps (away from home) */
#define FSTEP P1_2    /* paper feed STEP */
#define FDIR P1_3     /* paper feed DIR: 1 = feed forward */
#define HAM_CVX P1_4  /* convex hammer solenoid driver, active high */
#define HAM_CCV P1_5  /* concave hammer solenoid driver, active high */
#define MOTOR_EN P1_6 /* stepper drivers enable, active low */
#define LED P1_7      /* status LED, active low */
#define LIMIT P3_3    /* INT1: carriage limit (home) switch, low when closed */
#define LPT_ACK P3_5  /* Centronics nACK, low pulse after each byte */
#define PAPER P3_6    /* paper sensor, high = paper present */
#define HAM_SENSE P3_7 /* hammer-home sensor, high = both hammers back */
/* P0 is the Centronics data byte (with pull-ups). Toward the PC, P2.0-P2.3:
 * nFAULT, SELECT, PERROR, BUSY, the order of the bits they carry in IEEE 1284
 * nibble mode (0-3), so a nibble or the condition is one write to P2; nACK
 * (P3.5) is PtrClk there. From the PC: P3.2 (INT0) nSTROBE, P2.4 nAUTOFD
 * (HostBusy in nibble mode), P2.5 nSELECTIN (1284 Active).
 * firmware/README.md, "Pin map". */
#define LPT_NFAULT P2_0
#define LPT_SELECT P2_1
#define LPT_PERROR P2_2
#define LPT_BUSY P2_3
#define LPT_HOSTBUSY P2_4
#define LPT_ACTIVE P2_5
#define LPT_STROBE P3_2

#endif
