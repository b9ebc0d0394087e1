/* SPDX-License-Identifier: GPL-3.0-or-later */
/* The firmware's link layer, compiled natively: frames, CRC, sessions,
 * window, duplicates, ACK/NAK and the job-stream check, driven byte by byte
 * as the UART delivers them. Build and run: make -C firmware test */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../firmware/native/hal_native.h"
#include "../../firmware/src/crc16.h"
#include "../../firmware/src/decoder.h"
#include "../../firmware/src/exec.h"
#include "../../firmware/src/link.h"

static int failures;
static const char* current = "";
#define CHECK(cond)                                                              \
    do {                                                                         \
        if (!(cond)) {                                                           \
            fprintf(stderr, "%s:%d (%s, in %s): check failed: %s\n", __FILE__, __LINE__, __func__, current, #cond); \
            ++failures;                                                          \
        }                                                                        \
    } while (0)

/* Bit by bit, from the definition: the reference for the firmware's tables. */
static uint16_t crc_ref(const uint8_t* p, size_t n, uint16_t crc) {
    for (size_t i = 0; i < n; ++i) {
        crc ^= (uint16_t)(p[i] << 8);
        for (int k = 0; k < 8; ++k) crc = (uint16_t)((crc & 0x8000) ? ((unsigned)crc << 1) ^ 0x1021U : (unsigned)crc << 1);
    }
    return crc;
}
static uint16_t pass_ref(const uint8_t* p, size_t n) {
    uint16_t crc = 0xFFFF;
    for (size_t i = 0; i < n; ++i) {
        crc ^= (uint16_t)(p[i] << 8);
        for (int k = 0; k < 8; ++k) crc = (uint16_t)((crc & 0x8000) ? ((unsigned)crc << 1) ^ 0x8BB7U : (unsigned)crc << 1);
    }
    return crc;
}

static size_t frame(uint8_t* out, uint8_t seq, uint8_t type, const uint8_t* p, uint8_t len) {
    out[0] = FW_SYNC;
    out[1] = len;
    out[2] = seq;
    out[3] = type;
    if (len) memcpy(out + 4, p, len);
    uint16_t c = crc_ref(out + 1, (size_t)len + 3, 0xFFFF);
    out[4 + len] = (uint8_t)(c >> 8);
    out[5 + len] = (uint8_t)c;
    return (size_t)len + 6;
}

/* Bytes in, one at a time as the UART delivers them; the replies due after
 * each are sent before the next byte arrives (as at 9600 baud they would be). */
static void feed(const uint8_t* b, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        fw_rx_byte(b[i]);
        native_drain();
    }
}
/* A frame; DATA gets its check (CRC-16/0x8BB7 over the ops) appended. */
static void send(uint8_t seq, uint8_t type, const uint8_t* p, uint8_t len) {
    uint8_t buf[128], payload[100];
    if (len) memcpy(payload, p, len);
    if (type == T_DATA) {
        uint16_t c = pass_ref(p, len);
        payload[len++] = (uint8_t)(c >> 8);
        payload[len++] = (uint8_t)c;
    }
    feed(buf, frame(buf, seq, type, payload, len));
}

/* The replies sent since the last call, parsed and CRC-checked. */
struct reply {
    uint8_t seq, type, len, p[64];
};
static int replies(struct reply* out, int max) {
    int n = 0;
    size_t i = 0;
    while (i < native_tx_len && n < max) {
        CHECK(native_tx[i] == FW_SYNC);
        uint8_t len = native_tx[i + 1];
        CHECK(i + 6u + len <= native_tx_len);
        uint16_t c = crc_ref(native_tx + i + 1, (size_t)len + 3, 0xFFFF);
        CHECK(native_tx[i + 4 + len] == (uint8_t)(c >> 8) && native_tx[i + 5 + len] == (uint8_t)c);
        out[n].len = len;
        out[n].seq = native_tx[i + 2];
        out[n].type = native_tx[i + 3];
        memcpy(out[n].p, native_tx + i + 4, len);
        ++n;
        i += 6u + len;
    }
    native_tx_len = 0;
    return n;
}
static struct reply one_reply(void) {
    struct reply r[8];
    int n = replies(r, 8);
    CHECK(n == 1);
    if (n < 1) memset(&r[0], 0, sizeof r[0]);
    return r[0];
}

