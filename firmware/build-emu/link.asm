;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module link
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _pass_crc_update_PARM_2
	.globl _exec_busy
	.globl _exec_abort
	.globl _fw_rx_fill
	.globl _fw_rx_reset
	.globl _fw_paper_present
	.globl _fw_tx_kick
	.globl _fw_stack_used
	.globl _fw_buf
	.globl _fw_pause_req
	.globl _cfg_settle
	.globl _cfg_hammer
	.globl _cfg_home_iv
	.globl _cfg_travel
	.globl _fw_feed
	.globl _fw_carriage
	.globl _fw_sheet
	.globl _fw_pass_index
	.globl _fw_executed
	.globl _fw_job_id
	.globl _fw_flags
	.globl _fw_skip
	.globl _fw_strikes_in_pass
	.globl _fw_faults
	.globl _fw_state
	.globl _fw_ops_end
	.globl _fw_ops_done
	.globl _fw_ops_head
	.globl _fw_ring_free
	.globl _fw_flush
	.globl _fw_compact
	.globl _fw_link_init
	.globl _fw_ack
	.globl _fw_reply_byte
	.globl _fw_report_room
	.globl _fw_starved
	.globl _pass_crc_update
	.globl _fw_frame
;--------------------------------------------------------
; special function registers
;--------------------------------------------------------
	.area RSEG    (ABS,DATA)
	.org 0x0000
;--------------------------------------------------------
; special function bits
;--------------------------------------------------------
	.area RSEG    (ABS,DATA)
	.org 0x0000
;--------------------------------------------------------
; overlayable register banks
;--------------------------------------------------------
	.area REG_BANK_0	(REL,OVR,DATA)
	.ds 8
;--------------------------------------------------------
; internal ram data
;--------------------------------------------------------
	.area DSEG    (DATA)
_fw_ops_head::
	.ds 1
_fw_ops_done::
	.ds 1
_fw_ops_end::
	.ds 1
_fw_state::
	.ds 1
_fw_faults::
	.ds 1
_fw_strikes_in_pass::
	.ds 1
_fw_skip::
	.ds 1
_fw_flags::
	.ds 1
_fw_job_id::
	.ds 2
_fw_executed::
	.ds 2
_fw_pass_index::
	.ds 2
_fw_sheet::
	.ds 2
_fw_carriage::
	.ds 2
_fw_feed::
	.ds 2
_cfg_travel::
	.ds 2
_cfg_home_iv::
	.ds 2
_cfg_hammer::
	.ds 2
_cfg_settle::
	.ds 2
_fw_pause_req::
	.ds 1
_session:
	.ds 1
_expected:
	.ds 1
_nonce:
	.ds 2
_reported:
	.ds 1
_rp_reason:
	.ds 1
_rp_type:
	.ds 1
_rp_pos:
	.ds 1
_rp_crc:
	.ds 2
_rp_stash:
	.ds 2
_vs:
	.ds 4
_done_at:
	.ds 1
_on_hello_PARM_2:
	.ds 1
_on_hello_PARM_3:
	.ds 1
_on_data_PARM_2:
	.ds 1
_on_data_frame_65536_85:
	.ds 1
_on_data_c_65536_86:
	.ds 2
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
	.area	OSEG    (OVR,DATA)
	.area	OSEG    (OVR,DATA)
	.area	OSEG    (OVR,DATA)
_check_ops_PARM_2:
	.ds 1
	.area	OSEG    (OVR,DATA)
_pass_crc_update_PARM_2:
	.ds 1
	.area	OSEG    (OVR,DATA)
_on_configure_PARM_2:
	.ds 1
_on_configure_p_65536_93:
	.ds 1
_on_configure_sloc0_1_0:
	.ds 2
_on_configure_sloc1_1_0:
	.ds 2
_on_configure_sloc2_1_0:
	.ds 2
;--------------------------------------------------------
; indirectly addressable internal ram data
;--------------------------------------------------------
	.area ISEG    (DATA)
_fw_buf::
	.ds 64
;--------------------------------------------------------
; absolute internal ram data
;--------------------------------------------------------
	.area IABS    (ABS,DATA)
	.area IABS    (ABS,DATA)
;--------------------------------------------------------
; bit data
;--------------------------------------------------------
	.area BSEG    (BIT)
_rp_ack:
	.ds 1
_rp_nak:
	.ds 1
_rp_status:
	.ds 1
_rp_hello:
	.ds 1
_fw_ring_free_sloc0_1_0:
	.ds 1
_ack_field_sloc0_1_0:
	.ds 1
;--------------------------------------------------------
; paged external ram data
;--------------------------------------------------------
	.area PSEG    (PAG,XDATA)
;--------------------------------------------------------
; external ram data
;--------------------------------------------------------
	.area XSEG    (XDATA)
;--------------------------------------------------------
; absolute external ram data
;--------------------------------------------------------
	.area XABS    (ABS,XDATA)
;--------------------------------------------------------
; external initialized ram data
;--------------------------------------------------------
	.area XISEG   (XDATA)
	.area HOME    (CODE)
	.area GSINIT0 (CODE)
	.area GSINIT1 (CODE)
	.area GSINIT2 (CODE)
	.area GSINIT3 (CODE)
	.area GSINIT4 (CODE)
	.area GSINIT5 (CODE)
	.area GSINIT  (CODE)
	.area GSFINAL (CODE)
	.area CSEG    (CODE)
;--------------------------------------------------------
; global & static initialisations
;--------------------------------------------------------
	.area HOME    (CODE)
	.area GSINIT  (CODE)
	.area GSFINAL (CODE)
	.area GSINIT  (CODE)
;--------------------------------------------------------
; Home
;--------------------------------------------------------
	.area HOME    (CODE)
	.area HOME    (CODE)
