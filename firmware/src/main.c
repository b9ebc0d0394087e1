/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Tactus reference firmware for the AT89C52 at 11.0592 MHz (firmware/README.md). */
#include "board.h"
#include "decoder.h"
#include "exec.h"
#include "link.h"
#include "lpt.h"
#include "motion.h"
#include "uart.h"

/* Interrupt vectors: SDCC emits them for the prototypes it sees here. */
void t2_isr(void) __interrupt(5); /* timer 2, step.asm */
void uart_isr(void) __interrupt(SI0_VECTOR);
void strobe_isr(void) __interrupt(IE0_VECTOR);

void exec_init(void);
void exec_poll(void);

/* Warm restart: the 8051 clears its SFRs on reset but not its RAM. The
 * signature tells a reset (progress in RAM is exact) from a power-up. */
#define SIG0 0x54 /* 'T' */
#define SIG1 0xC5
static __data uint8_t sig[2];

/* SDCC's startup would clear RAM before main: returning 1 skips that, and
 * every variable is set below (all of it on a cold start). */
unsigned char _sdcc_external_startup(void) {
    EA = 0;
    return 1;
}

uint8_t fw_paper_present(void) { return PAPER; }

/* Stack high-water mark: the stack is painted at boot, and STATUS_REPLY
 * reports how many of its bytes were ever used (docs/protocol.md), so the
 * emulator measures the real worst case instead of an estimate. */
#define PAINT 0xA5
static void paint_stack(void) {
    __idata uint8_t *p = (__idata uint8_t *)(SP + 4); /* past this call's frame */
    do {
        *p = PAINT;
    } while (++p != 0);
}

uint8_t fw_stack_used(void) {
    extern __idata uint8_t _start__stack[];
    __idata uint8_t *p = (__idata uint8_t *)0xFF;
    while (*p == PAINT && p != _start__stack) --p;
    return (uint8_t)(p - _start__stack + 1);
}

static void cold_state(void) {
    fw_state = ST_IDLE;
    fw_faults = F_POWER_ON;
    fw_flags = 0;
    fw_job_id = 0;
    fw_executed = 0;
    fw_pass_index = 0;
    fw_sheet = 0;
    fw_strikes_in_pass = 0;
    fw_skip = 0;
    fw_carriage = 0;
    fw_feed = 0;
    cfg_travel = cfg_home_iv = cfg_hammer = cfg_settle = 0;
}

void main(void) {
    uint8_t warm = sig[0] == SIG0 && sig[1] == SIG1;
    int16_t b;
    P1 = 0x80; /* steps, hammers low; drivers enabled (P1.6 low); LED off */
    paint_stack();
    fw_pause_req = 0;
    if (warm) {
        /* Progress is exact; the position is not (the drivers lost power or
         * steps): the host homes again and resumes at the strike it is told.
         * The pass stays active: strikes in pass counts what this pass has
         * struck, and the host skips exactly those (clearing the flag here
         * made it restart the pass from its first strike: a reset in the
         * middle of a pass struck its first dots twice). */
        fw_faults |= F_WARM_RESET;
        fw_flags &= (uint8_t)~FL_HOMED;
        if (fw_flags & FL_JOB_ACTIVE) fw_state = ST_FAULT;
        else fw_state = ST_IDLE;
    } else {
        cold_state();
        sig[0] = SIG0;
        sig[1] = SIG1;
    }
    fw_link_init(warm);
    exec_init();
    motion_init();
    io_init();
    lpt_init();
    EA = 1;
    for (;;) {
#ifdef FW_DIAG_RX
        /* diagnostic: P1.7 high while a received byte is processed */
        while ((b = io_rx()) >= 0) {
            LED = 1;
            fw_rx_byte((uint8_t)b);
            LED = 0;
        }
#else
        while ((b = io_rx()) >= 0) fw_rx_byte((uint8_t)b);
#endif
        if (fw_ops_head > 0) fw_compact(); /* between bytes: the frame in progress moves too */
        exec_poll();
        fw_poll_paper();
        fw_report_room();
        io_tx_pump();
        lpt_poll();
#if defined(FW_DIAG_RX)
#elif defined(FW_DIAG_PASS)
        LED = !LED; /* diagnostic: P1.7 toggles once a main-loop pass */
#else
        LED = !(fw_state == ST_RUNNING || fw_state == ST_HOMING);
#endif
    }
}
