/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "link.h"

#include "crc16.h"
#include "decoder.h"
#include "exec.h"

FW_IDATA uint8_t fw_buf[FW_BUF_CAP];
uint8_t fw_ops_head, fw_ops_done, fw_ops_end;

uint8_t fw_state, fw_faults, fw_strikes_in_pass, fw_skip, fw_flags;
uint16_t fw_job_id, fw_executed, fw_pass_index, fw_sheet;
int16_t fw_carriage, fw_feed;
uint16_t cfg_travel, cfg_home_iv, cfg_hammer, cfg_settle;
uint8_t fw_pause_req;

/* Session: lost on any reset (the host opens a new one). */
static uint8_t session, expected;
static uint16_t nonce;
/* Ring bytes free as last told to the host (written as the ACK goes out). */
static volatile uint8_t reported;
/* Replies due (set by the main loop) and the one on the line (ISR side). */
static FW_BIT rp_ack, rp_nak, rp_status, rp_hello;
static uint8_t rp_reason;
static uint8_t rp_type, rp_pos; /* the reply on the line */
static uint16_t rp_crc, rp_stash;

/* The job-stream check runs over DATA payloads as they are copied in, across
 * frame boundaries (a pass record may span frames). */
enum {
    VS_OP,
    VS_FIXED,
    VS_FLAGS,
    VS_SKIP,
    VS_FEED,
    VS_FEED2,
    VS_FIRST,
    VS_FIRST2,
    VS_N,
    VS_ENTRY,
    VS_ENTRY2
};
struct vstate {
    uint8_t st, n, flags, hi; /* n: bytes left of a fixed op, or entries left */
};
static struct vstate vs;
static uint8_t done_at; /* payload offset just past the last op completed in it */

uint8_t fw_ring_free(void) {
    uint8_t used = (uint8_t)(fw_ops_end - fw_ops_head);
    return used >= FW_RING_BYTES ? 0 : (uint8_t)(FW_RING_BYTES - used);
}

void fw_flush(void) {
    fw_ops_head = fw_ops_end;
    fw_ops_done = fw_ops_end;
    vs.st = VS_OP;
}

void fw_compact(void) {
    uint8_t shift = fw_ops_head, n, i;
    if (shift == 0) return;
    /* Ops and any partly received frame move together. */
    n = (uint8_t)(fw_ops_end - shift + fw_rx_fill());
    for (i = 0; i < n; ++i) fw_buf[i] = fw_buf[i + shift];
    fw_ops_head = 0;
    fw_ops_done = (uint8_t)(fw_ops_done - shift);
    fw_ops_end = (uint8_t)(fw_ops_end - shift);
}

void fw_link_init(uint8_t warm) {
    (void)warm;
    session = 0;
    expected = 0;
    nonce = 0;
    fw_ops_head = fw_ops_done = fw_ops_end = 0;
    vs.st = VS_OP;
    fw_rx_reset();
    rp_ack = rp_nak = rp_status = rp_hello = 0;
    rp_pos = 0;
    reported = fw_ring_free();
}

/* --- replies
 *
 * Replies are not buffered: the main loop only marks which ones are due, and
 * the transmitter builds each byte when the UART asks for it (fw_reply_byte,
 * from the serial interrupt), reading the state as it is then. That costs 6
 * bytes of RAM instead of a 16-byte queue, never blocks the main loop, and
 * merges ACKs that pile up while one is on the line (each says everything).
 * A 16-bit field is read whole when its first byte goes out, so a reply never
 * carries half of an old value and half of a new one. */

static void due(void) { fw_tx_kick(); }

void fw_ack(void) {
    if (!session) return;
    rp_ack = 1;
    due();
}

static void nak(uint8_t why) {
    rp_reason = why;
    rp_nak = 1;
    due();
}

/* Only the main loop calls what follows, for the UART (io_tx_pump) or the
 * parallel port (lpt.c), never both at once: SDCC's functions are not
 * reentrant. */
static uint8_t hi_of(uint16_t v) {
    rp_stash = v;
    return (uint8_t)(v >> 8);
}

/* Byte k of the 8-byte short status every ACK, NAK and STATUS_REPLY starts with. */
static uint8_t ack_field(uint8_t k) {
    switch (k) {
        case 0: return reported = fw_ring_free();
        case 1: return hi_of(fw_executed);
        case 3: return fw_state;
        case 4: return fw_faults;
        case 5: return fw_strikes_in_pass;
        case 6: return hi_of(fw_job_id);
        default: return (uint8_t)rp_stash; /* 2, 7: the low byte read with the high */
    }
}

