/* SPDX-License-Identifier: GPL-3.0-or-later */
#include "hal_native.h"

#include "../src/exec.h"
#include "../src/link.h"

uint8_t native_tx[4096];
size_t native_tx_len;
uint8_t native_paper = 1;
unsigned native_aborts;

const uint8_t fw_table_id[4] = {0x12, 0x34, 0x56, 0x78};

/* Replies are pulled by the test (native_drain), as the UART would. */
void fw_tx_kick(void) {}
void native_drain(void) {
    int16_t b;
    while ((b = fw_reply_byte()) >= 0)
        if (native_tx_len < sizeof native_tx) native_tx[native_tx_len++] = (uint8_t)b;
}
uint8_t fw_paper_present(void) { return native_paper; }
/* No motion natively: nothing is ever under way. */
void exec_abort(void) { ++native_aborts; }
uint8_t exec_busy(void) { return 0; }
void exec_drop_pass(void) {}
uint8_t fw_stack_used(void) { return 0; }
