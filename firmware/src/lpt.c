/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "lpt.h"

#include "board.h"
#include "link.h"
#include "uart.h"

uint8_t lpt_mode;
volatile FW_BIT lpt_strobe;
volatile FW_BIT fw_via_lpt;
static uint8_t lpt_out; /* the reply byte on the status lines */
static FW_BIT lpt_have; /* lpt_out holds a byte not yet sent */

/* The next reply byte into lpt_out, when the replies go this way. Only the
 * main loop builds replies for the parallel port (the UART's transmitter is
 * idle then: io_tx_pump), so fw_reply_byte is never entered twice. */
static void fill(void) {
    int16_t b;
    if (lpt_have || !fw_via_lpt) return;
    b = fw_reply_byte();
    if (b < 0) return;
    lpt_out = (uint8_t)b;
    lpt_have = 1;
}

/* The status lines P2.0-P2.3 (nFault, Select, PError, Busy) to v's low
 * bits, P2's upper half kept: two single-instruction writes (ORL, ANL, which
 * read the latches, not the pins), so the strobe interrupt's Busy is never
 * overwritten with a stale copy, and the input pins' latches stay 1. Never
 * with a constant 0 (see LM_TERM_DONE). */
#define LINES(v, keep)                       \
    do {                                     \
        P2 |= (v);                           \
        P2 &= (uint8_t)((v) | (keep));       \
    } while (0)
#define NF 0x01 /* nFault */
#define SEL 0x02
#define PE 0x04
#define BSY 0x08

/* Compatibility mode: PError = paper out, nFault low = a fault stands,
 * Select = on line (the firmware runs); Busy is the strobe's (kept). */
static void show_condition(void) {
    uint8_t c = SEL;
    if (fw_faults & F_PAPER_OUT) c |= PE;
    if (fw_state != ST_FAULT) c |= NF;
    LINES(c, 0xF8);
}

/* All four status lines at once (nibble mode, negotiation). */
static void lines4(uint8_t v) { LINES(v, 0xF0); }

/* Nibble mode: nFault, Select, PError and Busy carry data bits 0-3, then
 * nAck (PtrClk) falls: the nibble is there (events 9, 14). */
static void show_nibble(uint8_t n) {
    lines4(n);
    LPT_ACK = 0;
}

/* Centronics strobe (INT0, falling edge): in compatibility mode latch the
 * byte, acknowledge, and stay busy while the queue is nearly full (the PC
 * waits on Busy before the next strobe). While 1284 is active the strobe is
 * the negotiation's event 3, not data: noted for lpt_poll. */
#if FW_TARGET
void strobe_isr(void) __interrupt(IE0_VECTOR) {
#else
void strobe_isr(void) {
#endif
    if (LPT_ACTIVE) {
        lpt_strobe = 1;
        return;
    }
    LPT_BUSY = 1;
    RX_PUT(P0);
    fw_via_lpt = 1; /* replies go back the way the bytes came */
    LPT_ACK = 0;
#if FW_TARGET
    __asm nop __endasm;
    __asm nop __endasm;
    __asm nop __endasm;
    __asm nop __endasm;
#endif
    LPT_ACK = 1;
    if ((uint8_t)(rx_w - rx_r) < RXQ - 2) LPT_BUSY = 0;
}

void lpt_init(void) {
    lpt_mode = LM_COMPAT;
    lpt_strobe = 0;
    fw_via_lpt = 0;
    lpt_have = 0;
    LPT_HOSTBUSY = 1; /* inputs (P2 is quasi-bidirectional) */
    LPT_ACTIVE = 1;
    show_condition();
}

/* One if per mode, not a switch: SDCC's jump table indexes with MUL, and the
 * image must have none (README, "Step timing"). */
void lpt_poll(void) {
    uint8_t m = lpt_mode;
    fill();
    if (m == LM_COMPAT) {
        if (LPT_ACTIVE && !LPT_HOSTBUSY) { /* event 1: negotiation request */
            lpt_strobe = 0;
            /* Event 2: nAck low; PError, Select, nFault high; Busy low. */
            show_nibble(PE | SEL | NF);
            lpt_mode = LM_NEGOTIATING;
            return;
        }
        show_condition();
        return;
    }
    if (m == LM_NEGOTIATING) {
        /* A host that gives the negotiation up (its handshake timed out, it
         * reopened the port) drops 1284 Active without the strobe: back to
         * compatibility mode, nAck high again. Waiting here for the strobe
         * held the chip in the negotiation for good: the host's next bytes
         * came in, but no later negotiation was answered (a warm reset
         * while the host read a reply, lpt:emu?reset=N). */
        if (!LPT_ACTIVE) goto compat;
        /* Events 3-4 seen: the strobe fell and rose, HostBusy is high. */
        if (lpt_strobe && LPT_STROBE && LPT_HOSTBUSY) goto avail;
        return;
    }
    if (m == LM_IDLE) {
        if (!LPT_ACTIVE) { /* event 22: the host ends the 1284 mode */
            LPT_ACK = 0;   /* event 24 */
            lpt_mode = LM_TERM_ACK;
            return;
        }
        if (!LPT_HOSTBUSY && lpt_have) { /* event 7: the host is ready */
            show_nibble(lpt_out & 0x0F);
            lpt_mode = LM_LOW_SHOWN;
        }
        return;
    }
    if (m == LM_LOW_DONE) {
        if (!LPT_HOSTBUSY) {
            show_nibble(lpt_out >> 4);
            lpt_mode = LM_HIGH_SHOWN;
        }
        return;
    }
    if (m == LM_TERM_ACK) {
        if (!LPT_HOSTBUSY) { /* event 25 */
            LPT_ACK = 1;     /* event 27 */
            lpt_mode = LM_TERM_DONE;
        }
        return;
    }
    if (m == LM_TERM_DONE) {
        /* Event 28 (HostBusy high): back in compatibility mode. The host may
         * already be negotiating again (1284 Active high, HostBusy low): the
         * event has no answer from this side, and a poll can miss it. */
        if (!LPT_HOSTBUSY && !LPT_ACTIVE) return;
    compat:
        LPT_ACK = 1;
        lpt_mode = LM_COMPAT;
        LPT_BUSY = 0; /* not LINES(0, ...): SDCC writes P2 |= 0 as MOV P2,P2,
                       * which copies the pins (the host's inputs, low) into
                       * the latches and holds them low for good */
        show_condition();
        return;
    }
    if (!LPT_HOSTBUSY) return;
    if (m == LM_LOW_SHOWN) { /* event 10 */
        LPT_ACK = 1;         /* event 11 */
        lpt_mode = LM_LOW_DONE;
        return;
    }
    /* LM_HIGH_SHOWN, event 10 of the high nibble: the byte is over. */
    lpt_have = 0;
    fill();
avail:
    /* Events 5-6 (or the end of a byte): nDataAvail (nFault) low when a
     * byte waits; XFlag (Select), PError and Busy low; nAck high. */
    lines4(lpt_have ? 0 : NF);
    LPT_ACK = 1;
    /* A mode other than nibble (request 0x00) is refused: back to
     * compatibility mode (XFlag low said so). */
    lpt_mode = (m == LM_NEGOTIATING && P0 != 0) ? LM_COMPAT : LM_IDLE;
}