;--------------------------------------------------------
; code
;--------------------------------------------------------
	.area CSEG    (CODE)
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_ring_free'
;------------------------------------------------------------
;used                      Allocated to registers r7 
;------------------------------------------------------------
;	src/link.c:49: uint8_t fw_ring_free(void) {
;	-----------------------------------------
;	 function fw_ring_free
;	-----------------------------------------
_fw_ring_free:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
;	src/link.c:50: uint8_t used = (uint8_t)(fw_ops_end - fw_ops_head);
	mov	a,_fw_ops_end
	clr	c
	subb	a,_fw_ops_head
	mov	r7,a
;	src/link.c:51: return used >= FW_RING_BYTES ? 0 : (uint8_t)(FW_RING_BYTES - used);
	cjne	r7,#0x2f,00109$
00109$:
	mov	_fw_ring_free_sloc0_1_0,c
	jc	00103$
	mov	r5,#0x00
	mov	r6,#0x00
	sjmp	00104$
00103$:
	mov	a,#0x2f
	clr	c
	subb	a,r7
	mov	r7,a
	mov	r5,a
	mov	r6,#0x00
00104$:
	mov	dpl,r5
;	src/link.c:52: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_flush'
;------------------------------------------------------------
;	src/link.c:54: void fw_flush(void) {
;	-----------------------------------------
;	 function fw_flush
;	-----------------------------------------
_fw_flush:
;	src/link.c:55: fw_ops_head = fw_ops_end;
	mov	_fw_ops_head,_fw_ops_end
;	src/link.c:56: fw_ops_done = fw_ops_end;
	mov	_fw_ops_done,_fw_ops_end
;	src/link.c:57: vs.st = VS_OP;
	mov	_vs,#0x00
;	src/link.c:58: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_compact'
;------------------------------------------------------------
;shift                     Allocated to registers r7 
;n                         Allocated to registers r6 
;i                         Allocated to registers r5 
;------------------------------------------------------------
;	src/link.c:60: void fw_compact(void) {
;	-----------------------------------------
;	 function fw_compact
;	-----------------------------------------
_fw_compact:
;	src/link.c:61: uint8_t shift = fw_ops_head, n, i;
;	src/link.c:62: if (shift == 0) return;
	mov	a,_fw_ops_head
	mov	r7,a
	jnz	00102$
	ret
00102$:
;	src/link.c:64: n = (uint8_t)(fw_ops_end - shift + fw_rx_fill());
	mov	a,_fw_ops_end
	clr	c
	subb	a,r7
	mov	r6,a
	push	ar7
	push	ar6
	lcall	_fw_rx_fill
	mov	r5,dpl
	pop	ar6
	pop	ar7
	mov	a,r5
	add	a,r6
	mov	r6,a
;	src/link.c:65: for (i = 0; i < n; ++i) fw_buf[i] = fw_buf[i + shift];
	mov	r5,#0x00
00105$:
	clr	c
	mov	a,r5
	subb	a,r6
	jnc	00103$
	mov	a,r5
	add	a,#_fw_buf
	mov	r1,a
	mov	a,r7
	add	a,r5
	add	a,#_fw_buf
	mov	r0,a
	mov	ar4,@r0
	mov	@r1,ar4
	inc	r5
	sjmp	00105$
00103$:
;	src/link.c:66: fw_ops_head = 0;
	mov	_fw_ops_head,#0x00
;	src/link.c:67: fw_ops_done = (uint8_t)(fw_ops_done - shift);
	mov	a,_fw_ops_done
	clr	c
	subb	a,r7
	mov	_fw_ops_done,a
;	src/link.c:68: fw_ops_end = (uint8_t)(fw_ops_end - shift);
	mov	a,_fw_ops_end
	clr	c
	subb	a,r7
	mov	_fw_ops_end,a
;	src/link.c:69: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_link_init'
;------------------------------------------------------------
;warm                      Allocated to registers 
;------------------------------------------------------------
;	src/link.c:71: void fw_link_init(uint8_t warm) {
;	-----------------------------------------
;	 function fw_link_init
;	-----------------------------------------
_fw_link_init:
;	src/link.c:73: session = 0;
;	src/link.c:74: expected = 0;
;	src/link.c:75: nonce = 0;
	clr	a
	mov	_session,a
	mov	_expected,a
	mov	_nonce,a
	mov	(_nonce + 1),a
;	src/link.c:76: fw_ops_head = fw_ops_done = fw_ops_end = 0;
;	1-genFromRTrack replaced	mov	_fw_ops_end,#0x00
	mov	_fw_ops_end,a
;	1-genFromRTrack replaced	mov	_fw_ops_done,#0x00
	mov	_fw_ops_done,a
;	1-genFromRTrack replaced	mov	_fw_ops_head,#0x00
	mov	_fw_ops_head,a
;	src/link.c:77: vs.st = VS_OP;
;	1-genFromRTrack replaced	mov	_vs,#0x00
	mov	_vs,a
;	src/link.c:78: fw_rx_reset();
	lcall	_fw_rx_reset
;	src/link.c:79: rp_ack = rp_nak = rp_status = rp_hello = 0;
;	assignBit
	clr	_rp_hello
;	assignBit
	clr	_rp_status
;	assignBit
	clr	_rp_nak
;	assignBit
	clr	_rp_ack
;	src/link.c:80: rp_pos = 0;
	mov	_rp_pos,#0x00
;	src/link.c:81: reported = fw_ring_free();
	lcall	_fw_ring_free
	mov	_reported,dpl
;	src/link.c:82: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'due'
;------------------------------------------------------------
;	src/link.c:94: static void due(void) { fw_tx_kick(); }
;	-----------------------------------------
;	 function due
;	-----------------------------------------
_due:
	ljmp	_fw_tx_kick
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_ack'
;------------------------------------------------------------
;	src/link.c:96: void fw_ack(void) {
;	-----------------------------------------
;	 function fw_ack
;	-----------------------------------------
_fw_ack:
;	src/link.c:97: if (!session) return;
	mov	a,_session
	jnz	00102$
	ret
00102$:
;	src/link.c:98: rp_ack = 1;
;	assignBit
	setb	_rp_ack
;	src/link.c:99: due();
;	src/link.c:100: }
	ljmp	_due
;------------------------------------------------------------
;Allocation info for local variables in function 'nak'
;------------------------------------------------------------
;why                       Allocated to registers 
;------------------------------------------------------------
;	src/link.c:102: static void nak(uint8_t why) {
;	-----------------------------------------
;	 function nak
;	-----------------------------------------
_nak:
	mov	_rp_reason,dpl
;	src/link.c:104: rp_nak = 1;
;	assignBit
	setb	_rp_nak
;	src/link.c:105: due();
;	src/link.c:106: }
	ljmp	_due
;------------------------------------------------------------
;Allocation info for local variables in function 'hi_of'
;------------------------------------------------------------
;v                         Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/link.c:110: static uint8_t hi_of(uint16_t v) {
;	-----------------------------------------
;	 function hi_of
;	-----------------------------------------
_hi_of:
	mov	r6,dpl
	mov	r7,dph
;	src/link.c:111: rp_stash = v;
	mov	_rp_stash,r6
	mov	(_rp_stash + 1),r7
;	src/link.c:112: return (uint8_t)(v >> 8);
	mov	dpl,r7
;	src/link.c:113: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'ack_field'
;------------------------------------------------------------
;k                         Allocated to registers r7 
;used                      Allocated to registers r7 
;------------------------------------------------------------
;	src/link.c:116: static uint8_t ack_field(uint8_t k) {
;	-----------------------------------------
;	 function ack_field
;	-----------------------------------------
_ack_field:
;	src/link.c:117: switch (k) {
	mov	a,dpl
	mov	r7,a
	add	a,#0xff - 0x06
	jc	00107$
	mov	a,r7
	add	a,r7
;	src/link.c:118: case 0: {
	mov	dptr,#00122$
	jmp	@a+dptr
00122$:
	sjmp	00101$
	sjmp	00102$
	sjmp	00107$
	sjmp	00103$
	sjmp	00104$
	sjmp	00105$
	sjmp	00106$
00101$:
;	src/link.c:119: uint8_t used = (uint8_t)(fw_ops_end - fw_ops_head);
	mov	a,_fw_ops_end
	clr	c
	subb	a,_fw_ops_head
	mov	r7,a
;	src/link.c:120: reported = used >= FW_RING_BYTES ? 0 : (uint8_t)(FW_RING_BYTES - used);
	cjne	r7,#0x2f,00123$
00123$:
	mov	_ack_field_sloc0_1_0,c
	jc	00111$
	mov	r5,#0x00
	mov	r6,#0x00
	sjmp	00112$
00111$:
	mov	a,#0x2f
	clr	c
	subb	a,r7
	mov	r7,a
	mov	r5,a
	mov	r6,#0x00
00112$:
	mov	_reported,r5
;	src/link.c:121: return reported;
	mov	dpl,_reported
;	src/link.c:123: case 1: return hi_of(fw_executed);
	ret
00102$:
	mov	dpl,_fw_executed
	mov	dph,(_fw_executed + 1)
;	src/link.c:124: case 3: return fw_state;
	ljmp	_hi_of
00103$:
	mov	dpl,_fw_state
;	src/link.c:125: case 4: return fw_faults;
	ret
00104$:
	mov	dpl,_fw_faults
;	src/link.c:126: case 5: return fw_strikes_in_pass;
	ret
00105$:
	mov	dpl,_fw_strikes_in_pass
;	src/link.c:127: case 6: return hi_of(fw_job_id);
	ret
00106$:
	mov	dpl,_fw_job_id
	mov	dph,(_fw_job_id + 1)
;	src/link.c:128: default: return (uint8_t)rp_stash; /* 2, 7: the low byte read with the high */
	ljmp	_hi_of
00107$:
	mov	dpl,_rp_stash
;	src/link.c:129: }
;	src/link.c:130: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'payload_byte'
;------------------------------------------------------------
;k                         Allocated to registers r7 
;------------------------------------------------------------
;	src/link.c:132: static uint8_t payload_byte(uint8_t k) {
;	-----------------------------------------
;	 function payload_byte
;	-----------------------------------------
_payload_byte:
	mov	r7,dpl
;	src/link.c:133: switch (rp_type) {
	mov	a,#0x81
	cjne	a,_rp_type,00197$
	ljmp	00121$
00197$:
	mov	a,#0x83
	cjne	a,_rp_type,00198$
	sjmp	00101$
00198$:
	mov	a,#0x84
	cjne	a,_rp_type,00199$
	sjmp	00104$
00199$:
	ljmp	00131$
;	src/link.c:134: case T_NAK:
00101$:
;	src/link.c:135: if (k == 0) return rp_reason;
	mov	a,r7
	jnz	00103$
	mov	dpl,_rp_reason
	ret
00103$:
;	src/link.c:136: return ack_field((uint8_t)(k - 1));
	mov	ar6,r7
	dec	r6
	mov	dpl,r6
	ljmp	_ack_field
;	src/link.c:137: case T_STATUS_REPLY:
00104$:
;	src/link.c:138: if (k < 8) return ack_field(k);
	cjne	r7,#0x08,00201$
00201$:
	clr	a
	rlc	a
	mov	r6,a
	jz	00106$
	mov	dpl,r7
	ljmp	_ack_field
00106$:
;	src/link.c:139: switch (k) {
	mov	a,r6
	jz	00203$
	ljmp	00119$
00203$:
	mov	a,r7
	add	a,#0xff - 0x18
	jnc	00204$
	ljmp	00119$
00204$:
	mov	a,r7
	add	a,#0xf8
	mov	r6,a
	add	a,#(00205$-3-.)
	movc	a,@a+pc
	mov	dpl,a
	mov	a,r6
	add	a,#(00206$-3-.)
	movc	a,@a+pc
	mov	dph,a
	clr	a
	jmp	@a+dptr
00205$:
	.db	00107$
	.db	00108$
	.db	00119$
	.db	00109$
	.db	00119$
	.db	00110$
	.db	00119$
	.db	00111$
	.db	00114$
	.db	00116$
	.db	00119$
	.db	00112$
	.db	00114$
	.db	00116$
	.db	00119$
	.db	00117$
	.db	00118$
00206$:
	.db	00107$>>8
	.db	00108$>>8
	.db	00119$>>8
	.db	00109$>>8
	.db	00119$>>8
	.db	00110$>>8
	.db	00119$>>8
	.db	00111$>>8
	.db	00114$>>8
	.db	00116$>>8
	.db	00119$>>8
	.db	00112$>>8
	.db	00114$>>8
	.db	00116$>>8
	.db	00119$>>8
	.db	00117$>>8
	.db	00118$>>8
;	src/link.c:140: case 8: return (uint8_t)(fw_flags | (fw_paper_present() ? FL_PAPER : 0));
00107$:
	lcall	_fw_paper_present
	mov	a,dpl
	jz	00135$
	mov	r5,#0x08
	mov	r6,#0x00
	sjmp	00136$
00135$:
	mov	r5,#0x00
	mov	r6,#0x00
00136$:
	mov	r4,_fw_flags
	mov	a,r5
	orl	a,r4
	mov	dpl,a
	ret
;	src/link.c:141: case 9: return hi_of(fw_job_id);
00108$:
	mov	dpl,_fw_job_id
	mov	dph,(_fw_job_id + 1)
	ljmp	_hi_of
;	src/link.c:142: case 11: return hi_of(fw_sheet);
00109$:
	mov	dpl,_fw_sheet
	mov	dph,(_fw_sheet + 1)
	ljmp	_hi_of
;	src/link.c:143: case 13: return hi_of(fw_pass_index);
00110$:
	mov	dpl,_fw_pass_index
	mov	dph,(_fw_pass_index + 1)
	ljmp	_hi_of
;	src/link.c:144: case 15: /* i32, sign-extended from the 16-bit counters */
00111$:
;	src/link.c:145: rp_stash = (uint16_t)fw_carriage;
	mov	_rp_stash,_fw_carriage
	mov	(_rp_stash + 1),(_fw_carriage + 1)
;	src/link.c:146: return (rp_stash & 0x8000) ? 0xFF : 0;
	mov	a,(_rp_stash + 1)
	jnb	acc.7,00137$
	mov	r5,#0xff
	mov	r6,#0x00
	sjmp	00138$
00137$:
	mov	r5,#0x00
	mov	r6,#0x00
00138$:
	mov	dpl,r5
	ret
;	src/link.c:147: case 19:
00112$:
;	src/link.c:148: rp_stash = (uint16_t)fw_feed;
	mov	_rp_stash,_fw_feed
	mov	(_rp_stash + 1),(_fw_feed + 1)
;	src/link.c:149: return (rp_stash & 0x8000) ? 0xFF : 0;
	mov	a,(_rp_stash + 1)
	jnb	acc.7,00139$
	mov	r5,#0xff
	mov	r6,#0x00
	sjmp	00140$
00139$:
	mov	r5,#0x00
	mov	r6,#0x00
00140$:
	mov	dpl,r5
	ret
;	src/link.c:151: case 20: return (rp_stash & 0x8000) ? 0xFF : 0;
00114$:
	mov	a,(_rp_stash + 1)
	jnb	acc.7,00141$
	mov	r5,#0xff
	mov	r6,#0x00
	sjmp	00142$
00141$:
	mov	r5,#0x00
	mov	r6,#0x00
00142$:
	mov	dpl,r5
	ret
;	src/link.c:153: case 21: return (uint8_t)(rp_stash >> 8);
00116$:
	mov	dpl,(_rp_stash + 1)
	ret
;	src/link.c:154: case 23: return 0;
00117$:
	mov	dpl,#0x00
	ret
;	src/link.c:155: case 24: return fw_stack_used(); /* v2's underruns: a v3 pass runs only
00118$:
	ljmp	_fw_stack_used
;	src/link.c:158: default: return (uint8_t)rp_stash; /* 10, 12, 14, 18, 22 */
00119$:
	mov	dpl,_rp_stash
	ret
;	src/link.c:160: case T_HELLO_REPLY:
00121$:
;	src/link.c:161: switch (k) {
	mov	a,r7
	add	a,#0xff - 0x06
	jc	00129$
	mov	a,r7
	add	a,r7
;	src/link.c:162: case 0: return FW_PROTOCOL;
	mov	dptr,#00212$
	jmp	@a+dptr
00212$:
	sjmp	00122$
	sjmp	00123$
	sjmp	00124$
	sjmp	00125$
	sjmp	00126$
	sjmp	00127$
	sjmp	00128$
00122$:
	mov	dpl,#0x03
;	src/link.c:163: case 1: return FW_VERSION_MAJOR;
	ret
00123$:
	mov	dpl,#0x01
;	src/link.c:164: case 2: return FW_VERSION_MINOR;
	ret
00124$:
	mov	dpl,#0x00
;	src/link.c:165: case 3: return CAP_INTERPOINT | CAP_LPT | CAP_UART | CAP_WARM_RESTART;
	ret
00125$:
	mov	dpl,#0x0f
;	src/link.c:166: case 4: return FW_RING_BYTES;
	ret
00126$:
	mov	dpl,#0x2f
;	src/link.c:167: case 5: return FW_MAX_DATA;
	ret
00127$:
	mov	dpl,#0x21
;	src/link.c:168: case 6: return FW_WINDOW_FRAMES;
	ret
00128$:
	mov	dpl,#0x04
;	src/link.c:171: default: return k < 11 ? fw_table_id[k - 7] : 0;
	ret
00129$:
	cjne	r7,#0x0b,00213$
00213$:
	jnc	00143$
	mov	ar6,r7
	mov	a,r6
	add	a,#0xf9
	mov	r6,a
	rlc	a
	subb	a,acc
	mov	r5,a
	mov	a,r6
	add	a,#_fw_table_id
	mov	dpl,a
	mov	a,r5
	addc	a,#(_fw_table_id >> 8)
	mov	dph,a
	clr	a
	movc	a,@a+dptr
	mov	r5,a
	mov	r6,#0x00
	sjmp	00144$
00143$:
	mov	r5,#0x00
	mov	r6,#0x00
00144$:
	mov	dpl,r5
;	src/link.c:173: default: return ack_field(k);
	ret
00131$:
	mov	dpl,r7
;	src/link.c:174: }
;	src/link.c:175: }
	ljmp	_ack_field
;------------------------------------------------------------
;Allocation info for local variables in function 'rp_crc_byte'
;------------------------------------------------------------
;b                         Allocated to registers r7 
;i                         Allocated to registers r6 
;------------------------------------------------------------
;	src/link.c:177: static uint8_t rp_crc_byte(uint8_t b) {
;	-----------------------------------------
;	 function rp_crc_byte
;	-----------------------------------------
_rp_crc_byte:
	mov	r7,dpl
;	src/link.c:179: rp_crc ^= (uint16_t)((uint16_t)b << 8);
	mov	ar5,r7
	mov	ar6,r5
	clr	a
	mov	r5,a
	xrl	_rp_crc,a
	mov	a,r6
	xrl	(_rp_crc + 1),a
;	src/link.c:180: for (i = 0; i < 8; ++i) {
	mov	r6,#0x00
00105$:
;	src/link.c:181: if (rp_crc & 0x8000) rp_crc = (uint16_t)((uint16_t)(rp_crc << 1) ^ 0x1021U);
	mov	r4,_rp_crc
	mov	a,(_rp_crc + 1)
	mov	r5,a
	jnb	acc.7,00102$
	mov	a,_rp_crc
	add	a,_rp_crc
	mov	r4,a
	mov	a,(_rp_crc + 1)
	rlc	a
	mov	r5,a
	xrl	ar4,#0x21
	xrl	ar5,#0x10
	mov	_rp_crc,r4
	mov	(_rp_crc + 1),r5
	sjmp	00106$
00102$:
;	src/link.c:182: else rp_crc = (uint16_t)(rp_crc << 1);
	mov	a,_rp_crc
	add	a,_rp_crc
	mov	_rp_crc,a
	mov	a,(_rp_crc + 1)
	rlc	a
	mov	(_rp_crc + 1),a
00106$:
;	src/link.c:180: for (i = 0; i < 8; ++i) {
	inc	r6
	cjne	r6,#0x08,00123$
00123$:
	jc	00105$
;	src/link.c:184: return b;
	mov	dpl,r7
;	src/link.c:185: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'rp_len'
;------------------------------------------------------------
;	src/link.c:187: static uint8_t rp_len(void) {
;	-----------------------------------------
;	 function rp_len
;	-----------------------------------------
_rp_len:
;	src/link.c:188: switch (rp_type) {
	mov	a,#0x81
	cjne	a,_rp_type,00120$
	sjmp	00101$
00120$:
	mov	a,#0x83
	cjne	a,_rp_type,00121$
	sjmp	00102$
00121$:
	mov	a,#0x84
;	src/link.c:189: case T_HELLO_REPLY: return 13;
	cjne	a,_rp_type,00104$
	sjmp	00103$
00101$:
	mov	dpl,#0x0d
;	src/link.c:190: case T_NAK: return 9;
	ret
00102$:
	mov	dpl,#0x09
;	src/link.c:191: case T_STATUS_REPLY: return 25;
	ret
00103$:
	mov	dpl,#0x19
;	src/link.c:192: default: return 8;
	ret
00104$:
	mov	dpl,#0x08
;	src/link.c:193: }
;	src/link.c:194: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_reply_byte'
;------------------------------------------------------------
;k                         Allocated to registers r7 
;len                       Allocated to registers r6 
;------------------------------------------------------------
;	src/link.c:196: int16_t fw_reply_byte(void) {
;	-----------------------------------------
;	 function fw_reply_byte
;	-----------------------------------------
_fw_reply_byte:
;	src/link.c:198: if (rp_pos == 0) {
	mov	a,_rp_pos
	jnz	00114$
;	src/link.c:200: if (rp_hello) {
;	src/link.c:201: rp_hello = 0;
;	assignBit
	jbc	_rp_hello,00178$
	sjmp	00111$
00178$:
;	src/link.c:202: rp_type = T_HELLO_REPLY;
	mov	_rp_type,#0x81
	sjmp	00112$
00111$:
;	src/link.c:203: } else if (rp_nak) {
;	src/link.c:204: rp_nak = 0;
;	assignBit
	jbc	_rp_nak,00179$
	sjmp	00108$
00179$:
;	src/link.c:205: rp_type = T_NAK;
	mov	_rp_type,#0x83
	sjmp	00112$
00108$:
;	src/link.c:206: } else if (rp_status) {
;	src/link.c:207: rp_status = 0;
;	assignBit
	jbc	_rp_status,00180$
	sjmp	00105$
00180$:
;	src/link.c:208: rp_type = T_STATUS_REPLY;
	mov	_rp_type,#0x84
	sjmp	00112$
00105$:
;	src/link.c:209: } else if (rp_ack) {
;	src/link.c:210: rp_ack = 0;
;	assignBit
	jbc	_rp_ack,00181$
	sjmp	00102$
00181$:
;	src/link.c:211: rp_type = T_ACK;
	mov	_rp_type,#0x82
	sjmp	00112$
00102$:
;	src/link.c:213: return -1;
	mov	dptr,#0xffff
	ret
00112$:
;	src/link.c:215: rp_crc = 0xFFFF;
	mov	_rp_crc,#0xff
	mov	(_rp_crc + 1),#0xff
;	src/link.c:216: rp_pos = 1;
	mov	_rp_pos,#0x01
;	src/link.c:217: return FW_SYNC;
	mov	dptr,#0x007e
	ret
00114$:
;	src/link.c:219: k = rp_pos++;
	mov	r7,_rp_pos
	inc	_rp_pos
;	src/link.c:220: len = rp_len();
	push	ar7
	lcall	_rp_len
	mov	r6,dpl
	pop	ar7
;	src/link.c:221: if (k == 1) return rp_crc_byte(len);
	cjne	r7,#0x01,00116$
	mov	dpl,r6
	lcall	_rp_crc_byte
	mov	r4,#0x00
	mov	dph,r4
	ret
00116$:
;	src/link.c:222: if (k == 2) return rp_crc_byte(expected); /* the next SEQ this controller expects */
	cjne	r7,#0x02,00118$
	mov	dpl,_expected
	lcall	_rp_crc_byte
	mov	r4,#0x00
	mov	dph,r4
	ret
00118$:
;	src/link.c:223: if (k == 3) return rp_crc_byte(rp_type);
	cjne	r7,#0x03,00120$
	mov	dpl,_rp_type
	lcall	_rp_crc_byte
	mov	r4,#0x00
	mov	dph,r4
	ret
00120$:
;	src/link.c:224: k = (uint8_t)(k - 4);
	dec	r7
	dec	r7
	dec	r7
	dec	r7
;	src/link.c:225: if (k < len) return rp_crc_byte(payload_byte(k));
	clr	c
	mov	a,r7
	subb	a,r6
	jnc	00122$
	mov	dpl,r7
	lcall	_payload_byte
	lcall	_rp_crc_byte
	mov	r4,#0x00
	mov	dph,r4
	ret
00122$:
;	src/link.c:226: if (k == len) return (uint8_t)(rp_crc >> 8);
	mov	a,r7
	cjne	a,ar6,00124$
	mov	r7,(_rp_crc + 1)
	mov	r6,#0x00
	mov	dpl,r7
	mov	dph,r6
	ret
00124$:
;	src/link.c:227: rp_pos = 0;
	mov	_rp_pos,#0x00
;	src/link.c:228: return (uint8_t)rp_crc;
	mov	r7,_rp_crc
	mov	r6,#0x00
	mov	dpl,r7
	mov	dph,r6
;	src/link.c:229: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_report_room'
;------------------------------------------------------------
;free                      Allocated to registers r7 
;------------------------------------------------------------
;	src/link.c:231: void fw_report_room(void) {
;	-----------------------------------------
;	 function fw_report_room
;	-----------------------------------------
_fw_report_room:
;	src/link.c:233: if (!session) return;
	mov	a,_session
	jnz	00102$
	ret
00102$:
;	src/link.c:234: free = fw_ring_free();
	lcall	_fw_ring_free
	mov	r7,dpl
;	src/link.c:235: if ((uint16_t)free >= (uint16_t)reported + FW_MAX_DATA ||
	mov	ar5,r7
	mov	r6,#0x00
	mov	r3,_reported
	mov	r4,#0x00
	mov	a,#0x21
	add	a,r3
	mov	r3,a
	clr	a
	addc	a,r4
	mov	r4,a
	clr	c
	mov	a,r5
	subb	a,r3
	mov	a,r6
	subb	a,r4
	jnc	00103$
;	src/link.c:236: (free >= FW_MAX_DATA && reported < FW_MAX_DATA))
	cjne	r7,#0x21,00123$
00123$:
	jc	00107$
	mov	a,#0x100 - 0x21
	add	a,_reported
	jc	00107$
00103$:
;	src/link.c:237: fw_ack();
;	src/link.c:238: }
	ljmp	_fw_ack
00107$:
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_starved'
;------------------------------------------------------------
;	src/link.c:240: void fw_starved(void) {
;	-----------------------------------------
;	 function fw_starved
;	-----------------------------------------
_fw_starved:
;	src/link.c:241: if (session && fw_ring_free() > reported) fw_ack();
	mov	a,_session
	jz	00104$
	lcall	_fw_ring_free
	mov	r7,dpl
	clr	c
	mov	a,_reported
	subb	a,r7
	jnc	00104$
;	src/link.c:242: }
	ljmp	_fw_ack
00104$:
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'check_ops'
;------------------------------------------------------------
;len                       Allocated with name '_check_ops_PARM_2'
;p                         Allocated to registers r7 
;i                         Allocated to registers r6 
;b                         Allocated to registers r5 
;------------------------------------------------------------
;	src/link.c:251: static uint8_t check_ops(const FW_IDATA uint8_t *p, uint8_t len) {
;	-----------------------------------------
;	 function check_ops
;	-----------------------------------------
_check_ops:
	mov	r7,dpl
;	src/link.c:253: done_at = 0;
	mov	_done_at,#0x00
;	src/link.c:254: for (i = 0; i < len; ++i) {
	mov	r6,#0x00
00136$:
	clr	c
	mov	a,r6
	subb	a,_check_ops_PARM_2
	jc	00233$
	ljmp	00134$
00233$:
;	src/link.c:255: b = p[i];
	mov	a,r6
	add	a,r7
	mov	r1,a
	mov	ar5,@r1
;	src/link.c:256: switch (vs.st) {
	mov	a,_vs
	mov	r4,a
	add	a,#0xff - 0x0a
	jnc	00234$
	ljmp	00131$
00234$:
	mov	a,r4
	add	a,#(00235$-3-.)
	movc	a,@a+pc
	mov	dpl,a
	mov	a,r4
	add	a,#(00236$-3-.)
	movc	a,@a+pc
	mov	dph,a
	clr	a
	jmp	@a+dptr
00235$:
	.db	00101$
	.db	00112$
	.db	00115$
	.db	00118$
	.db	00119$
	.db	00120$
	.db	00121$
	.db	00122$
	.db	00123$
	.db	00127$
	.db	00130$
00236$:
	.db	00101$>>8
	.db	00112$>>8
	.db	00115$>>8
	.db	00118$>>8
	.db	00119$>>8
	.db	00120$>>8
	.db	00121$>>8
	.db	00122$>>8
	.db	00123$>>8
	.db	00127$>>8
	.db	00130$>>8
;	src/link.c:257: case VS_OP:
00101$:
;	src/link.c:258: switch (b) {
	cjne	r5,#0x10,00237$
	sjmp	00105$
00237$:
	cjne	r5,#0x11,00238$
	sjmp	00104$
00238$:
	cjne	r5,#0x12,00239$
	sjmp	00108$
00239$:
	cjne	r5,#0x13,00240$
	sjmp	00104$
00240$:
	cjne	r5,#0x14,00241$
	sjmp	00109$
00241$:
	cjne	r5,#0x40,00242$
	sjmp	00104$
00242$:
	cjne	r5,#0x42,00243$
	sjmp	00108$
00243$:
;	src/link.c:261: case OP_HOME: done_at = (uint8_t)(i + 1); continue;
	cjne	r5,#0x43,00110$
	sjmp	00108$
00104$:
	mov	ar4,r6
	inc	r4
	mov	_done_at,r4
	ljmp	00133$
;	src/link.c:262: case OP_JOB_BEGIN: vs.n = 4; vs.st = VS_FIXED; continue;
00105$:
	mov	(_vs + 0x0001),#0x04
	mov	_vs,#0x01
	ljmp	00133$
;	src/link.c:265: case OP_SEEK_FEED: vs.n = 2; vs.st = VS_FIXED; continue;
00108$:
	mov	(_vs + 0x0001),#0x02
	mov	_vs,#0x01
	ljmp	00133$
;	src/link.c:266: case OP_PASS: vs.st = VS_FLAGS; continue;
00109$:
	mov	_vs,#0x02
	ljmp	00133$
;	src/link.c:267: default: return 1;
00110$:
	mov	dpl,#0x01
	ret
;	src/link.c:269: case VS_FIXED:
00112$:
;	src/link.c:270: if (--vs.n == 0) {
	mov	a,(_vs + 0x0001)
	dec	a
	mov	r4,a
	mov	(_vs + 0x0001),r4
	jz	00245$
	ljmp	00133$
00245$:
;	src/link.c:271: vs.st = VS_OP;
	mov	_vs,#0x00
;	src/link.c:272: done_at = (uint8_t)(i + 1);
	mov	ar4,r6
	inc	r4
	mov	_done_at,r4
;	src/link.c:274: continue;
	ljmp	00133$
;	src/link.c:275: case VS_FLAGS:
00115$:
;	src/link.c:276: if (b & (uint8_t)~PF_ALL) return 1;
	mov	a,r5
	anl	a,#0xe0
	jz	00117$
	mov	dpl,#0x01
	ret
00117$:
;	src/link.c:277: vs.flags = b;
;	src/link.c:278: vs.st = (b & PF_SKIP) ? VS_SKIP : VS_FEED;
	mov	a,r5
	mov	(_vs + 0x0002),a
	jnb	acc.4,00139$
	mov	r4,#0x03
	sjmp	00140$
00139$:
	mov	r4,#0x04
00140$:
	mov	_vs,r4
;	src/link.c:279: continue;
	ljmp	00133$
;	src/link.c:280: case VS_SKIP: vs.hi = b; vs.st = VS_FEED; continue; /* skip: checked against n */
00118$:
	mov	(_vs + 0x0003),r5
	mov	_vs,#0x04
	ljmp	00133$
;	src/link.c:281: case VS_FEED: vs.st = (b & 0x80) ? VS_FEED2 : VS_FIRST; continue;
00119$:
	mov	a,r5
	jnb	acc.7,00141$
	mov	r4,#0x05
	sjmp	00142$
00141$:
	mov	r4,#0x06
00142$:
	mov	_vs,r4
;	src/link.c:282: case VS_FEED2: vs.st = VS_FIRST; continue;
	sjmp	00133$
00120$:
	mov	_vs,#0x06
;	src/link.c:283: case VS_FIRST: vs.st = (b & 0x80) ? VS_FIRST2 : VS_N; continue;
	sjmp	00133$
00121$:
	mov	a,r5
	jnb	acc.7,00143$
	mov	r4,#0x07
	sjmp	00144$
00143$:
	mov	r4,#0x08
00144$:
	mov	_vs,r4
;	src/link.c:284: case VS_FIRST2: vs.st = VS_N; continue;
	sjmp	00133$
00122$:
	mov	_vs,#0x08
;	src/link.c:285: case VS_N:
	sjmp	00133$
00123$:
;	src/link.c:286: if ((vs.flags & PF_SKIP) && vs.hi > b) return 1;
	mov	a,(_vs + 0x0002)
	jnb	acc.4,00125$
	clr	c
	mov	a,r5
	subb	a,(_vs + 0x0003)
	jnc	00125$
	mov	dpl,#0x01
	ret
00125$:
;	src/link.c:287: vs.n = b;
;	src/link.c:288: vs.st = b ? VS_ENTRY : VS_OP;
	mov	a,r5
	mov	(_vs + 0x0001),a
	jz	00145$
	mov	r3,#0x09
	mov	r4,#0x00
	sjmp	00146$
00145$:
	mov	r3,#0x00
	mov	r4,#0x00
00146$:
	mov	_vs,r3
;	src/link.c:289: done_at = (uint8_t)(i + 1); /* the header: the feed may start */
	mov	ar4,r6
	inc	r4
	mov	_done_at,r4
;	src/link.c:290: continue;
;	src/link.c:291: case VS_ENTRY:
	sjmp	00133$
00127$:
;	src/link.c:292: if (b & E_EXT) {
	mov	a,r5
	jnb	acc.6,00130$
;	src/link.c:293: vs.st = VS_ENTRY2;
	mov	_vs,#0x0a
;	src/link.c:294: continue;
;	src/link.c:297: case VS_ENTRY2:
	sjmp	00133$
00130$:
;	src/link.c:298: vs.st = --vs.n ? VS_ENTRY : VS_OP;
	mov	a,(_vs + 0x0001)
	dec	a
	mov	r5,a
	mov	(_vs + 0x0001),r5
	jz	00147$
	mov	r4,#0x09
	mov	r5,#0x00
	sjmp	00148$
00147$:
	mov	r4,#0x00
	mov	r5,#0x00
00148$:
	mov	_vs,r4
;	src/link.c:299: done_at = (uint8_t)(i + 1);
	mov	ar5,r6
	inc	r5
	mov	_done_at,r5
;	src/link.c:300: continue;
;	src/link.c:301: default: return 1;
	sjmp	00133$
00131$:
	mov	dpl,#0x01
;	src/link.c:302: }
	ret
00133$:
;	src/link.c:254: for (i = 0; i < len; ++i) {
	inc	r6
	ljmp	00136$
00134$:
;	src/link.c:304: return 0;
	mov	dpl,#0x00
;	src/link.c:305: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'pass_crc_update'
;------------------------------------------------------------
;b                         Allocated with name '_pass_crc_update_PARM_2'
;c                         Allocated to registers r4 r5 
;------------------------------------------------------------
;	src/link.c:314: uint16_t pass_crc_update(uint16_t c, uint8_t b) {
;	-----------------------------------------
;	 function pass_crc_update
;	-----------------------------------------
_pass_crc_update:
	mov	r6,dpl
	mov	r7,dph
;	src/link.c:315: c = (uint16_t)((uint16_t)(c << 4) ^ chk_nib[(uint8_t)((c >> 12) ^ (b >> 4))]);
	mov	ar4,r6
	mov	a,r7
	swap	a
	anl	a,#0xf0
	xch	a,r4
	swap	a
	xch	a,r4
	xrl	a,r4
	xch	a,r4
	anl	a,#0xf0
	xch	a,r4
	xrl	a,r4
	mov	r5,a
	mov	a,r7
	swap	a
	anl	a,#0x0f
	mov	r6,a
	mov	a,_pass_crc_update_PARM_2
	swap	a
	anl	a,#0x0f
	xrl	a,r6
	mov	b,#0x02
	mul	ab
	add	a,#_chk_nib
	mov	dpl,a
	mov	a,#(_chk_nib >> 8)
	addc	a,b
	mov	dph,a
	clr	a
	movc	a,@a+dptr
	mov	r6,a
	inc	dptr
	clr	a
	movc	a,@a+dptr
	mov	r7,a
	mov	a,r6
	xrl	ar4,a
	mov	a,r7
	xrl	ar5,a
;	src/link.c:316: c = (uint16_t)((uint16_t)(c << 4) ^ chk_nib[(uint8_t)((c >> 12) ^ (b & 0x0F))]);
	mov	ar6,r4
	mov	a,r5
	swap	a
	anl	a,#0xf0
	xch	a,r6
	swap	a
	xch	a,r6
	xrl	a,r6
	xch	a,r6
	anl	a,#0xf0
	xch	a,r6
	xrl	a,r6
	mov	r7,a
	mov	a,r5
	swap	a
	anl	a,#0x0f
	mov	r4,a
	mov	a,_pass_crc_update_PARM_2
	anl	a,#0x0f
	xrl	a,r4
	mov	b,#0x02
	mul	ab
	add	a,#_chk_nib
	mov	dpl,a
	mov	a,#(_chk_nib >> 8)
	addc	a,b
	mov	dph,a
	clr	a
	movc	a,@a+dptr
	mov	r4,a
	inc	dptr
	clr	a
	movc	a,@a+dptr
	mov	r5,a
	mov	a,r4
	xrl	a,r6
	mov	dpl,a
	mov	a,r5
	xrl	a,r7
	mov	dph,a
;	src/link.c:317: return c;
;	src/link.c:318: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'accept'
;------------------------------------------------------------
;	src/link.c:322: static void accept(void) { ++expected; }
;	-----------------------------------------
;	 function accept
;	-----------------------------------------
_accept:
	inc	_expected
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'on_hello'
;------------------------------------------------------------
;len                       Allocated with name '_on_hello_PARM_2'
;seq                       Allocated with name '_on_hello_PARM_3'
;p                         Allocated to registers r1 
;n                         Allocated to registers r7 r6 
;------------------------------------------------------------
;	src/link.c:324: static void on_hello(const FW_IDATA uint8_t *p, uint8_t len, uint8_t seq) {
;	-----------------------------------------
;	 function on_hello
;	-----------------------------------------
_on_hello:
	mov	r1,dpl
;	src/link.c:326: if (len != 3 || p[2] != FW_PROTOCOL) {
	mov	a,#0x03
	cjne	a,_on_hello_PARM_2,00101$
	mov	a,#0x02
	add	a,r1
	mov	r0,a
	mov	ar7,@r0
	cjne	r7,#0x03,00161$
	sjmp	00102$
00161$:
00101$:
;	src/link.c:327: nak(NAK_BAD_PAYLOAD);
	mov	dpl,#0x04
;	src/link.c:328: return;
	ljmp	_nak
00102$:
;	src/link.c:330: n = (uint16_t)(((uint16_t)p[0] << 8) | p[1]);
	mov	ar7,@r1
	mov	ar6,r7
	mov	r7,#0x00
	inc	r1
	mov	ar5,@r1
	mov	r4,#0x00
	mov	a,r5
	orl	ar7,a
	mov	a,r4
	orl	ar6,a
;	src/link.c:333: if (!session || n != nonce) {
	mov	a,_session
	jz	00116$
	mov	a,r7
	cjne	a,_nonce,00163$
	mov	a,r6
	cjne	a,(_nonce + 1),00163$
	sjmp	00117$
00163$:
00116$:
;	src/link.c:336: fw_flush();
	push	ar7
	push	ar6
	lcall	_fw_flush
	pop	ar6
	pop	ar7
;	src/link.c:337: if (fw_flags & FL_JOB_ACTIVE) {
	mov	a,_fw_flags
	jnb	acc.4,00112$
;	src/link.c:338: if (fw_state == ST_RUNNING || fw_state == ST_WAITING || fw_state == ST_HOMING) {
	mov	a,#0x01
	cjne	a,_fw_state,00165$
	sjmp	00107$
00165$:
	mov	a,#0x02
	cjne	a,_fw_state,00166$
	sjmp	00107$
00166$:
	mov	a,#0x05
	cjne	a,_fw_state,00112$
00107$:
;	src/link.c:339: if (exec_busy()) fw_pause_req = 1;
	push	ar7
	push	ar6
	lcall	_exec_busy
	mov	a,dpl
	pop	ar6
	pop	ar7
	jz	00105$
	mov	_fw_pause_req,#0x01
	sjmp	00112$
00105$:
;	src/link.c:340: else fw_state = ST_PAUSED;
	mov	_fw_state,#0x03
00112$:
;	src/link.c:343: session = 1;
	mov	_session,#0x01
;	src/link.c:344: nonce = n;
	mov	_nonce,r7
	mov	(_nonce + 1),r6
;	src/link.c:345: expected = (uint8_t)(seq + 1);
	mov	r7,_on_hello_PARM_3
	inc	r7
	mov	_expected,r7
;	src/link.c:346: fw_faults &= (uint8_t) ~(F_POWER_ON | F_WARM_RESET);
	anl	_fw_faults,#0xe7
;	src/link.c:347: if (fw_state == ST_FAULT && fw_faults == 0)
	mov	a,#0x04
	cjne	a,_fw_state,00117$
	mov	a,_fw_faults
	jnz	00117$
;	src/link.c:348: fw_state = (fw_flags & FL_JOB_ACTIVE) ? ST_PAUSED : ST_IDLE;
	mov	a,_fw_flags
	jnb	acc.4,00121$
	mov	r6,#0x03
	mov	r7,#0x00
	sjmp	00122$
00121$:
	mov	r6,#0x00
	mov	r7,#0x00
00122$:
	mov	_fw_state,r6
00117$:
;	src/link.c:350: rp_hello = 1;
;	assignBit
	setb	_rp_hello
;	src/link.c:351: due();
;	src/link.c:352: }
	ljmp	_due
;------------------------------------------------------------
;Allocation info for local variables in function 'on_data'
;------------------------------------------------------------
;len                       Allocated with name '_on_data_PARM_2'
;frame                     Allocated with name '_on_data_frame_65536_85'
;i                         Allocated to registers r3 
;c                         Allocated with name '_on_data_c_65536_86'
;p                         Allocated to registers r4 
;------------------------------------------------------------
;	src/link.c:354: static void on_data(FW_IDATA uint8_t *frame, uint8_t len) {
;	-----------------------------------------
;	 function on_data
;	-----------------------------------------
_on_data:
	mov	_on_data_frame_65536_85,dpl
;	src/link.c:356: uint16_t c = 0xFFFF;
	mov	_on_data_c_65536_86,#0xff
	mov	(_on_data_c_65536_86 + 1),#0xff
;	src/link.c:357: FW_IDATA uint8_t *p = frame + 3;
	mov	a,#0x03
	add	a,_on_data_frame_65536_85
	mov	r4,a
;	src/link.c:358: if (len < 3 || len > FW_MAX_DATA) {
	mov	a,#0x100 - 0x03
	add	a,_on_data_PARM_2
	jnc	00101$
	mov	a,_on_data_PARM_2
	add	a,#0xff - 0x21
	jnc	00102$
00101$:
;	src/link.c:359: nak(NAK_BAD_PAYLOAD);
	mov	dpl,#0x04
;	src/link.c:360: return;
	ljmp	_nak
00102$:
;	src/link.c:362: len = (uint8_t)(len - 2); /* the ops; the check follows them */
	mov	r3,_on_data_PARM_2
	dec	r3
	dec	r3
	mov	_on_data_PARM_2,r3
;	src/link.c:363: for (i = 0; i < len; ++i) c = pass_crc_update(c, p[i]);
	mov	r3,#0x00
00117$:
	clr	c
	mov	a,r3
	subb	a,_on_data_PARM_2
	jnc	00104$
	mov	a,r3
	add	a,r4
	mov	r1,a
	mov	_pass_crc_update_PARM_2,@r1
	mov	dpl,_on_data_c_65536_86
	mov	dph,(_on_data_c_65536_86 + 1)
	push	ar4
	push	ar3
	lcall	_pass_crc_update
	mov	_on_data_c_65536_86,dpl
	mov	(_on_data_c_65536_86 + 1),dph
	pop	ar3
	pop	ar4
	inc	r3
	sjmp	00117$
00104$:
;	src/link.c:364: if (c != (uint16_t)(((uint16_t)p[len] << 8) | p[len + 1])) {
	mov	a,_on_data_PARM_2
	add	a,r4
	mov	r1,a
	mov	ar3,@r1
	mov	ar2,r3
	mov	r3,#0x00
	mov	r6,_on_data_PARM_2
	mov	r7,#0x00
	inc	r6
	cjne	r6,#0x00,00169$
	inc	r7
00169$:
	mov	a,r6
	add	a,r4
	mov	r1,a
	mov	ar7,@r1
	mov	r6,#0x00
	mov	a,r7
	orl	ar3,a
	mov	a,r6
	orl	ar2,a
	mov	a,r3
;	src/link.c:368: return;
	cjne	a,_on_data_c_65536_86,00122$
	mov	a,r2
	cjne	a,(_on_data_c_65536_86 + 1),00122$
;	src/link.c:370: if (len > fw_ring_free()) {
	push	ar4
	lcall	_fw_ring_free
	mov	r7,dpl
	pop	ar4
	clr	c
	mov	a,r7
	subb	a,_on_data_PARM_2
	jnc	00108$
;	src/link.c:371: nak(NAK_NO_SPACE);
	mov	dpl,#0x02
;	src/link.c:372: return;
	ljmp	_nak
00108$:
;	src/link.c:374: if (check_ops(p, len)) {
	mov	_check_ops_PARM_2,_on_data_PARM_2
	mov	dpl,r4
	push	ar4
	lcall	_check_ops
	mov	a,dpl
	pop	ar4
	jz	00112$
;	src/link.c:378: fw_flush();
	lcall	_fw_flush
;	src/link.c:379: fw_faults |= F_STREAM;
	orl	_fw_faults,#0x80
;	src/link.c:380: fw_state = ST_FAULT;
	mov	_fw_state,#0x04
;	src/link.c:381: if (exec_busy()) exec_abort();
	lcall	_exec_busy
	mov	a,dpl
	jz	00110$
	lcall	_exec_abort
00110$:
;	src/link.c:382: nak(NAK_BAD_PAYLOAD);
	mov	dpl,#0x04
;	src/link.c:383: return;
	ljmp	_nak
00112$:
;	src/link.c:385: accept();
	push	ar4
	lcall	_accept
	pop	ar4
;	src/link.c:387: for (i = 0; i < len; ++i) frame[i] = p[i];
	mov	r7,#0x00
00120$:
	clr	c
	mov	a,r7
	subb	a,_on_data_PARM_2
	jnc	00113$
	mov	a,r7
	add	a,_on_data_frame_65536_85
	mov	r1,a
	mov	a,r7
	add	a,r4
	mov	r0,a
	mov	ar6,@r0
	mov	@r1,ar6
	inc	r7
	sjmp	00120$
00113$:
;	src/link.c:388: if (done_at) fw_ops_done = (uint8_t)(fw_ops_end + done_at);
	mov	a,_done_at
	jz	00115$
	mov	a,_done_at
	add	a,_fw_ops_end
	mov	_fw_ops_done,a
00115$:
;	src/link.c:389: fw_ops_end = (uint8_t)(fw_ops_end + len);
	mov	a,_on_data_PARM_2
	add	a,_fw_ops_end
	mov	_fw_ops_end,a
;	src/link.c:390: fw_ack();
;	src/link.c:391: }
	ljmp	_fw_ack
00122$:
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'on_configure'
;------------------------------------------------------------
;len                       Allocated with name '_on_configure_PARM_2'
;p                         Allocated with name '_on_configure_p_65536_93'
;sloc0                     Allocated with name '_on_configure_sloc0_1_0'
;sloc1                     Allocated with name '_on_configure_sloc1_1_0'
;sloc2                     Allocated with name '_on_configure_sloc2_1_0'
;------------------------------------------------------------
;	src/link.c:394: static uint8_t on_configure(const FW_IDATA uint8_t *p, uint8_t len) {
;	-----------------------------------------
;	 function on_configure
;	-----------------------------------------
_on_configure:
	mov	_on_configure_p_65536_93,dpl
;	src/link.c:397: if (len != 10 || BE16(p, 0) == 0 || BE16(p, 2) < 64 || BE16(p, 4) == 0) return 0;
	mov	a,#0x0a
	cjne	a,_on_configure_PARM_2,00120$
	sjmp	00121$
00120$:
	ljmp	00101$
00121$:
	mov	r0,_on_configure_p_65536_93
	mov	ar7,@r0
	mov	ar6,r7
	mov	r7,#0x00
	mov	a,_on_configure_p_65536_93
	inc	a
	mov	r0,a
	mov	ar5,@r0
	mov	ar4,r5
	mov	r5,#0x00
	mov	a,r4
	orl	a,r7
	mov	r2,a
	mov	a,r5
	orl	a,r6
	mov	r3,a
	orl	a,r2
	jz	00101$
	push	ar4
	push	ar5
	mov	a,#0x02
	add	a,_on_configure_p_65536_93
	mov	r0,a
	mov	ar3,@r0
	mov	ar2,r3
	mov	r3,#0x00
	mov	a,#0x03
	add	a,_on_configure_p_65536_93
	mov	r0,a
	mov	ar5,@r0
	mov	_on_configure_sloc0_1_0,r5
;	1-genFromRTrack replaced	mov	(_on_configure_sloc0_1_0 + 1),#0x00
	mov	(_on_configure_sloc0_1_0 + 1),r3
	mov	a,_on_configure_sloc0_1_0
	orl	a,r3
	mov	r4,a
	mov	a,(_on_configure_sloc0_1_0 + 1)
	orl	a,r2
	mov	r5,a
	clr	c
	mov	a,r4
	subb	a,#0x40
	mov	a,r5
	subb	a,#0x00
	pop	ar5
	pop	ar4
	jc	00101$
	push	ar3
	push	ar2
	mov	a,#0x04
	add	a,_on_configure_p_65536_93
	mov	r1,a
	mov	ar3,@r1
	mov	r2,#0x00
	mov	(_on_configure_sloc1_1_0 + 1),r3
;	1-genFromRTrack replaced	mov	_on_configure_sloc1_1_0,#0x00
	mov	_on_configure_sloc1_1_0,r2
	mov	a,#0x05
	add	a,_on_configure_p_65536_93
	mov	r1,a
	mov	ar3,@r1
	mov	_on_configure_sloc2_1_0,r3
;	1-genFromRTrack replaced	mov	(_on_configure_sloc2_1_0 + 1),#0x00
	mov	(_on_configure_sloc2_1_0 + 1),r2
	mov	a,_on_configure_sloc2_1_0
	orl	a,_on_configure_sloc1_1_0
	mov	r2,a
	mov	a,(_on_configure_sloc2_1_0 + 1)
	orl	a,(_on_configure_sloc1_1_0 + 1)
	orl	a,r2
	pop	ar2
	pop	ar3
	jnz	00102$
00101$:
	mov	dpl,#0x00
	ret
00102$:
;	src/link.c:398: cfg_travel = BE16(p, 0);
	mov	a,r4
	orl	a,r7
	mov	_cfg_travel,a
	mov	a,r5
	orl	a,r6
	mov	(_cfg_travel + 1),a
;	src/link.c:399: cfg_home_iv = BE16(p, 2);
	mov	a,_on_configure_sloc0_1_0
	orl	a,r3
	mov	_cfg_home_iv,a
	mov	a,(_on_configure_sloc0_1_0 + 1)
	orl	a,r2
	mov	(_cfg_home_iv + 1),a
;	src/link.c:400: cfg_hammer = BE16(p, 4);
	mov	a,_on_configure_sloc2_1_0
	orl	a,_on_configure_sloc1_1_0
	mov	_cfg_hammer,a
	mov	a,(_on_configure_sloc2_1_0 + 1)
	orl	a,(_on_configure_sloc1_1_0 + 1)
	mov	(_cfg_hammer + 1),a
;	src/link.c:401: cfg_settle = BE16(p, 6);
	mov	a,#0x06
	add	a,_on_configure_p_65536_93
	mov	r1,a
	mov	ar7,@r1
	mov	ar6,r7
	mov	r7,#0x00
	mov	a,#0x07
	add	a,_on_configure_p_65536_93
	mov	r1,a
	mov	ar5,@r1
	mov	r4,#0x00
	mov	a,r5
	orl	a,r7
	mov	_cfg_settle,a
	mov	a,r4
	orl	a,r6
	mov	(_cfg_settle + 1),a
;	src/link.c:403: fw_flags |= FL_CONFIGURED;
	orl	_fw_flags,#0x01
;	src/link.c:404: return 1;
	mov	dpl,#0x01
;	src/link.c:405: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_frame'
;------------------------------------------------------------
;f                         Allocated to registers r1 
;len                       Allocated to registers r7 
;seq                       Allocated to registers r6 
;type                      Allocated to registers r5 
;diff                      Allocated to registers r6 
;p                         Allocated to registers r4 
;------------------------------------------------------------
;	src/link.c:407: void fw_frame(FW_IDATA uint8_t *f) {
;	-----------------------------------------
;	 function fw_frame
;	-----------------------------------------
_fw_frame:
	mov	r1,dpl
;	src/link.c:408: uint8_t len = f[0], seq = f[1], type = f[2], diff;
	mov	ar7,@r1
	mov	a,r1
	inc	a
	mov	r0,a
	mov	ar6,@r0
	mov	a,#0x02
	add	a,r1
	mov	r0,a
	mov	ar5,@r0
;	src/link.c:409: const FW_IDATA uint8_t *p = f + 3;
	mov	a,#0x03
	add	a,r1
	mov	r4,a
;	src/link.c:410: if (type == T_HELLO) {
	cjne	r5,#0x01,00102$
;	src/link.c:411: on_hello(p, len, seq);
	mov	_on_hello_PARM_2,r7
	mov	_on_hello_PARM_3,r6
	mov	dpl,r4
;	src/link.c:412: return;
	ljmp	_on_hello
00102$:
;	src/link.c:414: if (!session) {
	mov	a,_session
	jnz	00104$
;	src/link.c:415: nak(NAK_NO_SESSION);
	mov	dpl,#0x03
;	src/link.c:416: return;
	ljmp	_nak
00104$:
;	src/link.c:418: diff = (uint8_t)(seq - expected);
	mov	a,r6
	clr	c
	subb	a,_expected
	mov	r6,a
;	src/link.c:419: if (diff >= 128) {
	cjne	r6,#0x80,00232$
00232$:
	jc	00106$
;	src/link.c:421: fw_ack();
;	src/link.c:422: return;
	ljmp	_fw_ack
00106$:
;	src/link.c:424: if (diff != 0) {
	mov	a,r6
	jz	00108$
;	src/link.c:425: nak(NAK_OUT_OF_ORDER);
	mov	dpl,#0x01
;	src/link.c:426: return;
	ljmp	_nak
00108$:
;	src/link.c:428: if (type == T_DATA) {
	cjne	r5,#0x03,00110$
;	src/link.c:429: on_data(f, len);
	mov	_on_data_PARM_2,r7
	mov	dpl,r1
;	src/link.c:430: return;
	ljmp	_on_data
00110$:
;	src/link.c:432: if (type < T_CONFIGURE || type > T_KEEPALIVE) {
	cjne	r5,#0x02,00237$
00237$:
	jc	00111$
	mov	a,r5
	add	a,#0xff - 0x08
	jnc	00112$
00111$:
;	src/link.c:433: nak(NAK_UNKNOWN_TYPE);
	mov	dpl,#0x05
;	src/link.c:434: return;
	ljmp	_nak
00112$:
;	src/link.c:436: if (type == T_CONFIGURE) {
	cjne	r5,#0x02,00117$
;	src/link.c:437: if (!on_configure(p, len)) {
	mov	_on_configure_PARM_2,r7
	mov	dpl,r4
	lcall	_on_configure
	mov	a,dpl
	jnz	00115$
;	src/link.c:438: nak(NAK_BAD_PAYLOAD);
	mov	dpl,#0x04
;	src/link.c:439: return;
	ljmp	_nak
00115$:
;	src/link.c:441: accept();
	lcall	_accept
;	src/link.c:442: fw_ack();
;	src/link.c:443: return;
	ljmp	_fw_ack
00117$:
;	src/link.c:445: if (len != 0) {
	mov	a,r7
	jz	00119$
;	src/link.c:446: nak(NAK_BAD_PAYLOAD);
	mov	dpl,#0x04
;	src/link.c:447: return;
	ljmp	_nak
00119$:
;	src/link.c:449: accept();
	push	ar5
	lcall	_accept
	pop	ar5
;	src/link.c:450: switch (type) {
	cjne	r5,#0x04,00244$
	sjmp	00120$
00244$:
	cjne	r5,#0x05,00245$
	sjmp	00128$
00245$:
	cjne	r5,#0x06,00246$
	sjmp	00135$
00246$:
	cjne	r5,#0x07,00247$
	ljmp	00138$
00247$:
	ljmp	00140$
;	src/link.c:451: case T_PAUSE:
00120$:
;	src/link.c:452: if (fw_state == ST_RUNNING || fw_state == ST_WAITING || fw_state == ST_HOMING) {
	mov	a,#0x01
	cjne	a,_fw_state,00248$
	sjmp	00124$
00248$:
	mov	a,#0x02
	cjne	a,_fw_state,00249$
	sjmp	00124$
00249$:
	mov	a,#0x05
	cjne	a,_fw_state,00250$
	sjmp	00251$
00250$:
	ljmp	00140$
00251$:
00124$:
;	src/link.c:453: if (exec_busy()) fw_pause_req = 1;
	lcall	_exec_busy
	mov	a,dpl
	jz	00122$
	mov	_fw_pause_req,#0x01
	sjmp	00140$
00122$:
;	src/link.c:454: else fw_state = ST_PAUSED;
	mov	_fw_state,#0x03
;	src/link.c:456: break;
;	src/link.c:457: case T_RESUME:
	sjmp	00140$
00128$:
;	src/link.c:458: fw_pause_req = 0;
	mov	_fw_pause_req,#0x00
;	src/link.c:459: fw_faults &= (uint8_t) ~(F_HOST_TIMEOUT | F_LIMIT | F_HAMMER | F_STREAM | F_UNDERRUN);
	anl	_fw_faults,#0x19
;	src/link.c:460: if (fw_paper_present()) fw_faults &= (uint8_t)~F_PAPER_OUT;
	lcall	_fw_paper_present
	mov	a,dpl
	jz	00130$
	anl	_fw_faults,#0xfe
00130$:
;	src/link.c:461: if ((fw_faults & (F_PAPER_OUT | F_POWER_ON | F_WARM_RESET)) == 0 &&
	mov	a,_fw_faults
	anl	a,#0x19
	jz	00255$
	sjmp	00140$
00255$:
;	src/link.c:462: (fw_state == ST_PAUSED || fw_state == ST_FAULT))
	mov	a,#0x03
	cjne	a,_fw_state,00256$
	sjmp	00131$
00256$:
	mov	a,#0x04
	cjne	a,_fw_state,00140$
00131$:
;	src/link.c:463: fw_state = (fw_flags & FL_JOB_ACTIVE) ? ST_RUNNING : ST_IDLE;
	mov	a,_fw_flags
	jnb	acc.4,00143$
	mov	r6,#0x01
	mov	r7,#0x00
	sjmp	00144$
00143$:
	mov	r6,#0x00
	mov	r7,#0x00
00144$:
	mov	_fw_state,r6
;	src/link.c:464: break;
;	src/link.c:465: case T_ABORT:
	sjmp	00140$
00135$:
;	src/link.c:466: exec_abort();
	lcall	_exec_abort
;	src/link.c:467: fw_flush();
	lcall	_fw_flush
;	src/link.c:468: fw_flags &= (uint8_t) ~(FL_JOB_ACTIVE | FL_PASS_ACTIVE);
	anl	_fw_flags,#0xeb
;	src/link.c:469: fw_pause_req = 0;
	mov	_fw_pause_req,#0x00
;	src/link.c:470: if ((fw_faults & (F_POWER_ON | F_WARM_RESET)) == 0) {
	mov	a,_fw_faults
	anl	a,#0x18
	jz	00261$
	sjmp	00140$
00261$:
;	src/link.c:471: fw_faults = 0;
	mov	_fw_faults,#0x00
;	src/link.c:472: fw_state = ST_IDLE;
	mov	_fw_state,#0x00
;	src/link.c:474: break;
;	src/link.c:475: case T_STATUS:
	sjmp	00140$
00138$:
;	src/link.c:476: rp_status = 1;
;	assignBit
	setb	_rp_status
;	src/link.c:477: due();
;	src/link.c:478: return;
;	src/link.c:480: }
	ljmp	_due
00140$:
;	src/link.c:481: fw_ack();
;	src/link.c:482: }
	ljmp	_fw_ack
	.area CSEG    (CODE)
	.area CONST   (CODE)
_chk_nib:
	.byte #0x00, #0x00	; 0
	.byte #0xb7, #0x8b	; 35767
	.byte #0xd9, #0x9c	; 40153
	.byte #0x6e, #0x17	; 5998
	.byte #0x05, #0xb2	; 45573
	.byte #0xb2, #0x39	; 14770
	.byte #0xdc, #0x2e	; 11996
	.byte #0x6b, #0xa5	; 42347
	.byte #0xbd, #0xef	; 61373
	.byte #0x0a, #0x64	; 25610
	.byte #0x64, #0x73	; 29540
	.byte #0xd3, #0xf8	; 63699
	.byte #0xb8, #0x5d	; 23992
	.byte #0x0f, #0xd6	; 54799
	.byte #0x61, #0xc1	; 49505
	.byte #0xd6, #0x4a	; 19158
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
