/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_UART_H
#define TACTUS_FW_UART_H
#include "fw.h"

/* Serial port (timer 1, SMOD=1) and the Centronics input, both feeding one
 * receive queue that the main loop drains into the frame decoder. */
void io_init(void);
/* A received byte, or -1. */
int16_t io_rx(void);
/* Hands the next reply byte to the transmitter when it has room (main loop). */
void io_tx_pump(void);

#endif
