/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "motion.h"

#include <8052.h>

#include "link.h"
#include "ramp.h"

/* The phase program step.asm walks (see the kinds there). */
#define K_END 0
#define K_FAST_UP 1
#define K_COUNT 2
#define K_FAST_DN 3
#define K_SLOW_UP 4
#define K_SLOW_DN 5
#define K_SCOUNT 6
#define K_HOME 7
#define K_HOFF 8
#define K_LAST 9

/* Read by step.asm. */
__data uint8_t c_cl, c_ch, c_ui, c_di, s_pl, s_ph, s_pin, s_kind, mv_p;
__data uint8_t t2_a; /* the step interrupt keeps ACC here (step.asm) */
volatile __bit m_slow, m_cr, m_fu, m_upcr, m_updn, mv_done, mv_limit;
/* Seven phases at most: slow up, fast up, cruise, fast down, slow down, the
 * last two steps, and the end (one byte). */
static __idata uint8_t prog[6 * 5 + 1];
static __idata uint8_t *wp;

void nextph(void);
void timer_go(uint16_t x);

static void rec(uint8_t kind, uint16_t count, uint16_t ptr) {
    wp[0] = kind;
    if (kind == K_END) return; /* the interrupt reads nothing after it */
    wp[1] = (uint8_t)count;                      /* DJNZ form: 0 means 256 */
    wp[2] = (uint8_t)(((count - 1) >> 8) + 1);
    wp[3] = (uint8_t)ptr;
    wp[4] = (uint8_t)(ptr >> 8);
    wp += 5;
}

static uint16_t rd16(FW_CODE uint8_t *p) { return (uint16_t)(((uint16_t)p[0] << 8) | p[1]); }

/* Starts the program in prog: its first event `x` cycles after the last
 * event of the program before (step.asm, timer_go), the second `second` (a
 * reload value) after that; from there on the interrupt writes each interval
 * two steps ahead. */
static void start(uint16_t x, uint16_t second) {
    ET2 = 0;
    mv_done = 0;
    mv_limit = 0;
    mv_p = (uint8_t)prog;
    nextph();
    RCAP2L = (uint8_t)second;
    RCAP2H = (uint8_t)(second >> 8);
    timer_go(x < 64 ? 64 : x);
    ET2 = 1;
}

void motion_init(void) {
    T2CON = 0; /* timer, 16-bit auto-reload */
    PT2 = 1;   /* steps above the UART and the strobe: 5 cycles of latency at most (README, "Step timing") */
    ET2 = 1;
    mv_done = 1;
}

void motion_stop(void) {
    TR2 = 0;
    TF2 = 0;
    mv_done = 1;
}

/* A table move, split into phases. Before step k the interval is
 * T[min(k, n + 2 - k, R + 1) - 1] (docs/protocol.md); the interrupt for step k
 * writes the interval of step k + 2, so the phases cover steps 3..n and end
 * with the last two steps, which write nothing. Indices are 8-bit (R < 256);
 * only the step count and the cruise are 16-bit. The feed's table is all
 * 16-bit entries: its k is R + 1. */
static uint8_t t_r, t_k; /* the feed has t_k > t_r: no fast entries */
static FW_CODE uint8_t *t_slow;

/* Steps with table indices lo..hi, rising (lo is a variable: it moves). Macros,
 * not functions, like emit_dn: a call level here costs 2 bytes of stack on
 * the main loop's deepest chain (README, "Stack"). The slow ascent writes
 * T[K] too (its high byte is 0xFF, ramp_slow holds T[0..K]): the fast ascent
 * then writes low bytes only, which keeps its interrupt short enough for
 * the top of the ramp (step.asm). */
#define EMIT_UP(lo, hi)                                                                         \
    do {                                                                                        \
        if ((lo) <= t_k) {                                                                      \
            top = (hi) <= t_k ? (hi) : t_k;                                                     \
            rec(K_SLOW_UP, (uint8_t)(top - (lo) + 1), (uint16_t)(t_slow + 2 * (lo)));           \
            (lo) = (uint8_t)(top + 1);                                                          \
        }                                                                                       \
        if ((lo) <= (hi) && (lo) > t_k)                                                         \
            rec(K_FAST_UP, (uint8_t)((hi) - (lo) + 1), (uint8_t)(RAMP_FAST_BIAS + (lo) - t_k)); \
    } while (0)

