/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The step interrupt's latency under colliding low-priority interrupts (s51).
 *
 * A firmware image with this main instead of src/main.c (make -C firmware
 * probe): the real step interrupt, motion.c, uart.c and their interrupt
 * vectors, and a main loop that runs the same block of moves (a feed move,
 * a long and a short carriage move, a hammer down and up) four times:
 *   block 0: nothing else happens (the reference);
 *   block 1: the main loop sets TI (the UART interrupt) a swept number of
 *            cycles before each timer event;
 *   block 2: the same with IE0 (the Centronics strobe interrupt);
 *   block 3: both at once (the strobe's, then the UART's after its RETI).
 * The delay sweeps 0..127 cycles after the counter comes within 128 cycles
 * of its overflow, so every alignment of a low-priority interrupt's vectoring,
 * its first instructions and its RETI with the timer event is met many times.
 * Every edge must come on its cycle in every block: tests/firmware/
 * emu_latency_test.py compares the blocks' edges with block 0's. Then it ends
 * the run through the simulator interface (xram 0xFFFF). */
#include <stdint.h>

#include "board.h"
#include "link.h"
#include "motion.h"
#include "uart.h"

void t2_isr(void) __interrupt(5);
void uart_isr(void) __interrupt(SI0_VECTOR);
void strobe_isr(void) __interrupt(IE0_VECTOR);

unsigned char _sdcc_external_startup(void) {
    EA = 0;
    return 1;
}
uint8_t fw_paper_present(void) { return 1; }
uint8_t fw_stack_used(void) { return 0; }
/* What motion.c, uart.c and lpt.c take from the link layer, which the probe
 * leaves out (the whole firmware and this main would not fit in 8 KB): no
 * replies, an idle controller, the configuration set below. */
int16_t fw_reply_byte(void) { return -1; }
uint8_t fw_state, fw_faults;
uint16_t cfg_travel, cfg_home_iv, cfg_hammer, cfg_settle;

__data uint8_t pr_k;    /* the delay, 0..127 cycles */
__data uint8_t pr_t;    /* TL2 last read */
__data uint8_t pr_mode; /* bit 0: TI, bit 1: IE0, bit 2: a byte out every 4th event */
__data uint8_t pr_n;    /* events, for bit 2 */

/* Until mv_done: wait for the counter to come within 128 cycles of its
 * overflow (TH2 = 0xFF, TL2 >= 128), burn pr_k cycles (a jump into a slide of
 * NOPs), raise the chosen flags in one instruction each, wait for the
 * counter to reload (TH2 below 0xFF or TL2 going down), and step pr_k. The
 * flags are raised from about 118 cycles before an overflow to a few after
 * it; short intervals (fast carriage steps) take several events a round. */
static void inject(void) __naked {
    __asm
1$:     jb      _mv_done, 9$
        mov     a, 0xCD                 ; TH2
        cjne    a, #0xFF, 1$
        mov     a, 0xCC                 ; TL2
        add     a, #128
        jnc     1$
        sjmp    2$
9$:     ret
2$:     mov     dptr, #20$
        mov     a, #127
        clr     c
        subb    a, _pr_k
        jmp     @a+dptr
20$:    .rept   127
        nop
        .endm
        mov     a, _pr_mode
        jnb     acc.1, 21$
        setb    0x89                    ; IE0 (TCON.1): the strobe interrupt
21$:    jnb     acc.0, 26$
        setb    0x99                    ; TI (SCON.1): the UART interrupt
26$:    jnb     acc.2, 22$
        inc     _pr_n
        mov     a, _pr_n
        anl     a, #3
        jnz     22$
        mov     0x99, #0x55             ; SBUF: a byte out, TI when it has gone
22$:    mov     _pr_t, 0xCC
23$:    jb      _mv_done, 29$
        mov     a, 0xCD
        cjne    a, #0xFF, 25$           ; reloaded: the counter is low again
        mov     a, 0xCC
        cjne    a, _pr_t, 24$
24$:    mov     _pr_t, a                ; (C kept)
        jnc     23$                     ; TL2 went down: reloaded
25$:    inc     _pr_k
        anl     _pr_k, #127
        ljmp    1$
29$:    ret
    __endasm;
}

static void done(void) {
    inject();
    while (io_rx() >= 0) {
    }
}

void main(void) {
    uint8_t block;
    P1 = 0x80;
    cfg_settle = 920;
    cfg_hammer = 3686;
    motion_init();
    io_init();
    EA = 1;
    pr_k = 0;
    for (block = 0; block < 5; ++block) {
        pr_mode = block < 4 ? block : 4;
        FDIR = 1;
        move_feed(1500);
        done();
        CDIR = 1;
        move_carriage(3000);
        done();
        move_carriage(37);
        done();
        hammer_down_after_settle(PIN_CVX);
        done();
        hammer_up_after_pulse();
        done();
    }
    *(volatile __xdata uint8_t *)0xFFFF = 's';
    for (;;) {
    }
}
