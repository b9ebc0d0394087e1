;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module uart
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _strobe_isr
	.globl _uart_isr
	.globl _fw_reply_byte
	.globl _TF2
	.globl _EXF2
	.globl _RCLK
	.globl _TCLK
	.globl _EXEN2
	.globl _TR2
	.globl _C_T2
	.globl _CP_RL2
	.globl _T2CON_7
	.globl _T2CON_6
	.globl _T2CON_5
	.globl _T2CON_4
	.globl _T2CON_3
	.globl _T2CON_2
	.globl _T2CON_1
	.globl _T2CON_0
	.globl _PT2
	.globl _ET2
	.globl _CY
	.globl _AC
	.globl _F0
	.globl _RS1
	.globl _RS0
	.globl _OV
	.globl _F1
	.globl _P
	.globl _PS
	.globl _PT1
	.globl _PX1
	.globl _PT0
	.globl _PX0
	.globl _RD
	.globl _WR
	.globl _T1
	.globl _T0
	.globl _INT1
	.globl _INT0
	.globl _TXD
	.globl _RXD
	.globl _P3_7
	.globl _P3_6
	.globl _P3_5
	.globl _P3_4
	.globl _P3_3
	.globl _P3_2
	.globl _P3_1
	.globl _P3_0
	.globl _EA
	.globl _ES
	.globl _ET1
	.globl _EX1
	.globl _ET0
	.globl _EX0
	.globl _P2_7
	.globl _P2_6
	.globl _P2_5
	.globl _P2_4
	.globl _P2_3
	.globl _P2_2
	.globl _P2_1
	.globl _P2_0
	.globl _SM0
	.globl _SM1
	.globl _SM2
	.globl _REN
	.globl _TB8
	.globl _RB8
	.globl _TI
	.globl _RI
	.globl _P1_7
	.globl _P1_6
	.globl _P1_5
	.globl _P1_4
	.globl _P1_3
	.globl _P1_2
	.globl _P1_1
	.globl _P1_0
	.globl _TF1
	.globl _TR1
	.globl _TF0
	.globl _TR0
	.globl _IE1
	.globl _IT1
	.globl _IE0
	.globl _IT0
	.globl _P0_7
	.globl _P0_6
	.globl _P0_5
	.globl _P0_4
	.globl _P0_3
	.globl _P0_2
	.globl _P0_1
	.globl _P0_0
	.globl _TH2
	.globl _TL2
	.globl _RCAP2H
	.globl _RCAP2L
	.globl _T2CON
	.globl _B
	.globl _ACC
	.globl _PSW
	.globl _IP
	.globl _P3
	.globl _IE
	.globl _P2
	.globl _SBUF
	.globl _SCON
	.globl _P1
	.globl _TH1
	.globl _TH0
	.globl _TL1
	.globl _TL0
	.globl _TMOD
	.globl _TCON
	.globl _PCON
	.globl _DPH
	.globl _DPL
	.globl _SP
	.globl _P0
	.globl _io_init
	.globl _io_rx
	.globl _io_tx_pump
	.globl _fw_tx_kick
;--------------------------------------------------------
; special function registers
;--------------------------------------------------------
	.area RSEG    (ABS,DATA)
	.org 0x0000
_P0	=	0x0080
_SP	=	0x0081
_DPL	=	0x0082
_DPH	=	0x0083
_PCON	=	0x0087
_TCON	=	0x0088
_TMOD	=	0x0089
_TL0	=	0x008a
_TL1	=	0x008b
_TH0	=	0x008c
_TH1	=	0x008d
_P1	=	0x0090
_SCON	=	0x0098
_SBUF	=	0x0099
_P2	=	0x00a0
_IE	=	0x00a8
_P3	=	0x00b0
_IP	=	0x00b8
_PSW	=	0x00d0
_ACC	=	0x00e0
_B	=	0x00f0
_T2CON	=	0x00c8
_RCAP2L	=	0x00ca
_RCAP2H	=	0x00cb
_TL2	=	0x00cc
_TH2	=	0x00cd
;--------------------------------------------------------
; special function bits
;--------------------------------------------------------
	.area RSEG    (ABS,DATA)
	.org 0x0000
