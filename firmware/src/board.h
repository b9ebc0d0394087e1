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
#define LPT_BUSY P3_4 /* Centronics BUSY, high = busy */
#define LPT_ACK P3_5  /* Centronics nACK, low pulse after each byte */
#define PAPER P3_6    /* paper sensor, high = paper present */
#define HAM_SENSE P3_7 /* hammer-home sensor, high = both hammers back */
/* P3.2 (INT0) is Centronics nSTROBE; P0 is the Centronics data byte (with
 * pull-ups); P2.0 nFAULT, P2.1 PERROR, P2.2 SELECT toward the PC. */
#define LPT_NFAULT P2_0
#define LPT_PERROR P2_1
#define LPT_SELECT P2_2

#endif
