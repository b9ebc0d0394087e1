/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The executor: runs the job stream from the ring, one step of work per call
 * from the main loop, never blocking while a move or wait is under way.
 * Motion itself is timed by the step interrupt (motion.c, step.asm). */
#include "exec.h"

#include "board.h"
#include "decoder.h"
#include "link.h"
#include "motion.h"
#include "ramp.h"

/* What the executor is doing. */
enum {
    X_FETCH,    /* take the next op */
    X_HOME,     /* homing move under way */
    X_SEEK,     /* seek under way */
    X_FEED,     /* pass: feed move under way */
    X_MOVE,     /* pass: carriage move to the next strike under way */
    X_SETTLE,   /* pass: at rest before the hammer */
    X_DWELL,    /* pass: hammer down */
    X_NEXT      /* pass: at rest, ready for the next entry once it is in the ring */
};
static uint8_t xs;
static uint8_t p_flags, p_left; /* pass flags, entries not yet struck */
static uint16_t p_first;        /* grid units to the first strike */
static __bit c_neg;             /* carriage's last direction (backlash) */
static __bit f_neg;
static __bit ham_ccv;
static __bit p_is_first; /* the next entry is the pass's first (its move is the header's) */
static __bit p_drop;     /* a new session dropped the rest of the pass (exec_drop_pass) */

#ifdef FW_EMU
/* Called once a strike is made (fired, counted, its pulse over, the hammer
 * back): `sim --firmware --reset-at-strike N` sets an s51 breakpoint on it
 * (the map's _fw_strike_fired) and resets the chip at its Nth call, the head
 * at rest. Emulator build only; the chip's image has no such call. */
static __bit emu_fired;
void fw_strike_fired(void) {}
#endif

uint8_t exec_busy(void) { return xs != X_FETCH || !mv_done; }

void exec_abort(void) {
    /* A move cut short leaves the counter at its target, not where the steps
     * got to: the position is no longer known until the next HOME. */
    if (!mv_done) fw_flags &= (uint8_t)~FL_HOMED;
    motion_stop();
    HAM_CVX = 0;
    HAM_CCV = 0;
    xs = X_FETCH;
    /* The pass stays active: strikes in pass counts what it struck, and the
     * host's restart after a limit, hammer or stream fault skips exactly
     * those (clearing it here made the host restart the pass from its first
     * strike, as main.c once did after a warm reset). ABORT clears it (link.c). */
}

void exec_drop_pass(void) {
    if (xs >= X_FEED) p_drop = 1;
}

/* Leaves a dropped pass at a safe point (at rest): it stays active, with its
 * strike count, and the job holds still until RESUME. */
static uint8_t dropped(void) {
    if (!p_drop) return 0;
    p_drop = 0;
    xs = X_FETCH;
    fw_pause_req = 0;
    fw_state = ST_PAUSED;
    fw_ack();
    return 1;
}

void exec_init(void) {
    xs = X_FETCH;
    p_drop = 0;
    c_neg = 0;
    f_neg = 0;
}

static void fault(uint8_t bits) {
    exec_abort();
    fw_faults |= bits;
    fw_state = ST_FAULT;
    fw_flush();
    fw_ack();
}

static uint8_t at(uint8_t i) { return fw_buf[fw_ops_head + i]; }

/* A carriage move of `steps` in direction `neg` (toward home), counted in the position. A
 * reversal adds the backlash to the motor's move (the sources' rule). */
static __bit neg;
static void carriage(uint16_t steps) {
    uint16_t motor = steps;
    if (steps == 0) return;
    if (neg != c_neg) motor += C_BACKLASH;
    c_neg = neg;
    CDIR = !neg;
    if (neg) fw_carriage -= (int16_t)motor;
    else fw_carriage += (int16_t)motor;
    move_carriage(motor);
}

/* A uvar at ring offset *i (1 or 2 bytes, 15 bits); advances *i. An svar is
 * the same with bit 6 (one byte) or bit 14 (two bytes) as the sign. */
static uint8_t vi;
static uint16_t uvar(void) {
    uint8_t b = at(vi++);
    if (!(b & 0x80)) return b;
    return (uint16_t)(((uint16_t)(b & 0x7F) << 8) | at(vi++));
}
static int16_t svar(void) {
    uint8_t two = (at(vi) & 0x80) != 0;
    uint16_t u = uvar();
    if (two) return (u & 0x4000) ? (int16_t)(u | 0x8000) : (int16_t)u;
    return (u & 0x40) ? (int16_t)u - 128 : (int16_t)u;
}

/* n x g by shift and add: SDCC's __mulint uses MUL AB, and the image must
 * have no MUL or DIV (step.asm: they lengthen the step interrupt's latency). */
static uint16_t times(uint16_t n, uint8_t g) {
    uint16_t r = 0;
    for (; g; g >>= 1, n <<= 1)
        if (g & 1) r += n;
    return r;
}