_P0_0	=	0x0080
_P0_1	=	0x0081
_P0_2	=	0x0082
_P0_3	=	0x0083
_P0_4	=	0x0084
_P0_5	=	0x0085
_P0_6	=	0x0086
_P0_7	=	0x0087
_IT0	=	0x0088
_IE0	=	0x0089
_IT1	=	0x008a
_IE1	=	0x008b
_TR0	=	0x008c
_TF0	=	0x008d
_TR1	=	0x008e
_TF1	=	0x008f
_P1_0	=	0x0090
_P1_1	=	0x0091
_P1_2	=	0x0092
_P1_3	=	0x0093
_P1_4	=	0x0094
_P1_5	=	0x0095
_P1_6	=	0x0096
_P1_7	=	0x0097
_RI	=	0x0098
_TI	=	0x0099
_RB8	=	0x009a
_TB8	=	0x009b
_REN	=	0x009c
_SM2	=	0x009d
_SM1	=	0x009e
_SM0	=	0x009f
_P2_0	=	0x00a0
_P2_1	=	0x00a1
_P2_2	=	0x00a2
_P2_3	=	0x00a3
_P2_4	=	0x00a4
_P2_5	=	0x00a5
_P2_6	=	0x00a6
_P2_7	=	0x00a7
_EX0	=	0x00a8
_ET0	=	0x00a9
_EX1	=	0x00aa
_ET1	=	0x00ab
_ES	=	0x00ac
_EA	=	0x00af
_P3_0	=	0x00b0
_P3_1	=	0x00b1
_P3_2	=	0x00b2
_P3_3	=	0x00b3
_P3_4	=	0x00b4
_P3_5	=	0x00b5
_P3_6	=	0x00b6
_P3_7	=	0x00b7
_RXD	=	0x00b0
_TXD	=	0x00b1
_INT0	=	0x00b2
_INT1	=	0x00b3
_T0	=	0x00b4
_T1	=	0x00b5
_WR	=	0x00b6
_RD	=	0x00b7
_PX0	=	0x00b8
_PT0	=	0x00b9
_PX1	=	0x00ba
_PT1	=	0x00bb
_PS	=	0x00bc
_P	=	0x00d0
_F1	=	0x00d1
_OV	=	0x00d2
_RS0	=	0x00d3
_RS1	=	0x00d4
_F0	=	0x00d5
_AC	=	0x00d6
_CY	=	0x00d7
_ET2	=	0x00ad
_PT2	=	0x00bd
_T2CON_0	=	0x00c8
_T2CON_1	=	0x00c9
_T2CON_2	=	0x00ca
_T2CON_3	=	0x00cb
_T2CON_4	=	0x00cc
_T2CON_5	=	0x00cd
_T2CON_6	=	0x00ce
_T2CON_7	=	0x00cf
_CP_RL2	=	0x00c8
_C_T2	=	0x00c9
_TR2	=	0x00ca
_EXEN2	=	0x00cb
_TCLK	=	0x00cc
_RCLK	=	0x00cd
_EXF2	=	0x00ce
_TF2	=	0x00cf
;--------------------------------------------------------
; overlayable register banks
;--------------------------------------------------------
	.area REG_BANK_0	(REL,OVR,DATA)
	.ds 8
;--------------------------------------------------------
; internal ram data
;--------------------------------------------------------
	.area DSEG    (DATA)
_rx_w:
	.ds 1
_rx_r:
	.ds 1
_tx_next:
	.ds 1
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
;--------------------------------------------------------
; indirectly addressable internal ram data
;--------------------------------------------------------
	.area ISEG    (DATA)
_rxq:
	.ds 8
;--------------------------------------------------------
; absolute internal ram data
;--------------------------------------------------------
	.area IABS    (ABS,DATA)
	.area IABS    (ABS,DATA)
;--------------------------------------------------------
; bit data
;--------------------------------------------------------
	.area BSEG    (BIT)
_tx_have:
	.ds 1
