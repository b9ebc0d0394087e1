/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_LINK_H
#define TACTUS_FW_LINK_H
#include "fw.h"

/* The link layer: sessions, the sliding window over the job ring, duplicates,
 * ACK/NAK, and the job-stream check done as DATA is copied in (docs/protocol.md).
 *
 * The ring is linear: ops occupy fw_buf[fw_ops_head, fw_ops_end); what follows
 * is the receive area. fw_ops_done marks the end of the last op that is
 * complete and checked: the executor never reads past it. fw_compact() moves
 * everything down when the executor has consumed bytes at the head, so no op
 * ever wraps around the end of the buffer. */
extern uint8_t fw_ops_head, fw_ops_done, fw_ops_end;

/* State shared with the executor (exec.c); kept over a warm reset. */
extern uint8_t fw_state, fw_faults, fw_strikes_in_pass, fw_skip;
extern uint16_t fw_job_id, fw_executed, fw_pass_index, fw_sheet;
extern int16_t fw_carriage, fw_feed;
extern uint8_t fw_flags;
/* Bytes of the stack ever used since boot (main.c). */
uint8_t fw_stack_used(void); /* FL_* except FL_PAPER, which is read from the pin */

/* Configuration (CONFIGURE). */
extern uint16_t cfg_travel, cfg_home_iv, cfg_hammer, cfg_settle;

/* Requests from the host to the executor. */
extern uint8_t fw_pause_req;

void fw_link_init(uint8_t warm);
/* Moves the ring down to fw_buf[0] (main loop, between bytes). */
void fw_compact(void);
/* Drops every buffered op (new session, abort, faults that end the stream). */
void fw_flush(void);
/* Sends an ACK now (state change, pass done). */
void fw_ack(void);
/* Sends an ACK if the host has not heard of room it may now use (the v2
 * rules: a whole frame's room first appears, or a frame's worth more). */
void fw_report_room(void);
/* Main loop: clears *paper out* once the sensor sees paper (the job then
 * shows paused until RESUME). */
void fw_poll_paper(void);
/* The executor ran out of data: report room the host has not been told of. */
void fw_starved(void);
uint8_t fw_ring_free(void);

/* Platform: a reply is due; start the transmitter if it is idle. It then
 * calls fw_reply_byte() for each byte (from the serial interrupt). */
void fw_tx_kick(void);
/* The next byte of the replies due, or -1 when there is none. */
int16_t fw_reply_byte(void);
/* Platform: whether paper is present (the status flags, RESUME, fw_poll_paper). */
uint8_t fw_paper_present(void);
/* Platform: the generated ramp table's identity (HELLO_REPLY). */
extern FW_CODE uint8_t fw_table_id[4];

/* The DATA check (docs/protocol.md): CRC-16 with poly 0x8BB7, init 0xFFFF,
 * over a DATA payload's ops; a polynomial other than the frame's, so an error
 * the frame CRC misses is not missed by this one for the same reason. */
uint16_t pass_crc_update(uint16_t c, uint8_t b);
#ifdef FW_EMU
extern uint8_t fw_rx_dropped; /* uart.c: receive bytes the full queue dropped */
#endif

#endif