/* Starts a pass record at the head: reads its header, consumes it, and
 * starts the feed. The header is whole in the ring; its entries follow as
 * they arrive (each strike starts once its entry is in). */
static void pass_begin(void) {
    int16_t feed;
    vi = 1;
    p_flags = at(vi++);
    fw_skip = 0;
    if (p_flags & PF_SKIP) fw_skip = at(vi++);
    feed = svar();
    p_first = uvar();
    p_left = at(vi++);
    fw_ops_head += vi;
    fw_strikes_in_pass = fw_skip;
    fw_flags |= FL_PASS_ACTIVE;
    xs = X_FEED;
    if (!(p_flags & PF_NO_FEED) && feed != 0) {
        uint8_t back = feed < 0; /* not `neg`: that is the carriage's */
        uint16_t steps = times((uint16_t)(back ? -feed : feed), F_GRID);
        if ((__bit)back != f_neg) steps += F_BACKLASH;
        f_neg = back;
        FDIR = !back;
        fw_feed += back ? -(int16_t)steps : (int16_t)steps;
        move_feed(steps);
    }
}

/* The move to the strike at the head of the entries. */
static void strike_move(uint8_t first) {
    uint8_t e = at(0);
    uint16_t d;
    ham_ccv = (e & E_CONCAVE) != 0;
    if (first) {
        neg = (p_flags & PF_FIRST_NEG) != 0;
        carriage(times(p_first, C_GRID));
    } else {
        d = e & E_DIST;
        if (e & E_EXT) d = (uint16_t)((d << 8) | at(1));
        neg = (p_flags & PF_SWEEP_NEG) != 0;
        carriage(times(d, C_GRID));
    }
    xs = X_MOVE;
}

static void pass_end(void) {
    fw_flags &= (uint8_t)~FL_PASS_ACTIVE;
    ++fw_pass_index;
    fw_executed = fw_pass_index;
    fw_strikes_in_pass = 0;
    xs = X_FETCH;
    fw_ack(); /* the host counts a pass only when it is executed */
}

static uint16_t be16(uint8_t i) { return (uint16_t)(((uint16_t)at(i) << 8) | at((uint8_t)(i + 1))); }

static void fetch(void) {
    uint8_t op;
    if (fw_state == ST_PAUSED || fw_state == ST_FAULT) return;
    if (fw_ops_head == fw_ops_done) {
        if ((fw_flags & FL_JOB_ACTIVE) && fw_state != ST_WAITING) {
            fw_state = ST_WAITING;
            fw_starved();
        }
        return;
    }
    if (fw_pause_req) {
        fw_pause_req = 0;
        fw_state = ST_PAUSED;
        fw_ack();
        return;
    }
    op = at(0);
    if (!(fw_flags & FL_JOB_ACTIVE) && op != OP_JOB_BEGIN) {
        fault(F_STREAM); /* ops outside a job: a host bug */
        return;
    }
    if (fw_state == ST_WAITING) fw_state = ST_RUNNING;
    switch (op) {
        case OP_JOB_BEGIN:
            fw_job_id = be16(1);
            fw_pass_index = be16(3);
            fw_executed = fw_pass_index;
            fw_strikes_in_pass = 0;
            fw_flags = (uint8_t)((fw_flags | FL_JOB_ACTIVE) & ~FL_JOB_ENDED);
            fw_state = ST_RUNNING;
            fw_ops_head += 5;
            fw_ack();
            break;
        case OP_JOB_END:
            fw_ops_head += 1;
#ifdef FW_EMU
            /* s51's simulator interface (run-s51.sh --stop-at-job-end maps it
             * to xram 0xFFFF): 's' ends the run, so a benchmark reads the
             * emulator's cycle counters at a known point. A plain write to
             * xram otherwise. */
            *(volatile __xdata uint8_t *)0xFFFF = 's';
#endif
            fw_flags = (uint8_t)((fw_flags & ~FL_JOB_ACTIVE) | FL_JOB_ENDED);
            fw_state = ST_IDLE;
            fw_ack();
            break;
        case OP_SHEET_BEGIN:
            if (!PAPER) {
                /* Nothing is dropped: the op runs again once paper is in. */
                fw_faults |= F_PAPER_OUT;
                fw_state = ST_FAULT;
                fw_ack();
                return;
            }
            fw_sheet = be16(1);
            fw_feed = 0; /* the sheet's top edge is the feed origin */
            fw_ops_head += 3;
            break;
        case OP_SHEET_END:
            fw_sheet = 0;
            fw_ops_head += 1;
            break;
        case OP_HOME:
            fw_ops_head += 1;
            fw_state = ST_HOMING;
            CDIR = 0;
            c_neg = 1;
            xs = X_HOME;
#ifdef FW_EMU
            /* s51 has no mechanics to close the switch: the emulator build
             * closes it at step 0, which the emulated carriage reaches after
             * exactly fw_carriage steps (it loses none). Same rate, same pin. */
            /* After a warm reset (not homed, the count kept in RAM) too: the
             * emulated carriage lost no step, so it is fw_carriage from home. */
            if (fw_carriage > 0) {
                move_constant(PIN_CSTEP, (uint16_t)fw_carriage);
            }
            mv_limit = 1;
#else
            move_home(cfg_travel + 2 * C_GRID);
#endif
            break;
        case OP_SEEK_CARRIAGE:
        case OP_SEEK_FEED: {
            int16_t target = (int16_t)be16(1);
            uint8_t feed = op == OP_SEEK_FEED;
            int16_t from = feed ? fw_feed : fw_carriage;
            int16_t d = target - from;
            fw_ops_head += 3;
            if (!feed && (!(fw_flags & FL_HOMED) || target < 0 || (uint16_t)target > cfg_travel)) {
                fault(F_STREAM);
                return;
            }
            if (d == 0) break;
            if (feed) {
                FDIR = d > 0;
                f_neg = d < 0;
                fw_feed = target;
            } else {
                CDIR = d > 0;
                c_neg = d < 0;
                fw_carriage = target;
            }
            move_constant(feed ? PIN_FSTEP : PIN_CSTEP, (uint16_t)(d < 0 ? -d : d));
            xs = X_SEEK;
            break;
        }
        case OP_PASS:
            if (!(fw_flags & FL_HOMED)) {
                fault(F_STREAM); /* the host must home before positioning */
                return;
            }
            pass_begin();
            break;
        default: fault(F_STREAM); break; /* checked on receipt: cannot happen */
    }
}