static void reset_all(void) {
    fw_faults = 0;
    fw_state = ST_IDLE;
    fw_flags = 0;
    fw_link_init(0);
    native_tx_len = 0;
}

static void hello(uint8_t seq, uint16_t nonce) {
    uint8_t p[3] = {(uint8_t)(nonce >> 8), (uint8_t)nonce, FW_PROTOCOL};
    send(seq, T_HELLO, p, 3);
}

static void test_crc(void) {
    const uint8_t check[] = "123456789";
    CHECK(crc16_block((const uint8_t*)check, 9, 0xFFFF) == 0x29B1);
    uint8_t data[256];
    for (int i = 0; i < 256; ++i) data[i] = (uint8_t)(i * 37 + 11);
    for (int n = 0; n <= 255; n += 17) CHECK(crc16_block(data, (uint8_t)n, 0xFFFF) == crc_ref(data, (size_t)n, 0xFFFF));
    uint16_t c = 0xFFFF;
    for (int i = 0; i < 40; ++i) c = pass_crc_update(c, data[i]);
    CHECK(c == pass_ref(data, 40)); /* the DATA check's nibble table against the definition */
}

static void test_session(void) {
    reset_all();
    send(0, T_KEEPALIVE, NULL, 0);
    struct reply r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_NO_SESSION);

    hello(5, 0xBEEF);
    r = one_reply();
    CHECK(r.type == T_HELLO_REPLY && r.seq == 6 && r.len == 13);
    CHECK(r.p[0] == FW_PROTOCOL && r.p[4] == FW_RING_BYTES && r.p[5] == FW_MAX_DATA &&
          r.p[6] == FW_WINDOW_FRAMES);
    CHECK(memcmp(r.p + 7, fw_table_id, 4) == 0);

    /* A HELLO for another protocol version is refused. */
    uint8_t old[3] = {0, 1, 2};
    send(9, T_HELLO, old, 3);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_BAD_PAYLOAD && r.seq == 6);

    send(6, T_KEEPALIVE, NULL, 0);
    r = one_reply();
    CHECK(r.type == T_ACK && r.seq == 7 && r.p[0] == FW_RING_BYTES);

    /* The same HELLO again (a retransmission) changes nothing. */
    hello(5, 0xBEEF);
    r = one_reply();
    CHECK(r.type == T_HELLO_REPLY && r.seq == 7);
    /* A new nonce opens a new session at its own SEQ. */
    hello(200, 0x0101);
    r = one_reply();
    CHECK(r.type == T_HELLO_REPLY && r.seq == 201);
}