static uint8_t payload_byte(uint8_t k) {
    switch (rp_type) {
        case T_NAK:
            if (k == 0) return rp_reason;
            return ack_field((uint8_t)(k - 1));
        case T_STATUS_REPLY:
            if (k < 8) return ack_field(k);
            switch (k) {
                case 8:
                    k = fw_flags;
                    if (fw_paper_present()) k |= FL_PAPER;
                    return k;
                case 9: return hi_of(fw_job_id);
                case 11: return hi_of(fw_sheet);
                case 13: return hi_of(fw_pass_index);
                case 15: /* i32, sign-extended from the 16-bit counters */
                    rp_stash = (uint16_t)fw_carriage;
                    return (rp_stash & 0x8000) ? 0xFF : 0;
                case 19:
                    rp_stash = (uint16_t)fw_feed;
                    return (rp_stash & 0x8000) ? 0xFF : 0;
                case 16:
                case 20: return (rp_stash & 0x8000) ? 0xFF : 0;
                case 17:
                case 21: return (uint8_t)(rp_stash >> 8);
#ifdef FW_EMU
                case 23: return fw_rx_dropped; /* receive bytes dropped (uart.c) */
#else
                case 23: return 0;
#endif
                case 24: return fw_stack_used(); /* v2's underruns: a v3 pass runs only
                                                    when whole in the ring, so the field
                                                    reports the stack high-water mark */
                default: return (uint8_t)rp_stash; /* 10, 12, 14, 18, 22 */
            }
        case T_HELLO_REPLY:
            switch (k) {
                case 0: return FW_PROTOCOL;
                case 1: return FW_VERSION_MAJOR;
                case 2: return FW_VERSION_MINOR;
                case 3: return CAP_INTERPOINT | CAP_LPT | CAP_UART | CAP_WARM_RESTART;
                case 4: return FW_RING_BYTES;
                case 5: return FW_MAX_DATA;
                case 6: return FW_WINDOW_FRAMES;
                /* Which ramp table and grid the firmware was built with: the host
                 * refuses a profile whose table differs (tools/gen-ramp.py). */
                default: return k < 11 ? fw_table_id[k - 7] : 0;
            }
        default: return ack_field(k);
    }
}

static uint8_t rp_crc_byte(uint8_t b) {
    rp_crc = crc16_update(rp_crc, b); /* the frame CRC's own routine (crc16.c) */
    return b;
}

static uint8_t rp_len(void) {
    switch (rp_type) {
        case T_HELLO_REPLY: return 13;
        case T_NAK: return 9;
        case T_STATUS_REPLY: return 25;
        default: return 8;
    }
}

int16_t fw_reply_byte(void) {
    uint8_t k, len;
    if (rp_pos == 0) {
        /* Idle: the next reply due, most urgent first. */
        if (rp_hello) {
            rp_hello = 0;
            rp_type = T_HELLO_REPLY;
        } else if (rp_nak) {
            rp_nak = 0;
            rp_type = T_NAK;
        } else if (rp_status) {
            rp_status = 0;
            rp_type = T_STATUS_REPLY;
        } else if (rp_ack) {
            rp_ack = 0;
            rp_type = T_ACK;
        } else {
            return -1;
        }
        rp_crc = 0xFFFF;
        rp_pos = 1;
        return FW_SYNC;
    }
    k = rp_pos++;
    len = rp_len();
    if (k == 1) return rp_crc_byte(len);
    if (k == 2) return rp_crc_byte(expected); /* the next SEQ this controller expects */
    if (k == 3) return rp_crc_byte(rp_type);
    k = (uint8_t)(k - 4);
    if (k < len) return rp_crc_byte(payload_byte(k));
    if (k == len) return (uint8_t)(rp_crc >> 8);
    rp_pos = 0;
    return (uint8_t)rp_crc;
}

void fw_report_room(void) {
    uint8_t free;
    if (!session) return;
    free = fw_ring_free();
    if ((uint16_t)free >= (uint16_t)reported + FW_MAX_DATA ||
        (free >= FW_MAX_DATA && reported < FW_MAX_DATA))
        fw_ack();
}

/* Paper loaded while *paper out* stands: the fault clears and the job shows
 * paused, with an ACK saying so; the host, which waits for the fault to
 * clear, then sends RESUME, and the SHEET_BEGIN that found no paper runs
 * (docs/protocol.md, "Paper out"; the C++ controller's load_paper). */