void exec_poll(void) {
    if (!mv_done) {
        /* The limit switch closing during a move toward home that is not
         * homing means lost steps: stop before the head hits the frame. */
        if (xs != X_HOME && !LIMIT && !CDIR && fw_carriage > (int16_t)(4 * C_GRID)) {
            fw_flags &= (uint8_t)~FL_HOMED;
            fault(F_LIMIT);
        }
        return;
    }
    switch (xs) {
        case X_FETCH: fetch(); return;
        case X_HOME:
#ifdef FW_EMU
            mv_limit = 1;
#endif
            if (!mv_limit) {
                fault(F_LIMIT); /* travelled the whole width without finding the switch */
                return;
            }
            fw_carriage = 0;
            fw_flags |= FL_HOMED;
            fw_state = ST_RUNNING;
            xs = X_FETCH;
            return;
        case X_SEEK: xs = X_FETCH; return;
        case X_FEED:
            if (dropped()) return;
            if (p_left == 0) {
                pass_end();
                return;
            }
            p_is_first = 1;
            xs = X_NEXT;
            return;
        case X_MOVE:
            if (fw_carriage < 0 || (uint16_t)fw_carriage > cfg_travel) {
                fw_flags &= (uint8_t)~FL_HOMED;
                fault(F_LIMIT);
                return;
            }
            /* The hammer comes down at the settle's end, from the timer. */
            xs = X_SETTLE;
            hammer_down_after_settle(fw_skip ? 0 : (ham_ccv ? PIN_CCV : PIN_CVX));
            return;
        case X_SETTLE:
            /* Down (or, made before a reset, passed over at the same pace). */
            xs = X_DWELL;
            if (fw_skip) {
                --fw_skip; /* made before the reset: passed over at the same pace */
            } else {
                ++fw_strikes_in_pass;
#ifdef FW_EMU
                emu_fired = 1;
#endif
            }
            hammer_up_after_pulse();
            return;
        case X_DWELL:
            /* Both hammers must be back before the head moves on. */
            if (!HAM_SENSE) {
                fault(F_HAMMER);
                return;
            }
#ifdef FW_EMU
            if (emu_fired) {
                emu_fired = 0;
                fw_strike_fired();
            }
#endif
            if (dropped()) return; /* the entry went with the ring */
            fw_ops_head += (at(0) & E_EXT) ? 2 : 1;
            if (--p_left == 0) {
                pass_end();
                return;
            }
            p_is_first = 0;
            xs = X_NEXT;
            if (fw_pause_req) {
                /* A safe point: at rest between two strikes. */
                fw_pause_req = 0;
                fw_state = ST_PAUSED;
                fw_ack();
            }
            return;
        case X_NEXT:
            if (dropped()) return;
            if (fw_state == ST_PAUSED || fw_state == ST_FAULT) return;
            if (fw_ops_head == fw_ops_done) {
                /* The next strike's entry has not arrived: wait at rest. */
                if (fw_state != ST_WAITING) {
                    fw_state = ST_WAITING;
                    fw_starved();
                }
                return;
            }
            if (fw_state == ST_WAITING) fw_state = ST_RUNNING;
            strike_move(p_is_first);
            return;
        default: return;
    }
}