static void test_window(void) {
    reset_all();
    hello(0, 1);
    (void)one_reply();
    const uint8_t job[5] = {OP_JOB_BEGIN, 0, 7, 0, 0};
    send(1, T_DATA, job, 5);
    struct reply r = one_reply();
    CHECK(r.type == T_ACK && r.seq == 2 && r.p[0] == FW_RING_BYTES - 5);
    CHECK(fw_ops_end - fw_ops_head == 5 && fw_ops_done == fw_ops_end);
    CHECK(memcmp(fw_buf + fw_ops_head, job, 5) == 0);

    /* A duplicate (its ACK was lost) is acknowledged again, never executed. */
    send(1, T_DATA, job, 5);
    r = one_reply();
    CHECK(r.type == T_ACK && r.seq == 2 && r.p[0] == FW_RING_BYTES - 5);
    CHECK(fw_ops_end - fw_ops_head == 5);

    /* Ahead: a frame was lost. */
    send(4, T_DATA, job, 5);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_OUT_OF_ORDER && r.seq == 2);


    /* More than the window offers: the first frame fits, the second cannot
     * even be stored (the receive area is the ring's free end plus a slack
     * for control frames), so it is dropped unheard; a host that keeps to
     * the window never sends it. */
    uint8_t big[FW_MAX_DATA - 2];
    memset(big, OP_JOB_END, sizeof big);
    uint8_t seq = 2;
    send(seq, T_DATA, big, FW_MAX_DATA - 2);
    r = one_reply();
    CHECK(r.type == T_ACK && r.p[0] == FW_RING_BYTES - 5 - (FW_MAX_DATA - 2));
    ++seq;
    const uint8_t before = fw_ops_end;
    uint8_t raw[128];
    uint8_t payload[FW_MAX_DATA];
    memcpy(payload, big, sizeof big);
    uint16_t ck = pass_ref(big, sizeof big);
    payload[sizeof big] = (uint8_t)(ck >> 8);
    payload[sizeof big + 1] = (uint8_t)ck;
    feed(raw, frame(raw, seq, T_DATA, payload, FW_MAX_DATA));
    CHECK(native_tx_len == 0 && fw_ops_end == before);
    /* One that can be stored but exceeds the free ring is refused. */
    uint8_t mid[12];
    memset(mid, OP_JOB_END, sizeof mid);
    send(seq, T_DATA, mid, sizeof mid);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_NO_SPACE && fw_ops_end == before);
    /* Control frames still fit when the ring is full (the slack). */
    send(seq, T_STATUS, NULL, 0);
    r = one_reply();
    CHECK(r.type == T_STATUS_REPLY && r.len == 25);
    /* Unknown frame type. */
    send((uint8_t)(seq + 1), 0x33, NULL, 0);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_UNKNOWN_TYPE);

    /* Unknown op (a host bug): refused, and the stream is dropped with a
     * fault, since the ops before it may have been cut mid-record. */
    const uint8_t bad[2] = {0x11, 0x99};
    send((uint8_t)(seq + 1), T_DATA, bad, 2);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_BAD_PAYLOAD && r.seq == (uint8_t)(seq + 1));
    CHECK((r.p[5] & F_STREAM) && fw_ops_end == fw_ops_head);
}

/* A pass record: 0x14 flags feed first n entries. */
static size_t pass_record(uint8_t* out, uint8_t n) {
    size_t k = 0;
    out[k++] = OP_PASS;
    out[k++] = 0;
    out[k++] = 2;  /* feed 2 grid units */
    out[k++] = 40; /* first move */
    out[k++] = n;
    for (uint8_t i = 0; i < n; ++i) out[k++] = (uint8_t)((i & 1 ? E_CONCAVE : 0) | 10);
    return k;
}

static void test_pass_stream(void) {
    reset_all();
    hello(0, 1);
    (void)one_reply();
    uint8_t rec[64];
    size_t n = pass_record(rec, 20);
    /* A pass streams: its header, then each strike entry, becomes executable
     * as it arrives, not only when the whole record is in. */
    send(1, T_DATA, rec, 3);
    (void)one_reply();
    CHECK(fw_ops_done == fw_ops_head); /* the header is not whole yet */
    send(2, T_DATA, rec + 3, 7); /* n, then 5 entries */
    struct reply r = one_reply();
    CHECK(r.type == T_ACK && r.p[4] == 0);
    CHECK(fw_ops_done == fw_ops_end && fw_ops_end - fw_ops_head == 10);
    send(3, T_DATA, rec + 10, (uint8_t)(n - 10));
    r = one_reply();
    CHECK(r.type == T_ACK && r.seq == 4 && (size_t)(fw_ops_end - fw_ops_head) == n && fw_ops_done == fw_ops_end);

    /* A DATA frame whose frame CRC is right but whose check is not (an error
     * the frame CRC missed) is dropped unheard: no reply, nothing stored. */
    uint8_t payload[8] = {OP_JOB_END, OP_JOB_END, 0, 0};
    uint16_t c = pass_ref(payload, 2) ^ 0x0400;
    payload[2] = (uint8_t)(c >> 8);
    payload[3] = (uint8_t)c;
    uint8_t buf[32];
    const uint8_t end_before = fw_ops_end;
    feed(buf, frame(buf, 4, T_DATA, payload, 4));
    CHECK(native_tx_len == 0 && fw_ops_end == end_before);
    send(4, T_KEEPALIVE, NULL, 0); /* the same SEQ is still expected */
    CHECK(one_reply().seq == 5);

    /* Unknown flag bits: malformed, the stream is dropped with a fault. */
    reset_all();
    hello(0, 2);
    (void)one_reply();
    uint8_t hdr2[5] = {OP_PASS, 0x80, 0, 0, 1};
    send(1, T_DATA, hdr2, 5);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_BAD_PAYLOAD && (r.p[5] & F_STREAM));
    /* A skip larger than the pass: malformed. */
    hello(0, 3);
    (void)one_reply();
    uint8_t hdr3[6] = {OP_PASS, PF_SKIP, 5, 0, 0, 3};
    send(1, T_DATA, hdr3, 6);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_BAD_PAYLOAD);
}

