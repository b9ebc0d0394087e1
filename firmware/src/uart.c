/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "uart.h"

#include "board.h"
#include "link.h"
#include "lpt.h"

/* Baud from timer 1 in mode 2 with SMOD=1: 11.0592 MHz / (16 x 12 x (256 - TH1)).
 * SMOD=1 is also what s51 honours (it ignores SMOD=0). */
#ifndef FW_BAUD
#define FW_BAUD 9600
#endif
#define TH1_RELOAD (256 - (11059200UL / (16UL * 12UL * FW_BAUD)))

__idata uint8_t rxq[RXQ];
volatile uint8_t rx_w, rx_r;
#ifdef FW_EMU
uint8_t fw_rx_dropped;
#endif
/* One byte handed from the main loop to the transmitter: the serial
 * interrupt calls nothing, so it needs little stack (check-size.py). */
static volatile uint8_t tx_next;
static volatile __bit tx_have, tx_busy;

void io_init(void) {
    rx_w = rx_r = 0;
#ifdef FW_EMU
    fw_rx_dropped = 0;
#endif
    fw_via_lpt = 0;
    tx_busy = 0;
    tx_have = 0;
    TMOD = (TMOD & 0x0F) | 0x20; /* timer 1: 8-bit auto-reload */
    TH1 = TL1 = (uint8_t)TH1_RELOAD;
    PCON |= 0x80;                /* SMOD */
    SCON = 0x50;                 /* mode 1, receiver on */
    TR1 = 1;
    ES = 1;
    /* Centronics: falling edge of nSTROBE on INT0. */
    LPT_BUSY = 0;
    LPT_ACK = 1;
    IT0 = 1;
    EX0 = 1;
}

void uart_isr(void) __interrupt(SI0_VECTOR) {
    if (RI) {
        RI = 0;
        fw_via_lpt = 0; /* replies go back the way the bytes came */
        RX_PUT(SBUF);
    }
    if (TI) {
        TI = 0;
        if (tx_have) {
            SBUF = tx_next;
            tx_have = 0;
        } else {
            tx_busy = 0;
        }
    }
}

int16_t io_rx(void) {
    uint8_t b;
    if (rx_r == rx_w) {
        /* Room again (in compatibility mode: in nibble mode Busy is a data line). */
        if (LPT_BUSY && lpt_mode == LM_COMPAT) LPT_BUSY = 0;
        return -1;
    }
    b = rxq[rx_r & (RXQ - 1)];
    ++rx_r;
    return b;
}

/* Replies are built byte by byte as the line takes them (link.c): the main
 * loop hands over the next byte whenever the last one has gone. */
void io_tx_pump(void) {
    int16_t b;
    if (tx_have || fw_via_lpt) return; /* the parallel port takes them (lpt.c) */
    b = fw_reply_byte();
    if (b < 0) return;
    tx_next = (uint8_t)b;
    tx_have = 1;
    if (!tx_busy) {
        tx_busy = 1;
        TI = 1; /* the interrupt sends it */
    }
}

void fw_tx_kick(void) {}
