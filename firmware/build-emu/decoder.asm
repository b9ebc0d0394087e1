;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module decoder
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _crc16_block
	.globl _fw_frame
	.globl _fw_rx_reset
	.globl _fw_rx_busy
	.globl _fw_rx_fill
	.globl _fw_rx_byte
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
_rx_fill:
	.ds 1
_rx_sync:
	.ds 1
_scan_total_196608_22:
	.ds 1
_scan_sloc0_1_0:
	.ds 2
_fw_rx_byte_total_327680_34:
	.ds 1
_fw_rx_byte_sloc0_1_0:
	.ds 2
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
_move_down_PARM_2:
	.ds 1
_move_down_PARM_3:
	.ds 1
;--------------------------------------------------------
; indirectly addressable internal ram data
;--------------------------------------------------------
	.area ISEG    (DATA)
;--------------------------------------------------------
; absolute internal ram data
;--------------------------------------------------------
	.area IABS    (ABS,DATA)
	.area IABS    (ABS,DATA)
;--------------------------------------------------------
; bit data
;--------------------------------------------------------
	.area BSEG    (BIT)
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
;Allocation info for local variables in function 'fw_rx_reset'
;------------------------------------------------------------
;	src/decoder.c:9: void fw_rx_reset(void) {
;	-----------------------------------------
;	 function fw_rx_reset
;	-----------------------------------------
_fw_rx_reset:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
;	src/decoder.c:10: rx_fill = 0;
	mov	_rx_fill,#0x00
;	src/decoder.c:11: rx_sync = 0;
	mov	_rx_sync,#0x00
;	src/decoder.c:12: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_rx_busy'
;------------------------------------------------------------
;	src/decoder.c:14: uint8_t fw_rx_busy(void) { return rx_sync; }
;	-----------------------------------------
;	 function fw_rx_busy
;	-----------------------------------------
_fw_rx_busy:
	mov	dpl,_rx_sync
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_rx_fill'
;------------------------------------------------------------
;	src/decoder.c:15: uint8_t fw_rx_fill(void) { return rx_fill; }
;	-----------------------------------------
;	 function fw_rx_fill
;	-----------------------------------------
_fw_rx_fill:
	mov	dpl,_rx_fill
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'move_down'
;------------------------------------------------------------
;src                       Allocated with name '_move_down_PARM_2'
;n                         Allocated with name '_move_down_PARM_3'
;dst                       Allocated to registers 
;------------------------------------------------------------
;	src/decoder.c:19: static void move_down(FW_IDATA uint8_t *dst, const FW_IDATA uint8_t *src, uint8_t n) {
;	-----------------------------------------
;	 function move_down
;	-----------------------------------------
_move_down:
	mov	r1,dpl
;	src/decoder.c:20: while (n--) *dst++ = *src++;
	mov	r0,_move_down_PARM_2
	mov	r7,_move_down_PARM_3
00101$:
	mov	ar6,r7
	dec	r7
	mov	a,r6
	jz	00104$
	mov	ar6,@r0
	inc	r0
	mov	@r1,ar6
	inc	r1
	sjmp	00101$
00104$:
;	src/decoder.c:21: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'resync'
;------------------------------------------------------------
;skip                      Allocated to registers 
;r                         Allocated to registers r6 
;i                         Allocated to registers r7 
;------------------------------------------------------------
;	src/decoder.c:25: static void resync(uint8_t skip) {
;	-----------------------------------------
;	 function resync
;	-----------------------------------------
_resync:
	mov	r7,dpl
;	src/decoder.c:26: FW_IDATA uint8_t *r = fw_buf + fw_ops_end;
	mov	a,_fw_ops_end
	add	a,#_fw_buf
	mov	r6,a
;	src/decoder.c:28: while (i < rx_fill && r[i] != FW_SYNC) ++i;
00102$:
	clr	c
	mov	a,r7
	subb	a,_rx_fill
	jnc	00104$
	mov	a,r7
	add	a,r6
	mov	r1,a
	mov	ar5,@r1
	cjne	r5,#0x7e,00127$
	sjmp	00104$
00127$:
	inc	r7
	sjmp	00102$
00104$:
;	src/decoder.c:29: if (i >= rx_fill) {
	clr	c
	mov	a,r7
	subb	a,_rx_fill
	jc	00106$
;	src/decoder.c:30: rx_fill = 0;
	mov	_rx_fill,#0x00
;	src/decoder.c:31: rx_sync = 0;
	mov	_rx_sync,#0x00
;	src/decoder.c:32: return;
	ret
00106$:
;	src/decoder.c:34: ++i; /* past the SYNC */
	inc	r7
;	src/decoder.c:35: move_down(r, r + i, (uint8_t)(rx_fill - i));
	mov	a,r7
	add	a,r6
	mov	_move_down_PARM_2,a
	mov	a,_rx_fill
	clr	c
	subb	a,r7
	mov	_move_down_PARM_3,a
	mov	dpl,r6
	push	ar7
	lcall	_move_down
	pop	ar7
;	src/decoder.c:36: rx_fill = (uint8_t)(rx_fill - i);
	mov	a,_rx_fill
	clr	c
	subb	a,r7
	mov	_rx_fill,a
;	src/decoder.c:37: rx_sync = 1;
	mov	_rx_sync,#0x01
;	src/decoder.c:38: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'scan'
;------------------------------------------------------------
;r                         Allocated to registers 
;len                       Allocated to registers r5 
;room                      Allocated to registers r6 
;total                     Allocated with name '_scan_total_196608_22'
;left                      Allocated to registers r6 
;old_end                   Allocated to registers r5 
;from                      Allocated to registers 
;sloc0                     Allocated with name '_scan_sloc0_1_0'
;------------------------------------------------------------
;	src/decoder.c:41: static inline void scan(void) {
;	-----------------------------------------
;	 function scan
;	-----------------------------------------
_scan:
00115$:
;	src/decoder.c:45: if (!rx_sync || rx_fill == 0) return;
	mov	a,_rx_sync
	jz	00101$
	mov	a,_rx_fill
	jnz	00102$
00101$:
	ret
00102$:
;	src/decoder.c:46: r = fw_buf + fw_ops_end;
	mov	a,_fw_ops_end
	add	a,#_fw_buf
	mov	r7,a
;	src/decoder.c:47: room = (uint8_t)(FW_BUF_CAP - fw_ops_end);
	mov	r6,_fw_ops_end
	mov	a,#0x40
	clr	c
	subb	a,r6
	mov	r6,a
;	src/decoder.c:48: len = r[0];
	mov	r0,ar7
	mov	ar5,@r0
;	src/decoder.c:49: total = (uint8_t)(len + FW_FRAME_OVERHEAD);
	mov	ar4,r5
	mov	a,#0x05
	add	a,r4
	mov	r4,a
	mov	_scan_total_196608_22,r4
;	src/decoder.c:53: if (len > FW_WIRE_MAX_PAYLOAD || total > room) {
	mov	a,r5
	add	a,#0xff - 0x50
	jc	00104$
	mov	a,r6
	subb	a,_scan_total_196608_22
	jnc	00105$
00104$:
;	src/decoder.c:54: resync(0); /* from the LEN byte: it may itself be a SYNC */
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:55: continue;
	sjmp	00115$
00105$:
;	src/decoder.c:57: if (rx_fill < total) return;
	clr	c
	mov	a,_rx_fill
	subb	a,_scan_total_196608_22
	jnc	00108$
	ret
00108$:
;	src/decoder.c:58: if (crc16_block(r, (uint8_t)(total - 2), 0xFFFF) !=
	mov	r6,_scan_total_196608_22
	dec	r6
	dec	r6
	mov	_crc16_block_PARM_2,r6
	mov	_crc16_block_PARM_3,#0xff
	mov	(_crc16_block_PARM_3 + 1),#0xff
	mov	dpl,r7
	push	ar7
	lcall	_crc16_block
	mov	_scan_sloc0_1_0,dpl
	mov	(_scan_sloc0_1_0 + 1),dph
	pop	ar7
;	src/decoder.c:59: (uint16_t)(((uint16_t)r[total - 2] << 8) | r[total - 1])) {
	mov	r2,_scan_total_196608_22
	mov	r3,#0x00
	mov	a,r2
	add	a,#0xfe
	mov	r4,a
	mov	a,r3
	addc	a,#0xff
	mov	a,r4
	add	a,r7
	mov	r1,a
	mov	ar6,@r1
	mov	ar5,r6
	mov	r6,#0x00
	dec	r2
	cjne	r2,#0xff,00153$
	dec	r3
00153$:
	mov	a,r2
	add	a,r7
	mov	r1,a
	mov	ar4,@r1
	mov	r3,#0x00
	mov	a,r4
	orl	ar6,a
	mov	a,r3
	orl	ar5,a
	mov	a,r6
	cjne	a,_scan_sloc0_1_0,00154$
	mov	a,r5
	cjne	a,(_scan_sloc0_1_0 + 1),00154$
	sjmp	00110$
00154$:
;	src/decoder.c:60: resync(0); /* from the LEN byte: it may itself be a SYNC */
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:61: continue;
	ljmp	00115$
00110$:
;	src/decoder.c:66: uint8_t left = (uint8_t)(rx_fill - total);
	mov	a,_rx_fill
	clr	c
	subb	a,_scan_total_196608_22
	mov	r6,a
;	src/decoder.c:67: uint8_t old_end = fw_ops_end;
	mov	r5,_fw_ops_end
;	src/decoder.c:68: rx_fill = 0;
	mov	_rx_fill,#0x00
;	src/decoder.c:69: rx_sync = 0;
	mov	_rx_sync,#0x00
;	src/decoder.c:70: fw_frame(r);
	mov	dpl,r7
	push	ar6
	push	ar5
	lcall	_fw_frame
	pop	ar5
	pop	ar6
;	src/decoder.c:71: if (left) {
	mov	a,r6
	jnz	00155$
	ljmp	00115$
00155$:
;	src/decoder.c:72: FW_IDATA uint8_t *from = fw_buf + old_end + total;
	mov	a,r5
	add	a,#_fw_buf
	add	a,_scan_total_196608_22
	mov	_move_down_PARM_2,a
;	src/decoder.c:73: r = fw_buf + fw_ops_end;
	mov	a,_fw_ops_end
	add	a,#_fw_buf
	mov	dpl,a
;	src/decoder.c:74: move_down(r, from, left);
	mov	_move_down_PARM_3,r6
	push	ar6
	lcall	_move_down
	pop	ar6
;	src/decoder.c:75: rx_fill = left;
	mov	_rx_fill,r6
;	src/decoder.c:76: resync(0);
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:80: }
	ljmp	00115$
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_rx_byte'
;------------------------------------------------------------
;b                         Allocated to registers r7 
;r                         Allocated to registers 
;len                       Allocated to registers r5 
;room                      Allocated to registers r6 
;total                     Allocated with name '_fw_rx_byte_total_327680_34'
;left                      Allocated to registers r6 
;old_end                   Allocated to registers r5 
;from                      Allocated to registers 
;sloc0                     Allocated with name '_fw_rx_byte_sloc0_1_0'
;------------------------------------------------------------
;	src/decoder.c:82: void fw_rx_byte(uint8_t b) {
;	-----------------------------------------
;	 function fw_rx_byte
;	-----------------------------------------
_fw_rx_byte:
	mov	r7,dpl
;	src/decoder.c:83: if (!rx_sync) {
	mov	a,_rx_sync
	jnz	00104$
;	src/decoder.c:84: if (b == FW_SYNC) {
	cjne	r7,#0x7e,00102$
;	src/decoder.c:85: rx_sync = 1;
	mov	_rx_sync,#0x01
;	src/decoder.c:86: rx_fill = 0;
	mov	_rx_fill,#0x00
00102$:
;	src/decoder.c:88: return;
	ret
00104$:
;	src/decoder.c:91: fw_buf[fw_ops_end + rx_fill] = b;
	mov	a,_rx_fill
	add	a,_fw_ops_end
	add	a,#_fw_buf
	mov	r0,a
	mov	@r0,ar7
;	src/decoder.c:92: ++rx_fill;
	inc	_rx_fill
;	src/decoder.c:93: scan();
00120$:
;	src/decoder.c:45: if (!rx_sync || rx_fill == 0) return;
	mov	a,_rx_sync
	jnz	00171$
	ret
00171$:
	mov	a,_rx_fill
	jnz	00172$
	ret
00172$:
;	src/decoder.c:46: r = fw_buf + fw_ops_end;
	mov	a,_fw_ops_end
	add	a,#_fw_buf
	mov	r7,a
;	src/decoder.c:47: room = (uint8_t)(FW_BUF_CAP - fw_ops_end);
	mov	r6,_fw_ops_end
	mov	a,#0x40
	clr	c
	subb	a,r6
	mov	r6,a
;	src/decoder.c:48: len = r[0];
	mov	r0,ar7
	mov	ar5,@r0
;	src/decoder.c:49: total = (uint8_t)(len + FW_FRAME_OVERHEAD);
	mov	ar4,r5
	mov	a,#0x05
	add	a,r4
	mov	r4,a
	mov	_fw_rx_byte_total_327680_34,r4
;	src/decoder.c:53: if (len > FW_WIRE_MAX_PAYLOAD || total > room) {
	mov	a,r5
	add	a,#0xff - 0x50
	jc	00109$
	mov	a,r6
	subb	a,_fw_rx_byte_total_327680_34
	jnc	00110$
00109$:
;	src/decoder.c:54: resync(0); /* from the LEN byte: it may itself be a SYNC */
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:55: continue;
	sjmp	00120$
00110$:
;	src/decoder.c:57: if (rx_fill < total) return;
	clr	c
	mov	a,_rx_fill
	subb	a,_fw_rx_byte_total_327680_34
	jnc	00175$
	ret
00175$:
;	src/decoder.c:58: if (crc16_block(r, (uint8_t)(total - 2), 0xFFFF) !=
	mov	r6,_fw_rx_byte_total_327680_34
	dec	r6
	dec	r6
	mov	_crc16_block_PARM_2,r6
	mov	_crc16_block_PARM_3,#0xff
	mov	(_crc16_block_PARM_3 + 1),#0xff
	mov	dpl,r7
	push	ar7
	lcall	_crc16_block
	mov	_fw_rx_byte_sloc0_1_0,dpl
	mov	(_fw_rx_byte_sloc0_1_0 + 1),dph
	pop	ar7
;	src/decoder.c:59: (uint16_t)(((uint16_t)r[total - 2] << 8) | r[total - 1])) {
	mov	r2,_fw_rx_byte_total_327680_34
	mov	r3,#0x00
	mov	a,r2
	add	a,#0xfe
	mov	r4,a
	mov	a,r3
	addc	a,#0xff
	mov	a,r4
	add	a,r7
	mov	r1,a
	mov	ar6,@r1
	mov	ar5,r6
	mov	r6,#0x00
	dec	r2
	cjne	r2,#0xff,00176$
	dec	r3
00176$:
	mov	a,r2
	add	a,r7
	mov	r1,a
	mov	ar4,@r1
	mov	r3,#0x00
	mov	a,r4
	orl	ar6,a
	mov	a,r3
	orl	ar5,a
	mov	a,r6
	cjne	a,_fw_rx_byte_sloc0_1_0,00177$
	mov	a,r5
	cjne	a,(_fw_rx_byte_sloc0_1_0 + 1),00177$
	sjmp	00114$
00177$:
;	src/decoder.c:60: resync(0); /* from the LEN byte: it may itself be a SYNC */
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:61: continue;
	ljmp	00120$
00114$:
;	src/decoder.c:66: uint8_t left = (uint8_t)(rx_fill - total);
	mov	a,_rx_fill
	clr	c
	subb	a,_fw_rx_byte_total_327680_34
	mov	r6,a
;	src/decoder.c:67: uint8_t old_end = fw_ops_end;
	mov	r5,_fw_ops_end
;	src/decoder.c:68: rx_fill = 0;
	mov	_rx_fill,#0x00
;	src/decoder.c:69: rx_sync = 0;
	mov	_rx_sync,#0x00
;	src/decoder.c:70: fw_frame(r);
	mov	dpl,r7
	push	ar6
	push	ar5
	lcall	_fw_frame
	pop	ar5
	pop	ar6
;	src/decoder.c:71: if (left) {
	mov	a,r6
	jnz	00178$
	ljmp	00120$
00178$:
;	src/decoder.c:72: FW_IDATA uint8_t *from = fw_buf + old_end + total;
	mov	a,r5
	add	a,#_fw_buf
	add	a,_fw_rx_byte_total_327680_34
	mov	_move_down_PARM_2,a
;	src/decoder.c:73: r = fw_buf + fw_ops_end;
	mov	a,_fw_ops_end
	add	a,#_fw_buf
	mov	dpl,a
;	src/decoder.c:74: move_down(r, from, left);
	mov	_move_down_PARM_3,r6
	push	ar6
	lcall	_move_down
	pop	ar6
;	src/decoder.c:75: rx_fill = left;
	mov	_rx_fill,r6
;	src/decoder.c:76: resync(0);
	mov	dpl,#0x00
	lcall	_resync
;	src/decoder.c:93: scan();
;	src/decoder.c:94: }
	ljmp	00120$
	.area CSEG    (CODE)
	.area CONST   (CODE)
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