void fw_poll_paper(void) {
    if (!(fw_faults & F_PAPER_OUT) || !fw_paper_present()) return;
    fw_faults &= (uint8_t)~F_PAPER_OUT;
    /* Another fault (a warm reset) keeps the job in its fault. (The C++
     * controller also passes over *host timeout*, which the firmware never sets.) */
    if (fw_state == ST_FAULT && fw_faults == 0) fw_state = ST_PAUSED;
    fw_ack();
}

void fw_starved(void) {
    if (session && fw_ring_free() > reported) fw_ack();
}

/* --- the job-stream check */

/* Runs the job-stream grammar over the ops of the frame at f (from f + 3),
 * moving each to f + its offset as it goes. Returns 0 if every
 * byte fits, 1 for a malformed stream. Sets done_at: the payload offset just
 * past the last thing the executor may start, a whole op, or a pass header,
 * or one whole strike entry of a pass (passes stream: a strike starts when its
 * entry is in the ring). */
static uint8_t check_ops(FW_IDATA uint8_t *f, uint8_t len) {
    uint8_t i, b;
    done_at = 0;
    for (i = 0; i < len; ++i) {
        /* The ops lie behind the frame's 3 header bytes: each moves down to
         * the ring's end as it is checked (one loop, not two: the frame's end
         * is the longest main-loop pass). A malformed stream flushes the ring,
         * so what moved past its end does not matter. */
        b = f[(uint8_t)(i + 3)];
        f[i] = b;
        switch (vs.st) {
            case VS_OP:
                switch (b) {
                    case OP_JOB_END:
                    case OP_SHEET_END:
                    case OP_HOME: done_at = (uint8_t)(i + 1); continue;
                    case OP_JOB_BEGIN: vs.n = 4; vs.st = VS_FIXED; continue;
                    case OP_SHEET_BEGIN:
                    case OP_SEEK_CARRIAGE:
                    case OP_SEEK_FEED: vs.n = 2; vs.st = VS_FIXED; continue;
                    case OP_PASS: vs.st = VS_FLAGS; continue;
                    default: return 1;
                }
            case VS_FIXED:
                if (--vs.n == 0) {
                    vs.st = VS_OP;
                    done_at = (uint8_t)(i + 1);
                }
                continue;
            case VS_FLAGS:
                if (b & (uint8_t)~PF_ALL) return 1;
                vs.flags = b;
                vs.st = (b & PF_SKIP) ? VS_SKIP : VS_FEED;
                continue;
            case VS_SKIP: vs.hi = b; vs.st = VS_FEED; continue; /* skip: checked against n */
            case VS_FEED: vs.st = (b & 0x80) ? VS_FEED2 : VS_FIRST; continue;
            case VS_FEED2: vs.st = VS_FIRST; continue;
            case VS_FIRST: vs.st = (b & 0x80) ? VS_FIRST2 : VS_N; continue;
            case VS_FIRST2: vs.st = VS_N; continue;
            case VS_N:
                if ((vs.flags & PF_SKIP) && vs.hi > b) return 1;
                vs.n = b;
                vs.st = b ? VS_ENTRY : VS_OP;
                done_at = (uint8_t)(i + 1); /* the header: the feed may start */
                continue;
            case VS_ENTRY:
                if (b & E_EXT) {
                    vs.st = VS_ENTRY2;
                    continue;
                }
                /* fall through */
            case VS_ENTRY2:
                vs.st = --vs.n ? VS_ENTRY : VS_OP;
                done_at = (uint8_t)(i + 1);
                continue;
            default: return 1;
        }
    }
    return 0;
}

/* The DATA check (docs/protocol.md): CRC-16 with poly 0x8BB7 over the ops,
 * nibble table. A polynomial other than the frame's, so an error pattern the
 * frame CRC misses is caught here: together about a 32-bit check. */
static FW_CODE uint16_t chk_nib[16] = {
    0x0000, 0x8BB7, 0x9CD9, 0x176E, 0xB205, 0x39B2, 0x2EDC, 0xA56B,
    0xEFBD, 0x640A, 0x7364, 0xF8D3, 0x5DB8, 0xD60F, 0xC161, 0x4AD6
};
#if FW_TARGET
/* The same in assembly: about 70 machine cycles a byte against about 120
 * from SDCC (every DATA byte goes through it as it arrives; crc16.c). */