static void test_resync(void) {
    reset_all();
    hello(0, 1);
    (void)one_reply();
    /* A false SYNC whose LEN swallows the real frame: the real frame is found
     * when the false one's CRC fails, by rescanning what was stored. */
    uint8_t buf[64];
    const uint8_t garbage[3] = {0x55, FW_SYNC, 12};
    feed(garbage, 3);
    size_t n = frame(buf, 1, T_KEEPALIVE, NULL, 0);
    feed(buf, n);
    CHECK(native_tx_len == 0); /* still inside the false frame */
    n = frame(buf, 2, T_KEEPALIVE, NULL, 0);
    feed(buf, n);
    CHECK(native_tx_len == 0); /* 13 of the false frame's 17 bytes */
    n = frame(buf, 3, T_KEEPALIVE, NULL, 0);
    feed(buf, n);
    /* The false frame's 17th byte is the 4th of the third frame: the rescan
     * it triggers accepts the first two (their ACKs merge into one, SEQ 3),
     * and the third completes two bytes later. */
    struct reply r[4];
    int got = replies(r, 4);
    CHECK(got == 2);
    if (got == 2) {
        CHECK(r[0].type == T_ACK && r[0].seq == 3);
        CHECK(r[1].type == T_ACK && r[1].seq == 4);
    }
    /* A corrupted frame is dropped silently. */
    n = frame(buf, 4, T_KEEPALIVE, NULL, 0);
    buf[3] ^= 0x01;
    feed(buf, n);
    CHECK(native_tx_len == 0);
    /* An impossible LEN is a false start at once. */
    const uint8_t oversize[2] = {FW_SYNC, 200};
    feed(oversize, 2);
    n = frame(buf, 4, T_KEEPALIVE, NULL, 0);
    feed(buf, n);
    CHECK(one_reply().seq == 5);
    /* A lone SYNC before a frame: the frame's own SYNC is read as LEN (0x7E,
     * too long), and the rescan must start at that byte, which is a SYNC
     * (found by fuzzing against the host's decoder). */
    const uint8_t lone[1] = {FW_SYNC};
    feed(lone, 1);
    n = frame(buf, 5, T_KEEPALIVE, NULL, 0);
    feed(buf, n);
    CHECK(one_reply().seq == 6);
}