_tx_busy:
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
;Allocation info for local variables in function 'io_init'
;------------------------------------------------------------
;	src/uart.c:22: void io_init(void) {
;	-----------------------------------------
;	 function io_init
;	-----------------------------------------
_io_init:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
;	src/uart.c:23: rx_w = rx_r = 0;
	mov	_rx_r,#0x00
	mov	_rx_w,#0x00
;	src/uart.c:24: tx_busy = 0;
;	assignBit
	clr	_tx_busy
;	src/uart.c:25: tx_have = 0;
;	assignBit
	clr	_tx_have
;	src/uart.c:26: TMOD = (TMOD & 0x0F) | 0x20; /* timer 1: 8-bit auto-reload */
	mov	a,_TMOD
	anl	a,#0x0f
	orl	a,#0x20
	mov	_TMOD,a
;	src/uart.c:27: TH1 = TL1 = (uint8_t)TH1_RELOAD;
	mov	_TL1,#0xfa
	mov	_TH1,#0xfa
;	src/uart.c:28: PCON |= 0x80;                /* SMOD */
	orl	_PCON,#0x80
;	src/uart.c:29: SCON = 0x50;                 /* mode 1, receiver on */
	mov	_SCON,#0x50
;	src/uart.c:30: TR1 = 1;
;	assignBit
	setb	_TR1
;	src/uart.c:31: ES = 1;
;	assignBit
	setb	_ES
;	src/uart.c:33: LPT_BUSY = 0;
;	assignBit
	clr	_P3_4
;	src/uart.c:34: LPT_ACK = 1;
;	assignBit
	setb	_P3_5
;	src/uart.c:35: IT0 = 1;
;	assignBit
	setb	_IT0
;	src/uart.c:36: EX0 = 1;
;	assignBit
	setb	_EX0
;	src/uart.c:37: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'uart_isr'
;------------------------------------------------------------
;	src/uart.c:49: void uart_isr(void) __interrupt(SI0_VECTOR) {
;	-----------------------------------------
;	 function uart_isr
;	-----------------------------------------
_uart_isr:
	push	acc
	push	ar7
	push	ar0
	push	psw
	mov	psw,#0x00
;	src/uart.c:50: if (RI) {
;	src/uart.c:51: RI = 0;
;	assignBit
	jbc	_RI,00131$
	sjmp	00107$
00131$:
;	src/uart.c:52: RX_PUT(SBUF);
	mov	a,_rx_w
	clr	c
	subb	a,_rx_r
	mov	r7,a
	cjne	r7,#0x08,00132$
00132$:
	jnc	00107$
	mov	a,#0x07
	anl	a,_rx_w
	add	a,#_rxq
	mov	r0,a
	mov	@r0,_SBUF
	inc	_rx_w
00107$:
;	src/uart.c:54: if (TI) {
;	src/uart.c:55: TI = 0;
;	assignBit
	jbc	_TI,00134$
	sjmp	00113$
00134$:
;	src/uart.c:56: if (tx_have) {
	jnb	_tx_have,00109$
;	src/uart.c:57: SBUF = tx_next;
	mov	_SBUF,_tx_next
;	src/uart.c:58: tx_have = 0;
;	assignBit
	clr	_tx_have
	sjmp	00113$
00109$:
;	src/uart.c:60: tx_busy = 0;
;	assignBit
	clr	_tx_busy
00113$:
;	src/uart.c:63: }
	pop	psw
	pop	ar0
	pop	ar7
	pop	acc
	reti
;	eliminated unneeded push/pop ar1
;	eliminated unneeded push/pop dpl
;	eliminated unneeded push/pop dph
;	eliminated unneeded push/pop b
;------------------------------------------------------------
;Allocation info for local variables in function 'strobe_isr'
;------------------------------------------------------------
;	src/uart.c:67: void strobe_isr(void) __interrupt(IE0_VECTOR) {
;	-----------------------------------------
;	 function strobe_isr
;	-----------------------------------------
_strobe_isr:
	push	acc
	push	ar7
	push	ar0
	push	psw
	mov	psw,#0x00
;	src/uart.c:68: LPT_BUSY = 1;
;	assignBit
	setb	_P3_4
;	src/uart.c:69: RX_PUT(P0);
	mov	a,_rx_w
	clr	c
	subb	a,_rx_r
	mov	r7,a
	cjne	r7,#0x08,00118$
00118$:
	jnc	00104$
	mov	a,#0x07
	anl	a,_rx_w
	add	a,#_rxq
	mov	r0,a
	mov	@r0,_P0
	inc	_rx_w
00104$:
;	src/uart.c:70: LPT_ACK = 0;
;	assignBit
	clr	_P3_5
;	src/uart.c:71: __asm nop __endasm;
	nop	
;	src/uart.c:72: __asm nop __endasm;
	nop	
;	src/uart.c:73: __asm nop __endasm;
	nop	
;	src/uart.c:74: __asm nop __endasm;
	nop	
;	src/uart.c:75: LPT_ACK = 1;
;	assignBit
	setb	_P3_5
;	src/uart.c:76: if ((uint8_t)(rx_w - rx_r) < RXQ - 2) LPT_BUSY = 0;
	mov	a,_rx_w
	clr	c
	subb	a,_rx_r
	mov	r7,a
	cjne	r7,#0x06,00120$
00120$:
	jnc	00108$
;	assignBit
	clr	_P3_4
00108$:
;	src/uart.c:77: }
	pop	psw
	pop	ar0
	pop	ar7
	pop	acc
	reti
;	eliminated unneeded push/pop ar1
;	eliminated unneeded push/pop dpl
;	eliminated unneeded push/pop dph
;	eliminated unneeded push/pop b
;------------------------------------------------------------
;Allocation info for local variables in function 'io_rx'
;------------------------------------------------------------
;b                         Allocated to registers r7 
;------------------------------------------------------------
;	src/uart.c:79: int16_t io_rx(void) {
;	-----------------------------------------
;	 function io_rx
;	-----------------------------------------
_io_rx:
;	src/uart.c:81: if (rx_r == rx_w) {
	mov	a,_rx_w
	cjne	a,_rx_r,00104$
;	src/uart.c:82: if (LPT_BUSY) LPT_BUSY = 0; /* room again */
;	assignBit
	jbc	_P3_4,00117$
	sjmp	00102$
00117$:
00102$:
;	src/uart.c:83: return -1;
	mov	dptr,#0xffff
	ret
00104$:
;	src/uart.c:85: b = rxq[rx_r & (RXQ - 1)];
	mov	a,#0x07
	anl	a,_rx_r
	add	a,#_rxq
	mov	r1,a
	mov	ar7,@r1
;	src/uart.c:86: ++rx_r;
	inc	_rx_r
;	src/uart.c:87: return b;
	mov	r6,#0x00
	mov	dpl,r7
	mov	dph,r6
;	src/uart.c:88: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'io_tx_pump'
;------------------------------------------------------------
;b                         Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/uart.c:92: void io_tx_pump(void) {
;	-----------------------------------------
;	 function io_tx_pump
;	-----------------------------------------
_io_tx_pump:
;	src/uart.c:94: if (tx_have) return;
	jnb	_tx_have,00102$
	ret
00102$:
;	src/uart.c:95: b = fw_reply_byte();
	lcall	_fw_reply_byte
	mov	r6,dpl
	mov	r7,dph
;	src/uart.c:96: if (b < 0) return;
	mov	ar5,r7
	mov	a,r5
	jnb	acc.7,00104$
	ret
00104$:
;	src/uart.c:97: tx_next = (uint8_t)b;
	mov	_tx_next,r6
;	src/uart.c:98: tx_have = 1;
;	assignBit
	setb	_tx_have
;	src/uart.c:99: if (!tx_busy) {
	jb	_tx_busy,00107$
;	src/uart.c:100: tx_busy = 1;
;	assignBit
	setb	_tx_busy
;	src/uart.c:101: TI = 1; /* the interrupt sends it */
;	assignBit
	setb	_TI
00107$:
;	src/uart.c:103: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_tx_kick'
;------------------------------------------------------------
;	src/uart.c:105: void fw_tx_kick(void) {}
;	-----------------------------------------
;	 function fw_tx_kick
;	-----------------------------------------
_fw_tx_kick:
	ret
	.area CSEG    (CODE)
	.area CONST   (CODE)
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
