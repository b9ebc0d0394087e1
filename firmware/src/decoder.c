/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "decoder.h"

#include "crc16.h"
#include "link.h"

static uint8_t rx_fill; /* bytes stored from LEN on, at fw_buf[fw_ops_end] */
static FW_BIT rx_sync; /* a SYNC was seen: collecting a candidate frame */
/* The frame CRC over LEN..PAYLOAD and a DATA payload's check over its ops,
 * kept up to date byte by byte as the bytes arrive: computed whole when the
 * frame ends, they took about 10,000 machine cycles of one main-loop pass,
 * long enough to make the executor late for a phase (the schedule is the
 * timer's only if the main loop starts each phase within a few thousand
 * cycles; docs/protocol.md, "Timing"). */
static uint16_t rx_crc, rx_chk;
/* Read from the candidate's header when its TYPE is stored: where the frame
 * CRC ends (LEN + 3) and whether it is DATA, so that a payload byte takes the
 * short path in fw_rx_byte (at the top step rate the main loop has about 280
 * of its own cycles a byte at 9600 baud: firmware/README.md, "Main loop"). */
static uint8_t rx_end;
static FW_BIT rx_data;

/* Folds the stored byte at index i (0 = LEN) into the running checks. */
static void fold(uint8_t i, uint8_t b) {
    if (i == 0) {
        rx_crc = 0xFFFF;
        rx_chk = 0xFFFF;
    } else if (i == 2) {
        rx_end = (uint8_t)(fw_buf[fw_ops_end] + 3);
        rx_data = b == T_DATA;
    }
    if (i < 3 || i < rx_end) rx_crc = crc16_update(rx_crc, b);
    /* Ops: payload bytes 3.. up to the 2-byte check at the payload's end. */
    if (i >= 3 && rx_data && i < (uint8_t)(rx_end - 2)) rx_chk = pass_crc_update(rx_chk, b);
}

/* After the stored bytes changed under the candidate (a rescan). */
static void refold(void) {
    uint8_t i;
    for (i = 0; i < rx_fill; ++i) fold(i, fw_buf[fw_ops_end + i]);
}

uint16_t fw_rx_data_check(void) { return rx_chk; }

void fw_rx_reset(void) {
    rx_fill = 0;
    rx_sync = 0;
}

uint8_t fw_rx_busy(void) { return rx_sync; }
uint8_t fw_rx_fill(void) { return rx_fill; }

/* Moves n bytes down (dst < src): the receive area only ever shifts toward
 * its start. */
static void move_down(FW_IDATA uint8_t *dst, const FW_IDATA uint8_t *src, uint8_t n) {
    while (n--) *dst++ = *src++;
}

/* Drops the first `skip` stored bytes and looks for a SYNC in the rest; what
 * follows it becomes the new candidate. Bytes before it are garbage. */
static void resync(uint8_t skip) {
    FW_IDATA uint8_t *r = fw_buf + fw_ops_end;
    uint8_t i = skip;
    while (i < rx_fill && r[i] != FW_SYNC) ++i;
    if (i >= rx_fill) {
        rx_fill = 0;
        rx_sync = 0;
        return;
    }
    ++i; /* past the SYNC */
    move_down(r, r + i, (uint8_t)(rx_fill - i));
    rx_fill = (uint8_t)(rx_fill - i);
    rx_sync = 1;
    refold();
}

/* Evaluates the stored bytes until a frame needs more of them. */
static inline void scan(void) {
    for (;;) {
        FW_IDATA uint8_t *r;
        uint8_t len, room, total;
        if (!rx_sync || rx_fill == 0) return;
        r = fw_buf + fw_ops_end;
        room = (uint8_t)(FW_BUF_CAP - fw_ops_end);
        len = r[0];
        total = (uint8_t)(len + FW_FRAME_OVERHEAD);
        /* A LEN the wire never carries, or one that cannot be stored: a false
         * SYNC (the host never sends more than it was offered, plus the slack
         * a control frame needs). */
        if (len > FW_WIRE_MAX_PAYLOAD || total > room) {
            resync(0); /* from the LEN byte: it may itself be a SYNC */
            continue;
        }
        if (rx_fill < total) return;
        if (rx_crc != (uint16_t)(((uint16_t)r[total - 2] << 8) | r[total - 1])) {
            resync(0); /* from the LEN byte: it may itself be a SYNC */
            continue;
        }
        {
            /* Bytes after the frame arrived during a rescan: keep them, they
             * are scanned for the next SYNC once the frame is handled. */
            uint8_t left = (uint8_t)(rx_fill - total);
            uint8_t old_end = fw_ops_end;
            rx_fill = 0;
            rx_sync = 0;
            fw_frame(r);
            if (left) {
                FW_IDATA uint8_t *from = fw_buf + old_end + total;
                r = fw_buf + fw_ops_end;
                move_down(r, from, left);
                rx_fill = left;
                resync(0);
            }
        }
    }
}

void fw_rx_byte(uint8_t b) {
    uint8_t i;
    if (!rx_sync) {
        if (b == FW_SYNC) {
            rx_sync = 1;
            rx_fill = 0;
        }
        return;
    }
    /* scan() rejects a LEN whose frame would not fit, so this never overflows. */
    i = rx_fill;
    fw_buf[fw_ops_end + i] = b;
    ++rx_fill;
    if (i >= 3 && i < rx_end) {
        /* Inside the payload: LEN was checked (scan, at the first byte) and
         * the frame is not whole yet, so only the checks move on. */
        rx_crc = crc16_update(rx_crc, b);
        if (rx_data && i < (uint8_t)(rx_end - 2)) rx_chk = pass_crc_update(rx_chk, b);
        return;
    }
    fold(i, b);
    scan();
}
