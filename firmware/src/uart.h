/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_UART_H
#define TACTUS_FW_UART_H
#include "fw.h"

/* Serial port (timer 1, SMOD=1) and the Centronics input, both feeding one
 * receive queue that the main loop drains into the frame decoder. */
void io_init(void);

/* The receive queue both inputs fill (the serial and the strobe interrupt). */
#define RXQ 8 /* power of two; the main loop drains it every few hundred cycles */
extern FW_IDATA uint8_t rxq[RXQ];
extern volatile uint8_t rx_w, rx_r;

/* A byte that finds the queue full is dropped: the frame it belongs to fails
 * its CRC and the host sends it again. The emulator build counts them
 * (STATUS_REPLY's byte 23, saturating): the main loop must never let the
 * queue fill (firmware/README.md, "Main loop"). */
#ifdef FW_EMU
extern uint8_t fw_rx_dropped;
#define RX_DROPPED() \
    do {             \
        if (++fw_rx_dropped == 0) fw_rx_dropped = 255; \
    } while (0)
#else
#define RX_DROPPED() \
    do {             \
    } while (0)
#endif
#define RX_PUT(b)                                  \
    do {                                           \
        if ((uint8_t)(rx_w - rx_r) < RXQ) {        \
            rxq[rx_w & (RXQ - 1)] = (b);           \
            ++rx_w;                                \
        } else {                                   \
            RX_DROPPED();                          \
        }                                          \
    } while (0)
/* A received byte, or -1. */
int16_t io_rx(void);
/* Hands the next reply byte to the transmitter when it has room (main loop). */
void io_tx_pump(void);

#endif
