/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Tactus reference firmware: what every source file shares.
 *
 * The link code (crc16.c, decoder.c, link.c) is plain C that SDCC compiles for
 * the 89C52 and gcc/clang compile natively for unit tests and fuzzing. These
 * macros hide the 8051 memory spaces from the native build. */
#ifndef TACTUS_FW_H
#define TACTUS_FW_H

#include <stdint.h>

#ifdef __SDCC
#define FW_IDATA __idata  /* indirect RAM 0x80-0xFF: the job ring lives here */
#define FW_CODE __code    /* flash */
#define FW_BIT __bit
#define FW_TARGET 1
#else
#define FW_BIT uint8_t
#define FW_IDATA
#define FW_CODE const
#define FW_TARGET 0
#endif

#define FW_PROTOCOL 3
#define FW_VERSION_MAJOR 1
#define FW_VERSION_MINOR 0

/* Frame layout (docs/protocol.md): SYNC LEN SEQ TYPE PAYLOAD CRC16hi CRC16lo. */
#define FW_SYNC 0x7E
#define FW_WIRE_MAX_PAYLOAD 80 /* a larger LEN is a false start, as on the host */
#define FW_FRAME_OVERHEAD 5    /* LEN SEQ TYPE CRC CRC: what is stored besides the payload */

/* The job ring and the receive area share one buffer (see link.c). Its size is
 * what the 89C52's 256 bytes leave once registers, variables and the stack are
 * placed; tools/check-size.py proves the stack keeps its 24 bytes. */
#ifndef FW_BUF_CAP
#define FW_BUF_CAP 64
#endif
/* Room kept beyond the window so a control frame always fits, even when the
 * host has filled every byte of the ring it was offered. */
#define FW_SLACK 17
#define FW_RING_BYTES (FW_BUF_CAP - FW_SLACK)
/* Largest DATA payload accepted (ops + the 2-byte check): about two thirds of
 * the ring, so the next frame fits while the ring still holds more than the
 * executor uses up during its transmission (docs/protocol.md, "Reliability"). */
#define FW_MAX_DATA ((FW_RING_BYTES * 2 / 3 + 2) < 80 ? (FW_RING_BYTES * 2 / 3 + 2) : 80)
#define FW_WINDOW_FRAMES 4

/* Frame types (host -> controller below 0x80). */
#define T_HELLO 0x01
#define T_CONFIGURE 0x02
#define T_DATA 0x03
#define T_PAUSE 0x04
#define T_RESUME 0x05
#define T_ABORT 0x06
#define T_STATUS 0x07
#define T_KEEPALIVE 0x08
#define T_HELLO_REPLY 0x81
#define T_ACK 0x82
#define T_NAK 0x83
#define T_STATUS_REPLY 0x84

/* NAK reasons. */
#define NAK_OUT_OF_ORDER 1
#define NAK_NO_SPACE     2
#define NAK_NO_SESSION   3
#define NAK_BAD_PAYLOAD  4
#define NAK_UNKNOWN_TYPE 5

/* Controller states. */
#define ST_IDLE 0
#define ST_RUNNING 1
#define ST_WAITING 2
#define ST_PAUSED 3
#define ST_FAULT 4
#define ST_HOMING 5

/* Fault bits. */
#define F_PAPER_OUT 0x01
#define F_LIMIT 0x02
#define F_HAMMER 0x04
#define F_POWER_ON 0x08
#define F_WARM_RESET 0x10
#define F_HOST_TIMEOUT 0x20
#define F_UNDERRUN 0x40
#define F_STREAM 0x80

/* Status flags. */
#define FL_CONFIGURED 0x01
#define FL_HOMED 0x02
#define FL_PASS_ACTIVE 0x04
#define FL_PAPER 0x08
#define FL_JOB_ACTIVE 0x10
/* The job named by job id ran to its JOB_END (docs/protocol.md): set there,
 * cleared by JOB_BEGIN (so an ABORT of a running job leaves it clear) and by
 * a cold start. */
#define FL_JOB_ENDED 0x20

/* Capabilities. */
#define CAP_INTERPOINT 0x01
#define CAP_LPT 0x02
#define CAP_UART 0x04
#define CAP_WARM_RESTART 0x08

#endif