static void test_control(void) {
    reset_all();
    hello(0, 1);
    (void)one_reply();
    uint8_t cfg[10] = {0x45, 0x60, 0x01, 0x20, 0x0E, 0x66, 0x1C, 0xCC, 0x07, 0xD0};
    send(1, T_CONFIGURE, cfg, 10);
    struct reply r = one_reply();
    CHECK(r.type == T_ACK && r.seq == 2 && (fw_flags & FL_CONFIGURED));
    CHECK(cfg_travel == 0x4560 && cfg_home_iv == 0x0120 && cfg_hammer == 0x0E66 &&
          cfg_settle == 0x1CCC);
    cfg[3] = 10; /* homing interval below the step interrupt's floor */
    cfg[2] = 0;
    send(2, T_CONFIGURE, cfg, 10);
    r = one_reply();
    CHECK(r.type == T_NAK && r.p[0] == NAK_BAD_PAYLOAD);
    send(2, T_CONFIGURE, cfg, 9);
    CHECK(one_reply().type == T_NAK);

    /* Pause before any job: nothing runs, state stays idle. Abort clears faults. */
    fw_faults = F_HAMMER;
    fw_state = ST_FAULT;
    send(2, T_RESUME, NULL, 0);
    r = one_reply();
    CHECK(r.type == T_ACK && r.p[4] == 0 && r.p[3] == ST_IDLE);
    /* Paper out stays while there is no paper. */
    native_paper = 0;
    fw_faults = F_PAPER_OUT;
    fw_state = ST_FAULT;
    send(3, T_RESUME, NULL, 0);
    r = one_reply();
    CHECK(r.p[4] == F_PAPER_OUT && r.p[3] == ST_FAULT);
    native_paper = 1;
    send(4, T_ABORT, NULL, 0);
    r = one_reply();
    CHECK(r.p[4] == 0 && r.p[3] == ST_IDLE && native_aborts > 0);
    /* A control frame with a payload is malformed. */
    send(5, T_PAUSE, cfg, 1);
    CHECK(one_reply().type == T_NAK);
}

/* Paper loaded while *paper out* stands (docs/protocol.md, "Paper out"): the
 * main loop's poll sees the sensor change, clears the fault and shows paused
 * with an ACK, without a RESUME; the host then resumes. (The firmware kept
 * the fault until RESUME, and the host, waiting for it to clear, gave up.) */
static void test_paper_loaded(void) {
    reset_all();
    hello(0, 7);
    (void)one_reply();
    /* A job whose SHEET_BEGIN found no paper (exec.c). */
    native_paper = 0;
    fw_flags = FL_JOB_ACTIVE;
    fw_faults = F_PAPER_OUT;
    fw_state = ST_FAULT;
    for (int i = 0; i < 3; ++i) fw_poll_paper(); /* no paper yet: nothing changes, nothing is said */
    native_drain();
    struct reply r[4];
    CHECK(replies(r, 4) == 0);
    CHECK(fw_faults == F_PAPER_OUT && fw_state == ST_FAULT);
    /* The operator loads paper. */
    native_paper = 1;
    fw_poll_paper();
    native_drain();
    CHECK(replies(r, 4) == 1);
    CHECK(r[0].type == T_ACK && r[0].p[4] == 0 && r[0].p[3] == ST_PAUSED);
    fw_poll_paper(); /* once only */
    native_drain();
    CHECK(replies(r, 4) == 0);
    send(1, T_STATUS, NULL, 0);
    r[0] = one_reply();
    CHECK(r[0].type == T_STATUS_REPLY && r[0].p[3] == ST_PAUSED && r[0].p[4] == 0 && (r[0].p[8] & FL_PAPER));
    send(2, T_RESUME, NULL, 0);
    r[0] = one_reply();
    CHECK(r[0].type == T_ACK && r[0].p[3] == ST_RUNNING && r[0].p[4] == 0);

    /* With another fault standing, loading paper clears paper out only: the
     * job stays in its fault. */
    native_paper = 0;
    fw_faults = F_PAPER_OUT | F_WARM_RESET;
    fw_state = ST_FAULT;
    native_paper = 1;
    fw_poll_paper();
    native_drain();
    CHECK(replies(r, 4) == 1);
    CHECK(r[0].p[4] == F_WARM_RESET && r[0].p[3] == ST_FAULT);
    fw_faults = 0;
    fw_flags = 0;
}

int main(void) {
    current = "test_crc";
    test_crc();
    current = "test_session";
    test_session();
    current = "test_window";
    test_window();
    current = "test_pass_stream";
    test_pass_stream();
    current = "test_resync";
    test_resync();
    current = "test_control";
    test_control();
    current = "test_paper_loaded";
    test_paper_loaded();
    if (failures) {
        fprintf(stderr, "%d check(s) failed\n", failures);
        return 1;
    }
    printf("firmware link tests passed\n");
    return 0;
}
