/* SPDX-License-Identifier: GPL-3.0-or-later */
#ifndef TACTUS_FW_DECODER_H
#define TACTUS_FW_DECODER_H
#include "fw.h"

/* The frame decoder, byte by byte, in the main loop.
 *
 * It receives in place: the bytes after a SYNC are stored from
 * fw_buf[fw_ops_end], the free end of the job ring, so a DATA payload is
 * already where it belongs and only moves down by its 3 header bytes. After a
 * bad CRC or an impossible LEN it rescans the stored bytes from the one after
 * the false SYNC, exactly as the host's FrameDecoder (core/encode/frame.cpp)
 * does, so garbage never hides a good frame. No recursion (SDCC's locals are
 * static) and no copy beyond one memmove per false start. */

extern FW_IDATA uint8_t fw_buf[FW_BUF_CAP];
extern uint8_t fw_ops_end; /* the receive area starts here */

/* Called for every frame whose CRC matched: frame points at LEN (SEQ, TYPE
 * and the payload follow). The callee may append the payload to the ring by
 * moving it down to frame[0] and adding LEN to fw_ops_end. */
void fw_frame(FW_IDATA uint8_t *frame);

void fw_rx_byte(uint8_t b);
void fw_rx_reset(void);
/* Whether a frame is partly received (the ring must not be moved then). */
uint8_t fw_rx_busy(void);
/* Bytes currently stored in the receive area. */
uint8_t fw_rx_fill(void);
/* The DATA check over the ops of the frame fw_frame() is handed (a DATA
 * frame's payload less its last two bytes), computed as its bytes arrived. */
uint16_t fw_rx_data_check(void);


#endif