uint16_t pass_crc_update(uint16_t c, uint8_t b) __naked {
    (void)c;
    (void)b;
    __asm
        mov   r2, dpl
        mov   r3, dph
        mov   dptr, #_chk_nib
        mov   a, _pass_crc_update_PARM_2
        swap  a
        ; c = (c << 4) ^ chk_nib[(c >> 12) ^ (a & 15)], high nibble then low
        anl   a, #0x0f
        mov   r4, a
        mov   a, r3
        swap  a
        anl   a, #0x0f
        xrl   a, r4
        rl    a
        mov   r4, a          ; byte offset of the entry
        mov   a, r2
        swap  a
        mov   r5, a
        anl   a, #0xf0
        mov   r2, a
        mov   a, r3
        swap  a
        anl   a, #0xf0
        mov   r3, a
        mov   a, r5
        anl   a, #0x0f
        orl   a, r3
        mov   r3, a
        mov   a, r4
        movc  a, @a+dptr     ; the entry, low byte first
        xrl   a, r2
        mov   r2, a
        mov   a, r4
        inc   a
        movc  a, @a+dptr
        xrl   a, r3
        mov   r3, a
        mov   a, _pass_crc_update_PARM_2
        anl   a, #0x0f
        mov   r4, a
        mov   a, r3
        swap  a
        anl   a, #0x0f
        xrl   a, r4
        rl    a
        mov   r4, a          ; byte offset of the entry
        mov   a, r2
        swap  a
        mov   r5, a
        anl   a, #0xf0
        mov   r2, a
        mov   a, r3
        swap  a
        anl   a, #0xf0
        mov   r3, a
        mov   a, r5
        anl   a, #0x0f
        orl   a, r3
        mov   r3, a
        mov   a, r4
        movc  a, @a+dptr     ; the entry, low byte first
        xrl   a, r2
        mov   r2, a
        mov   a, r4
        inc   a
        movc  a, @a+dptr
        xrl   a, r3
        mov   r3, a
        mov   dpl, r2
        mov   dph, r3
        ret
    __endasm;
}
#else
uint16_t pass_crc_update(uint16_t c, uint8_t b) {
    c = (uint16_t)((uint16_t)(c << 4) ^ NIB(chk_nib, (c >> 12) ^ (b >> 4)));
    c = (uint16_t)((uint16_t)(c << 4) ^ NIB(chk_nib, (c >> 12) ^ (b & 0x0F)));
    return c;
}
#endif

/* --- frames */

static void accept(void) { ++expected; }

/* PAUSE, or a new session in the middle of a job: a job under way pauses,
 * at once or (a phase under way) at its next safe point. */
static void hold_still(void) {
    if (fw_state == ST_RUNNING || fw_state == ST_WAITING || fw_state == ST_HOMING) {
        if (exec_busy()) fw_pause_req = 1;
        else fw_state = ST_PAUSED;
    }
}

static void on_hello(const FW_IDATA uint8_t *p, uint8_t len, uint8_t seq) {
    uint16_t n;
    if (len != 3 || p[2] != FW_PROTOCOL) {
        nak(NAK_BAD_PAYLOAD);
        return;
    }
    n = (uint16_t)(((uint16_t)p[0] << 8) | p[1]);
    /* A repeated HELLO of the same session is answered but changes nothing: a
     * stale duplicate must never rewind the sequence. */
    if (!session || n != nonce) {
        /* A new session: the host re-sends the job from the progress it is
         * told, so whatever is buffered is dropped and the job holds still. */
        fw_flush();
        if (fw_flags & FL_JOB_ACTIVE) hold_still();
        /* The rest of a pass under way was in the ring: without this the
         * executor took the new host's stream as that pass's strikes. */
        exec_drop_pass();
        session = 1;
        nonce = n;
        expected = (uint8_t)(seq + 1);
        fw_faults &= (uint8_t) ~(F_POWER_ON | F_WARM_RESET);
        if (fw_state == ST_FAULT && fw_faults == 0)
            fw_state = (fw_flags & FL_JOB_ACTIVE) ? ST_PAUSED : ST_IDLE;
    }
    rp_hello = 1;
    due();
}

