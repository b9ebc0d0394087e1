;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module main
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _main
	.globl __sdcc_external_startup
	.globl _exec_poll
	.globl _exec_init
	.globl _io_tx_pump
	.globl _io_rx
	.globl _io_init
	.globl _motion_init
	.globl _fw_report_room
	.globl _fw_compact
	.globl _fw_link_init
	.globl _fw_rx_byte
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
	.globl _fw_paper_present
	.globl _fw_stack_used
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
_sig:
	.ds 2
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
	.area	OSEG    (OVR,DATA)
;--------------------------------------------------------
; Stack segment in internal ram
;--------------------------------------------------------
	.area	SSEG
__start__stack:
	.ds	1

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
_main_sloc0_1_0:
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
; interrupt vector
;--------------------------------------------------------
	.area HOME    (CODE)
__interrupt_vect:
	ljmp	__sdcc_gsinit_startup
	ljmp	_strobe_isr
	.ds	5
	reti
	.ds	7
	reti
	.ds	7
	reti
	.ds	7
	ljmp	_uart_isr
	.ds	5
	ljmp	_t2_isr
;--------------------------------------------------------
; global & static initialisations
;--------------------------------------------------------
	.area HOME    (CODE)
	.area GSINIT  (CODE)
	.area GSFINAL (CODE)
	.area GSINIT  (CODE)
	.globl __sdcc_gsinit_startup
	.globl __sdcc_program_startup
	.globl __start__stack
	.globl __mcs51_genXINIT
	.globl __mcs51_genXRAMCLEAR
	.globl __mcs51_genRAMCLEAR
	.area GSFINAL (CODE)
	ljmp	__sdcc_program_startup
;--------------------------------------------------------
; Home
;--------------------------------------------------------
	.area HOME    (CODE)
	.area HOME    (CODE)
__sdcc_program_startup:
	ljmp	_main
;	return from main will return to caller
;--------------------------------------------------------
; code
;--------------------------------------------------------
	.area CSEG    (CODE)
