;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module crc16
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _crc16_update_PARM_2
	.globl _crc16_block_PARM_3
	.globl _crc16_block_PARM_2
	.globl _crc16_update
	.globl _crc16_block
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
_crc16_block_PARM_2:
	.ds 1
_crc16_block_PARM_3:
	.ds 2
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
_crc16_update_PARM_2:
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
;Allocation info for local variables in function 'crc16_update'
;------------------------------------------------------------
;b                         Allocated with name '_crc16_update_PARM_2'
;crc                       Allocated to registers r4 r5 
;------------------------------------------------------------
;	src/crc16.c:13: uint16_t crc16_update(uint16_t crc, uint8_t b) {
;	-----------------------------------------
;	 function crc16_update
;	-----------------------------------------
_crc16_update:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
	mov	r6,dpl
	mov	r7,dph
;	src/crc16.c:14: crc = (uint16_t)((uint16_t)(crc << 4) ^ crc_nib[(uint8_t)((crc >> 12) ^ (b >> 4))]);
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
	mov	a,_crc16_update_PARM_2
	swap	a
	anl	a,#0x0f
	xrl	a,r6
	mov	b,#0x02
	mul	ab
	add	a,#_crc_nib
	mov	dpl,a
	mov	a,#(_crc_nib >> 8)
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
;	src/crc16.c:15: crc = (uint16_t)((uint16_t)(crc << 4) ^ crc_nib[(uint8_t)((crc >> 12) ^ (b & 0x0F))]);
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
	mov	a,_crc16_update_PARM_2
	anl	a,#0x0f
	xrl	a,r4
	mov	b,#0x02
	mul	ab
	add	a,#_crc_nib
	mov	dpl,a
	mov	a,#(_crc_nib >> 8)
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
;	src/crc16.c:16: return crc;
;	src/crc16.c:17: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'crc16_block'
;------------------------------------------------------------
;n                         Allocated with name '_crc16_block_PARM_2'
;crc                       Allocated with name '_crc16_block_PARM_3'
;p                         Allocated to registers 
;------------------------------------------------------------
;	src/crc16.c:19: uint16_t crc16_block(const FW_IDATA uint8_t *p, uint8_t n, uint16_t crc) {
;	-----------------------------------------
;	 function crc16_block
;	-----------------------------------------
_crc16_block:
	mov	r1,dpl
;	src/crc16.c:20: while (n--) crc = crc16_update(crc, *p++);
	mov	r7,_crc16_block_PARM_2
00101$:
	mov	ar6,r7
	dec	r7
	mov	a,r6
	jz	00103$
	mov	_crc16_update_PARM_2,@r1
	inc	r1
	mov	dpl,_crc16_block_PARM_3
	mov	dph,(_crc16_block_PARM_3 + 1)
	push	ar7
	push	ar1
	lcall	_crc16_update
	mov	_crc16_block_PARM_3,dpl
	mov	(_crc16_block_PARM_3 + 1),dph
	pop	ar1
	pop	ar7
	sjmp	00101$
00103$:
;	src/crc16.c:21: return crc;
	mov	dpl,_crc16_block_PARM_3
	mov	dph,(_crc16_block_PARM_3 + 1)
;	src/crc16.c:22: }
	ret
	.area CSEG    (CODE)
	.area CONST   (CODE)
_crc_nib:
	.byte #0x00, #0x00	; 0
	.byte #0x21, #0x10	; 4129
	.byte #0x42, #0x20	; 8258
	.byte #0x63, #0x30	; 12387
	.byte #0x84, #0x40	; 16516
	.byte #0xa5, #0x50	; 20645
	.byte #0xc6, #0x60	; 24774
	.byte #0xe7, #0x70	; 28903
	.byte #0x08, #0x81	; 33032
	.byte #0x29, #0x91	; 37161
	.byte #0x4a, #0xa1	; 41290
	.byte #0x6b, #0xb1	; 45419
	.byte #0x8c, #0xc1	; 49548
	.byte #0xad, #0xd1	; 53677
	.byte #0xce, #0xe1	; 57806
	.byte #0xef, #0xf1	; 61935
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