static void on_data(FW_IDATA uint8_t *frame, uint8_t len) {
    uint16_t c;
    FW_IDATA uint8_t *p = frame + 3;
    if (len < 3 || len > FW_MAX_DATA) {
        nak(NAK_BAD_PAYLOAD);
        return;
    }
    len = (uint8_t)(len - 2); /* the ops; the check follows them */
    c = fw_rx_data_check(); /* folded in as the bytes arrived (decoder.c) */
    if (c != (uint16_t)(((uint16_t)p[len] << 8) | p[len + 1])) {
        /* The frame CRC passed but the DATA check did not: an error the frame
         * CRC missed. Dropped like a bad frame (its SEQ cannot be trusted);
         * the host sends it again. Never executed. */
        return;
    }
    if (len > fw_ring_free()) {
        nak(NAK_NO_SPACE);
        return;
    }
    if (check_ops(frame, len)) {
        /* A malformed op: a host bug, and the ops before it may end
         * mid-record. The ring is dropped with a fault; the host restarts
         * from the progress it is told. */
        fw_flush();
        fw_faults |= F_STREAM;
        fw_state = ST_FAULT;
        if (exec_busy()) exec_abort();
        nak(NAK_BAD_PAYLOAD);
        return;
    }
    accept();
    /* check_ops moved the ops to the ring's end. */
    if (done_at) fw_ops_done = (uint8_t)(fw_ops_end + done_at);
    fw_ops_end = (uint8_t)(fw_ops_end + len);
    fw_ack();
}

static uint16_t cfg_be16(const FW_IDATA uint8_t *p) {
    return (uint16_t)(((uint16_t)p[0] << 8) | p[1]);
}

static uint8_t on_configure(const FW_IDATA uint8_t *p, uint8_t len) {
    /* A homing interval below what the step interrupt can keep up with (64),
     * or a travel or hammer time of zero, would silently misbehave: refuse
     * it (big-endian fields, tested byte by byte). */
    if (len != 10 || !(p[0] | p[1]) || (!p[2] && p[3] < 64) || !(p[4] | p[5])) return 0;
    cfg_travel = cfg_be16(p);
    cfg_home_iv = cfg_be16(p + 2);
    cfg_hammer = cfg_be16(p + 4);
    cfg_settle = cfg_be16(p + 6);
    /* p[8..9], the keep-alive, is accepted but not enforced yet (README, "Not done"). */
    fw_flags |= FL_CONFIGURED;
    return 1;
}

void fw_frame(FW_IDATA uint8_t *f) {
    uint8_t len = f[0], seq = f[1], type = f[2], diff;
    const FW_IDATA uint8_t *p = f + 3;
    if (type == T_HELLO) {
        on_hello(p, len, seq);
        return;
    }
    if (!session) {
        nak(NAK_NO_SESSION);
        return;
    }
    diff = (uint8_t)(seq - expected);
    if (diff >= 128) {
        /* Already accepted: its ACK was lost. Acknowledge again, execute nothing. */
        fw_ack();
        return;
    }
    if (diff != 0) {
        nak(NAK_OUT_OF_ORDER);
        return;
    }
    if (type == T_DATA) {
        on_data(f, len);
        return;
    }
    if (type < T_CONFIGURE || type > T_KEEPALIVE) {
        nak(NAK_UNKNOWN_TYPE);
        return;
    }
    if (type == T_CONFIGURE) {
        if (!on_configure(p, len)) {
            nak(NAK_BAD_PAYLOAD);
            return;
        }
        accept();
        fw_ack();
        return;
    }
    if (len != 0) {
        nak(NAK_BAD_PAYLOAD);
        return;
    }
    accept();
    switch (type) {
        case T_PAUSE: hold_still(); break;
        case T_RESUME:
            fw_pause_req = 0;
            fw_faults &= (uint8_t) ~(F_HOST_TIMEOUT | F_LIMIT | F_HAMMER | F_STREAM | F_UNDERRUN);
            if (fw_paper_present()) fw_faults &= (uint8_t)~F_PAPER_OUT;
            if ((fw_faults & (F_PAPER_OUT | F_POWER_ON | F_WARM_RESET)) == 0 &&
                (fw_state == ST_PAUSED || fw_state == ST_FAULT))
                fw_state = (fw_flags & FL_JOB_ACTIVE) ? ST_RUNNING : ST_IDLE;
            break;
        case T_ABORT:
            exec_abort();
            fw_flush();
            fw_flags &= (uint8_t) ~(FL_JOB_ACTIVE | FL_PASS_ACTIVE);
            fw_pause_req = 0;
            if ((fw_faults & (F_POWER_ON | F_WARM_RESET)) == 0) {
                fw_faults = 0;
                fw_state = ST_IDLE;
            }
            break;
        case T_STATUS:
            rp_status = 1;
            due();
            return;
        default: break; /* KEEPALIVE: the ACK is the point */
    }
    fw_ack();
}