/* Steps with table indices hi down to 1 (hi is a variable: it moves). */
#define EMIT_DN(hi)                                                               \
    do {                                                                          \
        if ((hi) >= t_k) {                                                        \
            rec(K_FAST_DN, (uint8_t)((hi) - t_k + 1), (uint8_t)(RAMP_FAST_BIAS + (hi) - t_k)); \
            (hi) = (uint8_t)(t_k - 1);                                            \
        }                                                                         \
        if ((hi) >= 1) rec(K_SLOW_DN, (hi), (uint16_t)(t_slow + 2 * (hi)));       \
    } while (0)

/* move_carriage and move_feed (motion.h) come here directly, for the same
 * reason. */
void move_table(uint8_t feed, uint16_t n) {
    uint8_t a, hi, lo, top;
    if (feed) {
        s_pin = PIN_FSTEP;
        t_r = FEED_R;
        t_k = (uint8_t)(FEED_R + 1);
        t_slow = feed_table;
    } else {
        s_pin = PIN_CSTEP;
        t_r = RAMP_R;
        t_k = RAMP_K;
        t_slow = ramp_slow;
    }
    wp = prog;
    if (n >= 2 * (uint16_t)t_r) {
        /* The whole ramp: up, cruise (if any), down. */
        a = (uint8_t)(t_r + 1);
        lo = 2;
        if (a >= 3) EMIT_UP(lo, t_r);
        if (n > 2 * (uint16_t)t_r) rec(t_k <= t_r ? K_COUNT : K_SCOUNT, n - 2 * (uint16_t)t_r, 0);
        hi = (uint8_t)(t_r - 1);
        if (n - 2 < hi) hi = (uint8_t)(n - 2);
        EMIT_DN(hi);
    } else {
        /* A truncated ramp: up to step a, then down (n < 2R, so 8 bits). */
        a = (uint8_t)((n + 2) / 2);
        lo = 2;
        hi = (uint8_t)(a - 1);
        if (a >= 3) EMIT_UP(lo, hi);
        if (n >= 3) {
            hi = (uint8_t)(n - a);
            if (hi > n - 2) hi = (uint8_t)(n - 2);
            if (hi) EMIT_DN(hi);
        }
    }
    rec(K_LAST, n < 2 ? n : 2, 0);
    rec(K_END, 1, 0);
    /* Step 1 comes START_GAP + T[0] after the last event before the move. */
    start((uint16_t)(START_GAP - rd16(t_slow)), n >= 2 ? rd16(t_slow + 2) : 0);
}

/* One phase of `kind` and the end. */
static void one_phase(uint8_t kind, uint16_t n) {
    wp = prog;
    rec(kind, n, 0);
    rec(K_END, 1, 0);
}

void move_constant(uint8_t pin, uint16_t n) {
    s_pin = pin;
    one_phase(K_SCOUNT, n);
    start(START_GAP + cfg_home_iv, (uint16_t)(0 - cfg_home_iv));
}

void move_home(uint16_t n) {
    s_pin = PIN_CSTEP;
    one_phase(K_HOME, n);
    start(START_GAP + cfg_home_iv, (uint16_t)(0 - cfg_home_iv));
}

/* The interrupt makes every edge with XRL P1 (step.asm): s_pin holds the pins
 * that change, here the hammers that are up and go down ... */
void hammer_down_after_settle(uint8_t pins) {
    s_pin = pins & (uint8_t)~P1;
    one_phase(K_SCOUNT, 1);
    start(cfg_settle, 0);
}

/* ... and the hammers that are down and go up. */
void hammer_up_after_pulse(void) {
    s_pin = P1 & (PIN_CVX | PIN_CCV);
    one_phase(K_HOFF, 1);
    start(cfg_hammer, 0);
}