;------------------------------------------------------------
;Allocation info for local variables in function '_sdcc_external_startup'
;------------------------------------------------------------
;	src/main.c:26: unsigned char _sdcc_external_startup(void) {
;	-----------------------------------------
;	 function _sdcc_external_startup
;	-----------------------------------------
__sdcc_external_startup:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
;	src/main.c:27: EA = 0;
;	assignBit
	clr	_EA
;	src/main.c:28: return 1;
	mov	dpl,#0x01
;	src/main.c:29: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_paper_present'
;------------------------------------------------------------
;	src/main.c:31: uint8_t fw_paper_present(void) { return PAPER; }
;	-----------------------------------------
;	 function fw_paper_present
;	-----------------------------------------
_fw_paper_present:
	mov	c,_P3_6
	clr	a
	rlc	a
	mov	dpl,a
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'paint_stack'
;------------------------------------------------------------
;p                         Allocated to registers 
;------------------------------------------------------------
;	src/main.c:37: static void paint_stack(void) {
;	-----------------------------------------
;	 function paint_stack
;	-----------------------------------------
_paint_stack:
;	src/main.c:38: __idata uint8_t *p = (__idata uint8_t *)(SP + 4); /* past this call's frame */
	mov	r6,_SP
	mov	r7,#0x00
	mov	a,#0x04
	add	a,r6
	mov	r6,a
	clr	a
	addc	a,r7
	mov	ar1,r6
;	src/main.c:39: do {
00101$:
;	src/main.c:40: *p = PAINT;
	mov	@r1,#0xa5
	inc	r1
;	src/main.c:41: } while (++p != 0);
	mov	a,r1
	jnz	00101$
;	src/main.c:42: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fw_stack_used'
;------------------------------------------------------------
;p                         Allocated to registers r1 
;------------------------------------------------------------
;	src/main.c:44: uint8_t fw_stack_used(void) {
;	-----------------------------------------
;	 function fw_stack_used
;	-----------------------------------------
_fw_stack_used:
;	src/main.c:47: while (*p == PAINT && p != _start__stack) --p;
	mov	r1,#0xff
00102$:
	mov	ar7,@r1
	cjne	r7,#0xa5,00104$
	cjne	r1,#__start__stack,00122$
	sjmp	00104$
00122$:
	dec	r1
	sjmp	00102$
00104$:
;	src/main.c:48: return (uint8_t)(p - _start__stack + 1);
	mov	r7,#__start__stack
	mov	a,r1
	clr	c
	subb	a,r7
	inc	a
;	src/main.c:49: }
	mov	dpl,a
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'cold_state'
;------------------------------------------------------------
;	src/main.c:51: static void cold_state(void) {
;	-----------------------------------------
;	 function cold_state
;	-----------------------------------------
_cold_state:
;	src/main.c:52: fw_state = ST_IDLE;
	mov	_fw_state,#0x00
;	src/main.c:53: fw_faults = F_POWER_ON;
	mov	_fw_faults,#0x08
;	src/main.c:54: fw_flags = 0;
;	src/main.c:55: fw_job_id = 0;
	clr	a
	mov	_fw_flags,a
	mov	_fw_job_id,a
	mov	(_fw_job_id + 1),a
;	src/main.c:56: fw_executed = 0;
	mov	_fw_executed,a
	mov	(_fw_executed + 1),a
;	src/main.c:57: fw_pass_index = 0;
	mov	_fw_pass_index,a
	mov	(_fw_pass_index + 1),a
;	src/main.c:58: fw_sheet = 0;
	mov	_fw_sheet,a
	mov	(_fw_sheet + 1),a
;	src/main.c:59: fw_strikes_in_pass = 0;
;	1-genFromRTrack replaced	mov	_fw_strikes_in_pass,#0x00
	mov	_fw_strikes_in_pass,a
;	src/main.c:60: fw_skip = 0;
;	1-genFromRTrack replaced	mov	_fw_skip,#0x00
	mov	_fw_skip,a
;	src/main.c:61: fw_carriage = 0;
	mov	_fw_carriage,a
	mov	(_fw_carriage + 1),a
;	src/main.c:62: fw_feed = 0;
	mov	_fw_feed,a
	mov	(_fw_feed + 1),a
;	src/main.c:63: cfg_travel = cfg_home_iv = cfg_hammer = cfg_settle = 0;
	mov	_cfg_settle,a
	mov	(_cfg_settle + 1),a
	mov	_cfg_hammer,a
	mov	(_cfg_hammer + 1),a
	mov	_cfg_home_iv,a
	mov	(_cfg_home_iv + 1),a
	mov	_cfg_travel,a
	mov	(_cfg_travel + 1),a
;	src/main.c:64: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'main'
;------------------------------------------------------------
;warm                      Allocated to registers r7 
;b                         Allocated to registers r4 r5 
;------------------------------------------------------------
;	src/main.c:66: void main(void) {
;	-----------------------------------------
;	 function main
;	-----------------------------------------
_main:
;	src/main.c:67: uint8_t warm = sig[0] == SIG0 && sig[1] == SIG1;
	mov	a,#0x54
	cjne	a,_sig,00117$
	mov	a,#0xc5
	cjne	a,(_sig + 0x0001),00157$
	sjmp	00118$
00157$:
00117$:
;	assignBit
	clr	_main_sloc0_1_0
	sjmp	00119$
00118$:
;	assignBit
	setb	_main_sloc0_1_0
00119$:
	mov	c,_main_sloc0_1_0
	clr	a
	rlc	a
	mov	r7,a
;	src/main.c:69: P1 = 0x80; /* steps, hammers low; drivers enabled (P1.6 low); LED off */
	mov	_P1,#0x80
;	src/main.c:70: paint_stack();
	push	ar7
	lcall	_paint_stack
	pop	ar7
;	src/main.c:71: fw_pause_req = 0;
	mov	_fw_pause_req,#0x00
;	src/main.c:72: if (warm) {
	mov	a,r7
	jz	00105$
;	src/main.c:75: fw_faults |= F_WARM_RESET;
	orl	_fw_faults,#0x10
;	src/main.c:76: fw_flags &= (uint8_t)~(FL_HOMED | FL_PASS_ACTIVE);
	anl	_fw_flags,#0xf9
;	src/main.c:77: if (fw_flags & FL_JOB_ACTIVE) fw_state = ST_FAULT;
	mov	a,_fw_flags
	jnb	acc.4,00102$
	mov	_fw_state,#0x04
	sjmp	00106$
00102$:
;	src/main.c:78: else fw_state = ST_IDLE;
	mov	_fw_state,#0x00
	sjmp	00106$
00105$:
;	src/main.c:80: cold_state();
	push	ar7
	lcall	_cold_state
	pop	ar7
;	src/main.c:81: sig[0] = SIG0;
	mov	_sig,#0x54
;	src/main.c:82: sig[1] = SIG1;
	mov	(_sig + 0x0001),#0xc5
00106$:
;	src/main.c:84: fw_link_init(warm);
	mov	dpl,r7
	lcall	_fw_link_init
;	src/main.c:85: exec_init();
	lcall	_exec_init
;	src/main.c:86: motion_init();
	lcall	_motion_init
;	src/main.c:87: io_init();
	lcall	_io_init
;	src/main.c:88: EA = 1;
;	assignBit
	setb	_EA
;	src/main.c:90: while ((b = io_rx()) >= 0) fw_rx_byte((uint8_t)b);
00107$:
	lcall	_io_rx
	mov	r6,dpl
	mov	r7,dph
	mov	ar4,r6
	mov	a,r7
	jb	acc.7,00109$
	mov	dpl,r4
	lcall	_fw_rx_byte
	sjmp	00107$
00109$:
;	src/main.c:91: if (fw_ops_head > 0) fw_compact(); /* between bytes: the frame in progress moves too */
	mov	a,_fw_ops_head
	jz	00111$
	lcall	_fw_compact
00111$:
;	src/main.c:92: exec_poll();
	lcall	_exec_poll
;	src/main.c:93: fw_report_room();
	lcall	_fw_report_room
;	src/main.c:94: io_tx_pump();
	lcall	_io_tx_pump
;	src/main.c:95: LED = !(fw_state == ST_RUNNING || fw_state == ST_HOMING);
	mov	a,#0x01
	cjne	a,_fw_state,00162$
	sjmp	00121$
00162$:
	mov	a,#0x05
	cjne	a,_fw_state,00163$
	sjmp	00121$
00163$:
;	assignBit
	clr	_main_sloc0_1_0
	sjmp	00122$
00121$:
;	assignBit
	setb	_main_sloc0_1_0
00122$:
	cpl	_main_sloc0_1_0
	mov	c,_main_sloc0_1_0
	clr	a
	rlc	a
	add	a,#0xff
	mov	_P1_7,c
;	src/main.c:97: }
	sjmp	00107$
	.area CSEG    (CODE)
	.area CONST   (CODE)
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
