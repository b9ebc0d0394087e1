;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module exec
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _exec_poll
	.globl _exec_init
	.globl _motion_stop
	.globl _wait_ticks
	.globl _move_constant
	.globl _move_feed
	.globl _move_carriage
	.globl _fw_starved
	.globl _fw_ack
	.globl _fw_flush
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
	.globl _exec_busy
	.globl _exec_abort
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
_xs:
	.ds 1
_p_flags:
	.ds 1
_p_left:
	.ds 1
_p_first:
	.ds 2
_vi:
	.ds 1
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
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
_c_neg:
	.ds 1
_f_neg:
	.ds 1
_ham_ccv:
	.ds 1
_p_is_first:
	.ds 1
_exec_busy_sloc0_1_0:
	.ds 1
_neg:
	.ds 1
_svar_sloc0_1_0:
	.ds 1
_pass_begin_sloc0_1_0:
	.ds 1
_strike_move_sloc0_1_0:
	.ds 1
_fetch_sloc0_1_0:
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
;Allocation info for local variables in function 'exec_busy'
;------------------------------------------------------------
;	src/exec.c:32: uint8_t exec_busy(void) { return xs != X_FETCH || !mv_done; }
;	-----------------------------------------
;	 function exec_busy
;	-----------------------------------------
_exec_busy:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
	mov	a,_xs
	jnz	00104$
	jnb	_mv_done,00104$
;	assignBit
	clr	_exec_busy_sloc0_1_0
	sjmp	00105$
00104$:
;	assignBit
	setb	_exec_busy_sloc0_1_0
00105$:
	mov	c,_exec_busy_sloc0_1_0
	clr	a
	rlc	a
	mov	dpl,a
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'exec_abort'
;------------------------------------------------------------
;	src/exec.c:34: void exec_abort(void) {
;	-----------------------------------------
;	 function exec_abort
;	-----------------------------------------
_exec_abort:
;	src/exec.c:37: if (!mv_done) fw_flags &= (uint8_t)~FL_HOMED;
	jb	_mv_done,00102$
	anl	_fw_flags,#0xfd
00102$:
;	src/exec.c:38: motion_stop();
	lcall	_motion_stop
;	src/exec.c:39: HAM_CVX = 0;
;	assignBit
	clr	_P1_4
;	src/exec.c:40: HAM_CCV = 0;
;	assignBit
	clr	_P1_5
;	src/exec.c:41: xs = X_FETCH;
	mov	_xs,#0x00
;	src/exec.c:42: fw_flags &= (uint8_t)~FL_PASS_ACTIVE;
	anl	_fw_flags,#0xfb
;	src/exec.c:43: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'exec_init'
;------------------------------------------------------------
;	src/exec.c:45: void exec_init(void) {
;	-----------------------------------------
;	 function exec_init
;	-----------------------------------------
_exec_init:
;	src/exec.c:46: xs = X_FETCH;
	mov	_xs,#0x00
;	src/exec.c:47: c_neg = 0;
;	assignBit
	clr	_c_neg
;	src/exec.c:48: f_neg = 0;
;	assignBit
	clr	_f_neg
;	src/exec.c:49: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fault'
;------------------------------------------------------------
;bits                      Allocated to registers r7 
;------------------------------------------------------------
;	src/exec.c:51: static void fault(uint8_t bits) {
;	-----------------------------------------
;	 function fault
;	-----------------------------------------
_fault:
	mov	r7,dpl
;	src/exec.c:52: exec_abort();
	push	ar7
	lcall	_exec_abort
	pop	ar7
;	src/exec.c:53: fw_faults |= bits;
	mov	a,r7
	orl	_fw_faults,a
;	src/exec.c:54: fw_state = ST_FAULT;
	mov	_fw_state,#0x04
;	src/exec.c:55: fw_flush();
	lcall	_fw_flush
;	src/exec.c:56: fw_ack();
;	src/exec.c:57: }
	ljmp	_fw_ack
;------------------------------------------------------------
;Allocation info for local variables in function 'at'
;------------------------------------------------------------
;i                         Allocated to registers r7 
;------------------------------------------------------------
;	src/exec.c:59: static uint8_t at(uint8_t i) { return fw_buf[fw_ops_head + i]; }
;	-----------------------------------------
;	 function at
;	-----------------------------------------
_at:
	mov	a,dpl
	add	a,_fw_ops_head
	add	a,#_fw_buf
	mov	r1,a
	mov	dpl,@r1
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'carriage'
;------------------------------------------------------------
;steps                     Allocated to registers r6 r7 
;motor                     Allocated to registers r4 r5 
;------------------------------------------------------------
;	src/exec.c:64: static void carriage(uint16_t steps) {
;	-----------------------------------------
;	 function carriage
;	-----------------------------------------
_carriage:
	mov	r6,dpl
	mov	r7,dph
;	src/exec.c:65: uint16_t motor = steps;
	mov	ar4,r6
	mov	ar5,r7
;	src/exec.c:66: if (steps == 0) return;
	mov	a,r6
	orl	a,r7
	jnz	00102$
	ret
00102$:
;	src/exec.c:67: if (neg != c_neg) motor += C_BACKLASH;
	mov	c,_neg
	jb	_c_neg,00123$
	cpl	c
00123$:
	jc	00104$
	inc	r6
	cjne	r6,#0x00,00125$
	inc	r7
00125$:
	mov	ar4,r6
	mov	ar5,r7
00104$:
;	src/exec.c:68: c_neg = neg;
;	assignBit
	mov	c,_neg
	mov	_c_neg,c
;	src/exec.c:69: CDIR = !neg;
	mov	c,_neg
	cpl	c
	mov	_P1_1,c
;	src/exec.c:70: if (neg) fw_carriage -= (int16_t)motor;
	jnb	_neg,00106$
	mov	ar6,r4
	mov	ar7,r5
	mov	a,_fw_carriage
	clr	c
	subb	a,r6
	mov	_fw_carriage,a
	mov	a,(_fw_carriage + 1)
	subb	a,r7
	mov	(_fw_carriage + 1),a
	sjmp	00107$
00106$:
;	src/exec.c:71: else fw_carriage += (int16_t)motor;
	mov	ar6,r4
	mov	ar7,r5
	mov	a,r6
	add	a,_fw_carriage
	mov	_fw_carriage,a
	mov	a,r7
	addc	a,(_fw_carriage + 1)
	mov	(_fw_carriage + 1),a
00107$:
;	src/exec.c:72: move_carriage(motor);
	mov	dpl,r4
	mov	dph,r5
;	src/exec.c:73: }
	ljmp	_move_carriage
;------------------------------------------------------------
;Allocation info for local variables in function 'uvar'
;------------------------------------------------------------
;b                         Allocated to registers r7 
;------------------------------------------------------------
;	src/exec.c:78: static uint16_t uvar(void) {
;	-----------------------------------------
;	 function uvar
;	-----------------------------------------
_uvar:
;	src/exec.c:79: uint8_t b = at(vi++);
	mov	dpl,_vi
	inc	_vi
	lcall	_at
;	src/exec.c:80: if (!(b & 0x80)) return b;
	mov	a,dpl
	mov	r7,a
	jb	acc.7,00102$
	mov	ar5,r7
	mov	r6,#0x00
	mov	dpl,r5
	mov	dph,r6
	ret
00102$:
;	src/exec.c:81: return (uint16_t)(((uint16_t)(b & 0x7F) << 8) | at(vi++));
	anl	ar7,#0x7f
	mov	ar6,r7
	mov	r7,#0x00
	mov	dpl,_vi
	inc	_vi
	push	ar7
	push	ar6
	lcall	_at
	mov	r5,dpl
	pop	ar6
	pop	ar7
	mov	r4,#0x00
	mov	a,r5
	orl	a,r7
	mov	dpl,a
	mov	a,r4
	orl	a,r6
	mov	dph,a
;	src/exec.c:82: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'svar'
;------------------------------------------------------------
;two                       Allocated to registers r7 
;u                         Allocated to registers r5 r6 
;------------------------------------------------------------
;	src/exec.c:83: static int16_t svar(void) {
;	-----------------------------------------
;	 function svar
;	-----------------------------------------
_svar:
;	src/exec.c:84: uint8_t two = (at(vi) & 0x80) != 0;
	mov	dpl,_vi
	lcall	_at
	mov	r7,dpl
	anl	ar7,#0x80
	mov	r6,#0x00
	mov	a,r7
	orl	a,r6
	cjne	a,#0x01,00121$
00121$:
	cpl	c
	mov	_svar_sloc0_1_0,c
	clr	a
	rlc	a
	mov	r7,a
;	src/exec.c:85: uint16_t u = uvar();
	push	ar7
	lcall	_uvar
	mov	r5,dpl
	mov	r6,dph
	pop	ar7
;	src/exec.c:86: if (two) return (u & 0x4000) ? (int16_t)(u | 0x8000) : (int16_t)u;
	mov	a,r7
	jz	00102$
	mov	a,r6
	jnb	acc.6,00105$
	mov	ar4,r5
	mov	ar7,r6
	orl	ar7,#0x80
	sjmp	00106$
00105$:
	mov	ar4,r5
	mov	ar7,r6
00106$:
	mov	dpl,r4
	mov	dph,r7
	ret
00102$:
;	src/exec.c:87: return (u & 0x40) ? (int16_t)u - 128 : (int16_t)u;
	mov	a,r5
	jnb	acc.6,00107$
	mov	ar4,r5
	mov	ar7,r6
	mov	a,r4
	add	a,#0x80
	mov	r4,a
	mov	a,r7
	addc	a,#0xff
	mov	r7,a
	sjmp	00108$
00107$:
	mov	ar4,r5
	mov	ar7,r6
00108$:
	mov	dpl,r4
	mov	dph,r7
;	src/exec.c:88: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'pass_begin'
;------------------------------------------------------------
;feed                      Allocated to registers r6 r7 
;neg                       Allocated to registers r5 
;steps                     Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/exec.c:93: static void pass_begin(void) {
;	-----------------------------------------
;	 function pass_begin
;	-----------------------------------------
_pass_begin:
;	src/exec.c:96: p_flags = at(vi++);
	mov	_vi,#0x02
	mov	dpl,#0x01
	lcall	_at
	mov	_p_flags,dpl
;	src/exec.c:97: fw_skip = 0;
	mov	_fw_skip,#0x00
;	src/exec.c:98: if (p_flags & PF_SKIP) fw_skip = at(vi++);
	mov	a,_p_flags
	jnb	acc.4,00102$
	mov	dpl,_vi
	inc	_vi
	lcall	_at
	mov	_fw_skip,dpl
00102$:
;	src/exec.c:99: feed = svar();
	lcall	_svar
	mov	r6,dpl
	mov	r7,dph
;	src/exec.c:100: p_first = uvar();
	push	ar7
	push	ar6
	lcall	_uvar
	mov	_p_first,dpl
	mov	(_p_first + 1),dph
;	src/exec.c:101: p_left = at(vi++);
	mov	dpl,_vi
	inc	_vi
	lcall	_at
	mov	_p_left,dpl
	pop	ar6
	pop	ar7
;	src/exec.c:102: fw_ops_head += vi;
	mov	a,_vi
	add	a,_fw_ops_head
	mov	_fw_ops_head,a
;	src/exec.c:103: fw_strikes_in_pass = fw_skip;
	mov	_fw_strikes_in_pass,_fw_skip
;	src/exec.c:104: fw_flags |= FL_PASS_ACTIVE;
	orl	_fw_flags,#0x04
;	src/exec.c:105: xs = X_FEED;
	mov	_xs,#0x03
;	src/exec.c:106: if (!(p_flags & PF_NO_FEED) && feed != 0) {
	mov	a,_p_flags
	jnb	acc.1,00139$
	ret
00139$:
	mov	a,r6
	orl	a,r7
	jnz	00140$
	ret
00140$:
;	src/exec.c:107: uint8_t neg = feed < 0;
	mov	ar5,r7
	mov	a,r5
	rlc	a
	clr	a
	rlc	a
;	src/exec.c:108: uint16_t steps = (uint16_t)(neg ? -feed : feed) * F_GRID;
	mov	r5,a
	jz	00110$
	clr	c
	clr	a
	subb	a,r6
	mov	r3,a
	clr	a
	subb	a,r7
	mov	r4,a
	sjmp	00111$
00110$:
	mov	ar3,r6
	mov	ar4,r7
00111$:
	mov	__mulint_PARM_2,r3
	mov	(__mulint_PARM_2 + 1),r4
	mov	dptr,#0x0032
	push	ar5
	lcall	__mulint
	mov	r6,dpl
	mov	r7,dph
	pop	ar5
;	src/exec.c:109: if ((__bit)neg != f_neg) steps += F_BACKLASH;
;	assignBit
	mov	a,r5
	add	a,#0xff
	mov  _pass_begin_sloc0_1_0,c
	jb	_f_neg,00142$
	cpl	c
00142$:
	jc	00104$
	mov	ar3,r6
	mov	ar4,r7
	inc	r3
	cjne	r3,#0x00,00144$
	inc	r4
00144$:
	mov	ar6,r3
	mov	ar7,r4
00104$:
;	src/exec.c:110: f_neg = neg;
;	assignBit
	mov	c,_pass_begin_sloc0_1_0
	mov	_f_neg,c
;	src/exec.c:111: FDIR = !neg;
	mov	a,r5
	cjne	a,#0x01,00145$
00145$:
	mov  _pass_begin_sloc0_1_0,c
	clr	a
	rlc	a
	add	a,#0xff
	mov	_P1_3,c
;	src/exec.c:112: fw_feed += neg ? -(int16_t)steps : (int16_t)steps;
	mov	a,r5
	jz	00112$
	mov	ar4,r6
	mov	ar5,r7
	clr	c
	clr	a
	subb	a,r4
	mov	r4,a
	clr	a
	subb	a,r5
	mov	r5,a
	sjmp	00113$
00112$:
	mov	ar4,r6
	mov	ar5,r7
00113$:
	mov	a,r4
	add	a,_fw_feed
	mov	_fw_feed,a
	mov	a,r5
	addc	a,(_fw_feed + 1)
	mov	(_fw_feed + 1),a
;	src/exec.c:113: move_feed(steps);
	mov	dpl,r6
	mov	dph,r7
;	src/exec.c:115: }
	ljmp	_move_feed
;------------------------------------------------------------
;Allocation info for local variables in function 'strike_move'
;------------------------------------------------------------
;first                     Allocated to registers r7 
;e                         Allocated to registers r6 
;d                         Allocated to registers r4 r5 
;------------------------------------------------------------
;	src/exec.c:118: static void strike_move(uint8_t first) {
;	-----------------------------------------
;	 function strike_move
;	-----------------------------------------
_strike_move:
	mov	r7,dpl
;	src/exec.c:119: uint8_t e = at(0);
	mov	dpl,#0x00
	push	ar7
	lcall	_at
	mov	r6,dpl
	pop	ar7
;	src/exec.c:121: ham_ccv = (e & E_CONCAVE) != 0;
	mov	ar4,r6
	mov	a,#0x80
	anl	a,r4
	mov	r3,#0x00
	orl	a,r3
	cjne	a,#0x01,00116$
00116$:
	mov  _strike_move_sloc0_1_0,c
	cpl	c
	mov	_ham_ccv,c
;	src/exec.c:122: if (first) {
	mov	a,r7
	jz	00104$
;	src/exec.c:123: neg = (p_flags & PF_FIRST_NEG) != 0;
	mov	r3,_p_flags
	anl	ar3,#0x08
	mov	r7,#0x00
	mov	a,r3
	orl	a,r7
	cjne	a,#0x01,00118$
00118$:
	mov  _strike_move_sloc0_1_0,c
	cpl	c
	mov	_neg,c
;	src/exec.c:124: carriage(p_first * C_GRID);
	mov	__mulint_PARM_2,_p_first
	mov	(__mulint_PARM_2 + 1),(_p_first + 1)
	mov	dptr,#0x0014
	lcall	__mulint
	lcall	_carriage
	sjmp	00105$
00104$:
;	src/exec.c:126: d = e & E_DIST;
	anl	ar4,#0x3f
	mov	r5,#0x00
;	src/exec.c:127: if (e & E_EXT) d = (uint16_t)((d << 8) | at(1));
	mov	a,r6
	jnb	acc.6,00102$
	mov	ar7,r4
	mov	r6,#0x00
	mov	dpl,#0x01
	push	ar7
	push	ar6
	lcall	_at
	mov	r3,dpl
	pop	ar6
	pop	ar7
	mov	r2,#0x00
	mov	a,r3
	orl	a,r6
	mov	r4,a
	mov	a,r2
	orl	a,r7
	mov	r5,a
00102$:
;	src/exec.c:128: neg = (p_flags & PF_SWEEP_NEG) != 0;
	mov	r6,_p_flags
	anl	ar6,#0x04
	mov	r7,#0x00
	mov	a,r6
	orl	a,r7
	cjne	a,#0x01,00120$
00120$:
	mov  _strike_move_sloc0_1_0,c
	cpl	c
	mov	_neg,c
;	src/exec.c:129: carriage(d * C_GRID);
	mov	__mulint_PARM_2,r4
	mov	(__mulint_PARM_2 + 1),r5
	mov	dptr,#0x0014
	lcall	__mulint
	lcall	_carriage
00105$:
;	src/exec.c:131: xs = X_MOVE;
	mov	_xs,#0x04
;	src/exec.c:132: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'pass_end'
;------------------------------------------------------------
;	src/exec.c:134: static void pass_end(void) {
;	-----------------------------------------
;	 function pass_end
;	-----------------------------------------
_pass_end:
;	src/exec.c:135: fw_flags &= (uint8_t)~FL_PASS_ACTIVE;
	anl	_fw_flags,#0xfb
;	src/exec.c:136: ++fw_pass_index;
	inc	_fw_pass_index
	clr	a
	cjne	a,_fw_pass_index,00103$
	inc	(_fw_pass_index + 1)
00103$:
;	src/exec.c:137: fw_executed = fw_pass_index;
	mov	_fw_executed,_fw_pass_index
	mov	(_fw_executed + 1),(_fw_pass_index + 1)
;	src/exec.c:138: fw_strikes_in_pass = 0;
	mov	_fw_strikes_in_pass,#0x00
;	src/exec.c:139: xs = X_FETCH;
	mov	_xs,#0x00
;	src/exec.c:140: fw_ack(); /* the host counts a pass only when it is executed */
;	src/exec.c:141: }
	ljmp	_fw_ack
;------------------------------------------------------------
;Allocation info for local variables in function 'be16'
;------------------------------------------------------------
;i                         Allocated to registers r7 
;------------------------------------------------------------
;	src/exec.c:143: static uint16_t be16(uint8_t i) { return (uint16_t)(((uint16_t)at(i) << 8) | at((uint8_t)(i + 1))); }
;	-----------------------------------------
;	 function be16
;	-----------------------------------------
_be16:
	mov  r7,dpl
	push	ar7
	lcall	_at
	mov	r6,dpl
	pop	ar7
	mov	ar5,r6
	mov	r6,#0x00
	inc	r7
	mov	dpl,r7
	push	ar6
	push	ar5
	lcall	_at
	mov	r7,dpl
	pop	ar5
	pop	ar6
	mov	r4,#0x00
	mov	a,r7
	orl	a,r6
	mov	dpl,a
	mov	a,r4
	orl	a,r5
	mov	dph,a
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'fetch'
;------------------------------------------------------------
;op                        Allocated to registers r7 
;target                    Allocated to registers r5 r6 
;feed                      Allocated to registers r7 
;from                      Allocated to registers 
;d                         Allocated to registers r3 r4 
;------------------------------------------------------------
;	src/exec.c:145: static void fetch(void) {
;	-----------------------------------------
;	 function fetch
;	-----------------------------------------
_fetch:
;	src/exec.c:147: if (fw_state == ST_PAUSED || fw_state == ST_FAULT) return;
	mov	a,#0x03
	cjne	a,_fw_state,00263$
	ret
00263$:
	mov	a,#0x04
	cjne	a,_fw_state,00102$
	ret
00102$:
;	src/exec.c:148: if (fw_ops_head == fw_ops_done) {
	mov	a,_fw_ops_done
	cjne	a,_fw_ops_head,00108$
;	src/exec.c:149: if ((fw_flags & FL_JOB_ACTIVE) && fw_state != ST_WAITING) {
	mov	a,_fw_flags
	jnb	acc.4,00105$
	mov	a,#0x02
	cjne	a,_fw_state,00269$
	ret
00269$:
;	src/exec.c:150: fw_state = ST_WAITING;
	mov	_fw_state,#0x02
;	src/exec.c:151: fw_starved();
;	src/exec.c:153: return;
	ljmp	_fw_starved
00105$:
	ret
00108$:
;	src/exec.c:155: if (fw_pause_req) {
	mov	a,_fw_pause_req
	jz	00110$
;	src/exec.c:156: fw_pause_req = 0;
	mov	_fw_pause_req,#0x00
;	src/exec.c:157: fw_state = ST_PAUSED;
	mov	_fw_state,#0x03
;	src/exec.c:158: fw_ack();
;	src/exec.c:159: return;
	ljmp	_fw_ack
00110$:
;	src/exec.c:161: op = at(0);
	mov	dpl,#0x00
	lcall	_at
	mov	r7,dpl
;	src/exec.c:162: if (!(fw_flags & FL_JOB_ACTIVE) && op != OP_JOB_BEGIN) {
	mov	a,_fw_flags
	jb	acc.4,00112$
	cjne	r7,#0x10,00272$
	sjmp	00112$
00272$:
;	src/exec.c:163: fault(F_STREAM); /* ops outside a job: a host bug */
	mov	dpl,#0x80
;	src/exec.c:164: return;
	ljmp	_fault
00112$:
;	src/exec.c:166: if (fw_state == ST_WAITING) fw_state = ST_RUNNING;
	mov	a,#0x02
	cjne	a,_fw_state,00115$
	mov	_fw_state,#0x01
00115$:
;	src/exec.c:167: switch (op) {
	cjne	r7,#0x10,00275$
	sjmp	00116$
00275$:
	cjne	r7,#0x11,00276$
	sjmp	00117$
00276$:
	cjne	r7,#0x12,00277$
	sjmp	00118$
00277$:
	cjne	r7,#0x13,00278$
	ljmp	00121$
00278$:
	cjne	r7,#0x14,00279$
	ljmp	00138$
00279$:
	cjne	r7,#0x40,00280$
	ljmp	00122$
00280$:
	cjne	r7,#0x42,00281$
	ljmp	00127$
00281$:
	cjne	r7,#0x43,00282$
	ljmp	00127$
00282$:
	ljmp	00141$
;	src/exec.c:168: case OP_JOB_BEGIN:
00116$:
;	src/exec.c:169: fw_job_id = be16(1);
	mov	dpl,#0x01
	lcall	_be16
	mov	_fw_job_id,dpl
	mov	(_fw_job_id + 1),dph
;	src/exec.c:170: fw_pass_index = be16(3);
	mov	dpl,#0x03
	lcall	_be16
	mov	_fw_pass_index,dpl
	mov	(_fw_pass_index + 1),dph
;	src/exec.c:171: fw_executed = fw_pass_index;
	mov	_fw_executed,_fw_pass_index
	mov	(_fw_executed + 1),(_fw_pass_index + 1)
;	src/exec.c:172: fw_strikes_in_pass = 0;
	mov	_fw_strikes_in_pass,#0x00
;	src/exec.c:173: fw_flags |= FL_JOB_ACTIVE;
	orl	_fw_flags,#0x10
;	src/exec.c:174: fw_state = ST_RUNNING;
	mov	_fw_state,#0x01
;	src/exec.c:175: fw_ops_head += 5;
	mov	r6,_fw_ops_head
	mov	a,#0x05
	add	a,r6
	mov	_fw_ops_head,a
;	src/exec.c:176: fw_ack();
;	src/exec.c:177: break;
	ljmp	_fw_ack
;	src/exec.c:178: case OP_JOB_END:
00117$:
;	src/exec.c:179: fw_ops_head += 1;
	mov	a,_fw_ops_head
	inc	a
	mov	_fw_ops_head,a
;	src/exec.c:185: *(volatile __xdata uint8_t *)0xFFFF = 's';
	mov	dptr,#0xffff
	mov	a,#0x73
	movx	@dptr,a
;	src/exec.c:187: fw_flags &= (uint8_t)~FL_JOB_ACTIVE;
	anl	_fw_flags,#0xef
;	src/exec.c:188: fw_state = ST_IDLE;
	mov	_fw_state,#0x00
;	src/exec.c:189: fw_ack();
;	src/exec.c:190: break;
	ljmp	_fw_ack
;	src/exec.c:191: case OP_SHEET_BEGIN:
00118$:
;	src/exec.c:192: if (!PAPER) {
	jb	_P3_6,00120$
;	src/exec.c:194: fw_faults |= F_PAPER_OUT;
	orl	_fw_faults,#0x01
;	src/exec.c:195: fw_state = ST_FAULT;
	mov	_fw_state,#0x04
;	src/exec.c:196: fw_ack();
;	src/exec.c:197: return;
	ljmp	_fw_ack
00120$:
;	src/exec.c:199: fw_sheet = be16(1);
	mov	dpl,#0x01
	lcall	_be16
	mov	_fw_sheet,dpl
	mov	(_fw_sheet + 1),dph
;	src/exec.c:200: fw_feed = 0; /* the sheet's top edge is the feed origin */
	clr	a
	mov	_fw_feed,a
	mov	(_fw_feed + 1),a
;	src/exec.c:201: fw_ops_head += 3;
	mov	r6,_fw_ops_head
	mov	a,#0x03
	add	a,r6
	mov	_fw_ops_head,a
;	src/exec.c:202: break;
	ret
;	src/exec.c:203: case OP_SHEET_END:
00121$:
;	src/exec.c:204: fw_sheet = 0;
	clr	a
	mov	_fw_sheet,a
	mov	(_fw_sheet + 1),a
;	src/exec.c:205: fw_ops_head += 1;
	mov	a,_fw_ops_head
	inc	a
	mov	_fw_ops_head,a
;	src/exec.c:206: break;
	ret
;	src/exec.c:207: case OP_HOME:
00122$:
;	src/exec.c:208: fw_ops_head += 1;
	mov	a,_fw_ops_head
	inc	a
	mov	_fw_ops_head,a
;	src/exec.c:209: fw_state = ST_HOMING;
	mov	_fw_state,#0x05
;	src/exec.c:210: CDIR = 0;
;	assignBit
	clr	_P1_1
;	src/exec.c:211: c_neg = 1;
;	assignBit
	setb	_c_neg
;	src/exec.c:212: xs = X_HOME;
	mov	_xs,#0x01
;	src/exec.c:217: if (fw_carriage > 0 && (fw_flags & FL_HOMED)) {
	mov	r5,_fw_carriage
	mov	r6,(_fw_carriage + 1)
	clr	c
	clr	a
	subb	a,r5
	mov	a,#(0x00 ^ 0x80)
	mov	b,r6
	xrl	b,#0x80
	subb	a,b
	jnc	00124$
	mov	a,_fw_flags
	jnb	acc.1,00124$
;	src/exec.c:218: move_constant(PIN_CSTEP, (uint16_t)fw_carriage, cfg_home_iv);
	mov	_move_constant_PARM_2,_fw_carriage
	mov	(_move_constant_PARM_2 + 1),(_fw_carriage + 1)
	mov	_move_constant_PARM_3,_cfg_home_iv
	mov	(_move_constant_PARM_3 + 1),(_cfg_home_iv + 1)
	mov	dpl,#0x01
	lcall	_move_constant
00124$:
;	src/exec.c:220: mv_limit = 1;
;	assignBit
	setb	_mv_limit
;	src/exec.c:224: break;
	ret
;	src/exec.c:226: case OP_SEEK_FEED: {
00127$:
;	src/exec.c:227: int16_t target = (int16_t)be16(1);
	mov	dpl,#0x01
	push	ar7
	lcall	_be16
	mov	r5,dpl
	mov	r6,dph
	pop	ar7
;	src/exec.c:228: uint8_t feed = op == OP_SEEK_FEED;
	clr	a
	cjne	r7,#0x43,00286$
	inc	a
00286$:
;	src/exec.c:229: int16_t from = feed ? fw_feed : fw_carriage;
	mov	r7,a
	jz	00145$
	mov	r3,_fw_feed
	mov	r4,(_fw_feed + 1)
	sjmp	00146$
00145$:
	mov	r3,_fw_carriage
	mov	r4,(_fw_carriage + 1)
00146$:
;	src/exec.c:230: int16_t d = target - from;
	mov	a,r5
	clr	c
	subb	a,r3
	mov	r3,a
	mov	a,r6
	subb	a,r4
	mov	r4,a
;	src/exec.c:231: fw_ops_head += 3;
	mov	r2,_fw_ops_head
	mov	a,#0x03
	add	a,r2
	mov	_fw_ops_head,a
;	src/exec.c:232: if (!feed && (!(fw_flags & FL_HOMED) || target < 0 || (uint16_t)target > cfg_travel)) {
	mov	a,r7
	jnz	00129$
	mov	a,_fw_flags
	jnb	acc.1,00128$
	mov	ar1,r5
	mov	ar2,r6
	mov	a,r2
	jb	acc.7,00128$
	mov	ar1,r5
	mov	ar2,r6
	clr	c
	mov	a,_cfg_travel
	subb	a,r1
	mov	a,(_cfg_travel + 1)
	subb	a,r2
	jnc	00129$
00128$:
;	src/exec.c:233: fault(F_STREAM);
	mov	dpl,#0x80
;	src/exec.c:234: return;
	ljmp	_fault
00129$:
;	src/exec.c:236: if (d == 0) break;
	mov	a,r3
	orl	a,r4
	jnz	00293$
	ret
00293$:
;	src/exec.c:237: if (feed) {
	mov	a,r7
	jz	00136$
;	src/exec.c:238: FDIR = d > 0;
	mov	ar1,r3
	mov	ar2,r4
	clr	c
	clr	a
	subb	a,r1
	mov	a,#(0x00 ^ 0x80)
	mov	b,r2
	xrl	b,#0x80
	subb	a,b
	mov  _fetch_sloc0_1_0,c
	clr	a
	rlc	a
	add	a,#0xff
	mov	_P1_3,c
;	src/exec.c:239: f_neg = d < 0;
	mov	a,r2
	rlc	a
	mov	_f_neg,c
;	src/exec.c:240: fw_feed = target;
	mov	_fw_feed,r5
	mov	(_fw_feed + 1),r6
	sjmp	00137$
00136$:
;	src/exec.c:242: CDIR = d > 0;
	mov	ar1,r3
	mov	ar2,r4
	clr	c
	clr	a
	subb	a,r1
	mov	a,#(0x00 ^ 0x80)
	mov	b,r2
	xrl	b,#0x80
	subb	a,b
	mov  _fetch_sloc0_1_0,c
	clr	a
	rlc	a
	add	a,#0xff
	mov	_P1_1,c
;	src/exec.c:243: c_neg = d < 0;
	mov	a,r2
	rlc	a
	mov	_c_neg,c
;	src/exec.c:244: fw_carriage = target;
	mov	_fw_carriage,r5
	mov	(_fw_carriage + 1),r6
00137$:
;	src/exec.c:246: move_constant(feed ? PIN_FSTEP : PIN_CSTEP, (uint16_t)(d < 0 ? -d : d), cfg_home_iv);
	mov	a,r7
	jz	00147$
	mov	r6,#0x04
	mov	r7,#0x00
	sjmp	00148$
00147$:
	mov	r6,#0x01
	mov	r7,#0x00
00148$:
	mov	ar7,r4
	mov	a,r7
	jnb	acc.7,00149$
	clr	c
	clr	a
	subb	a,r3
	mov	r5,a
	clr	a
	subb	a,r4
	mov	r7,a
	sjmp	00150$
00149$:
	mov	ar5,r3
	mov	ar7,r4
00150$:
	mov	_move_constant_PARM_2,r5
	mov	(_move_constant_PARM_2 + 1),r7
	mov	_move_constant_PARM_3,_cfg_home_iv
	mov	(_move_constant_PARM_3 + 1),(_cfg_home_iv + 1)
	mov	dpl,r6
	lcall	_move_constant
;	src/exec.c:247: xs = X_SEEK;
	mov	_xs,#0x02
;	src/exec.c:248: break;
;	src/exec.c:250: case OP_PASS:
	ret
00138$:
;	src/exec.c:251: if (!(fw_flags & FL_HOMED)) {
	mov	a,_fw_flags
	jb	acc.1,00140$
;	src/exec.c:252: fault(F_STREAM); /* the host must home before positioning */
	mov	dpl,#0x80
;	src/exec.c:253: return;
	ljmp	_fault
00140$:
;	src/exec.c:255: pass_begin();
;	src/exec.c:256: break;
;	src/exec.c:257: default: fault(F_STREAM); break; /* checked on receipt: cannot happen */
	ljmp	_pass_begin
00141$:
	mov	dpl,#0x80
;	src/exec.c:258: }
;	src/exec.c:259: }
	ljmp	_fault
;------------------------------------------------------------
;Allocation info for local variables in function 'exec_poll'
;------------------------------------------------------------
;	src/exec.c:261: void exec_poll(void) {
;	-----------------------------------------
;	 function exec_poll
;	-----------------------------------------
_exec_poll:
;	src/exec.c:262: if (!mv_done) {
	jb	_mv_done,00107$
;	src/exec.c:265: if (xs != X_HOME && !LIMIT && !CDIR && fw_carriage > (int16_t)(4 * C_GRID)) {
	mov	a,#0x01
	cjne	a,_xs,00232$
	ret
00232$:
	jb	_P3_3,00102$
	jb	_P1_1,00102$
	clr	c
	mov	a,#0x50
	subb	a,_fw_carriage
	mov	a,#(0x00 ^ 0x80)
	mov	b,(_fw_carriage + 1)
	xrl	b,#0x80
	subb	a,b
	jnc	00102$
;	src/exec.c:266: fw_flags &= (uint8_t)~FL_HOMED;
	anl	_fw_flags,#0xfd
;	src/exec.c:267: fault(F_LIMIT);
	mov	dpl,#0x02
;	src/exec.c:269: return;
	ljmp	_fault
00102$:
	ret
00107$:
;	src/exec.c:271: switch (xs) {
	mov	a,_xs
	add	a,#0xff - 0x07
	jnc	00236$
	ret
00236$:
	mov	a,_xs
	add	a,#(00237$-3-.)
	movc	a,@a+pc
	mov	dpl,a
	mov	a,_xs
	add	a,#(00238$-3-.)
	movc	a,@a+pc
	mov	dph,a
	clr	a
	jmp	@a+dptr
00237$:
	.db	00108$
	.db	00109$
	.db	00112$
	.db	00113$
	.db	00116$
	.db	00122$
	.db	00128$
	.db	00135$
00238$:
	.db	00108$>>8
	.db	00109$>>8
	.db	00112$>>8
	.db	00113$>>8
	.db	00116$>>8
	.db	00122$>>8
	.db	00128$>>8
	.db	00135$>>8
;	src/exec.c:272: case X_FETCH: fetch(); return;
00108$:
	ljmp	_fetch
;	src/exec.c:273: case X_HOME:
00109$:
;	src/exec.c:275: mv_limit = 1;
;	assignBit
	setb	_mv_limit
;	src/exec.c:277: if (!mv_limit) {
	jb	_mv_limit,00111$
;	src/exec.c:278: fault(F_LIMIT); /* travelled the whole width without finding the switch */
	mov	dpl,#0x02
;	src/exec.c:279: return;
	ljmp	_fault
00111$:
;	src/exec.c:281: fw_carriage = 0;
	clr	a
	mov	_fw_carriage,a
	mov	(_fw_carriage + 1),a
;	src/exec.c:282: fw_flags |= FL_HOMED;
	orl	_fw_flags,#0x02
;	src/exec.c:283: fw_state = ST_RUNNING;
	mov	_fw_state,#0x01
;	src/exec.c:284: xs = X_FETCH;
	mov	_xs,#0x00
;	src/exec.c:285: return;
	ret
;	src/exec.c:286: case X_SEEK: xs = X_FETCH; return;
00112$:
	mov	_xs,#0x00
	ret
;	src/exec.c:287: case X_FEED:
00113$:
;	src/exec.c:288: if (p_left == 0) {
	mov	a,_p_left
	jnz	00115$
;	src/exec.c:289: pass_end();
;	src/exec.c:290: return;
	ljmp	_pass_end
00115$:
;	src/exec.c:292: p_is_first = 1;
;	assignBit
	setb	_p_is_first
;	src/exec.c:293: xs = X_NEXT;
	mov	_xs,#0x07
;	src/exec.c:294: return;
	ret
;	src/exec.c:295: case X_MOVE:
00116$:
;	src/exec.c:296: if (fw_carriage < 0 || (uint16_t)fw_carriage > cfg_travel) {
	mov	a,(_fw_carriage + 1)
	jb	acc.7,00117$
	mov	r6,_fw_carriage
	mov	r7,(_fw_carriage + 1)
	clr	c
	mov	a,_cfg_travel
	subb	a,r6
	mov	a,(_cfg_travel + 1)
	subb	a,r7
	jnc	00118$
00117$:
;	src/exec.c:297: fw_flags &= (uint8_t)~FL_HOMED;
	anl	_fw_flags,#0xfd
;	src/exec.c:298: fault(F_LIMIT);
	mov	dpl,#0x02
;	src/exec.c:299: return;
	ljmp	_fault
00118$:
;	src/exec.c:301: xs = X_SETTLE;
	mov	_xs,#0x05
;	src/exec.c:302: if (cfg_settle) {
	mov	a,_cfg_settle
	orl	a,(_cfg_settle + 1)
	jz	00122$
;	src/exec.c:303: wait_ticks(cfg_settle);
	mov	dpl,_cfg_settle
	mov	dph,(_cfg_settle + 1)
;	src/exec.c:304: return;
	ljmp	_wait_ticks
;	src/exec.c:307: case X_SETTLE:
00122$:
;	src/exec.c:308: xs = X_DWELL;
	mov	_xs,#0x06
;	src/exec.c:309: if (fw_skip) {
	mov	a,_fw_skip
	jz	00124$
;	src/exec.c:310: --fw_skip; /* made before the reset: pass over it */
	dec	_fw_skip
;	src/exec.c:311: return;
	ret
00124$:
;	src/exec.c:313: if (ham_ccv) HAM_CCV = 1;
	jnb	_ham_ccv,00126$
;	assignBit
	setb	_P1_5
	sjmp	00127$
00126$:
;	src/exec.c:314: else HAM_CVX = 1;
;	assignBit
	setb	_P1_4
00127$:
;	src/exec.c:315: wait_ticks(cfg_hammer);
	mov	dpl,_cfg_hammer
	mov	dph,(_cfg_hammer + 1)
	lcall	_wait_ticks
;	src/exec.c:316: ++fw_strikes_in_pass;
	inc	_fw_strikes_in_pass
;	src/exec.c:317: return;
	ret
;	src/exec.c:318: case X_DWELL:
00128$:
;	src/exec.c:319: HAM_CVX = 0;
;	assignBit
	clr	_P1_4
;	src/exec.c:320: HAM_CCV = 0;
;	assignBit
	clr	_P1_5
;	src/exec.c:322: if (!HAM_SENSE) {
	jb	_P3_7,00130$
;	src/exec.c:323: fault(F_HAMMER);
	mov	dpl,#0x04
;	src/exec.c:324: return;
	ljmp	_fault
00130$:
;	src/exec.c:326: fw_ops_head += (at(0) & E_EXT) ? 2 : 1;
	mov	dpl,#0x00
	lcall	_at
	mov	a,dpl
	jnb	acc.6,00149$
	mov	r6,#0x02
	mov	r7,#0x00
	sjmp	00150$
00149$:
	mov	r6,#0x01
	mov	r7,#0x00
00150$:
	mov	r7,_fw_ops_head
	mov	a,r6
	add	a,r7
	mov	_fw_ops_head,a
;	src/exec.c:327: if (--p_left == 0) {
	djnz	_p_left,00132$
;	src/exec.c:328: pass_end();
;	src/exec.c:329: return;
	ljmp	_pass_end
00132$:
;	src/exec.c:331: p_is_first = 0;
;	assignBit
	clr	_p_is_first
;	src/exec.c:332: xs = X_NEXT;
	mov	_xs,#0x07
;	src/exec.c:333: if (fw_pause_req) {
	mov	a,_fw_pause_req
	jz	00134$
;	src/exec.c:335: fw_pause_req = 0;
	mov	_fw_pause_req,#0x00
;	src/exec.c:336: fw_state = ST_PAUSED;
	mov	_fw_state,#0x03
;	src/exec.c:337: fw_ack();
;	src/exec.c:339: return;
;	src/exec.c:340: case X_NEXT:
	ljmp	_fw_ack
00134$:
	ret
00135$:
;	src/exec.c:341: if (fw_state == ST_PAUSED || fw_state == ST_FAULT) return;
	mov	a,#0x03
	cjne	a,_fw_state,00250$
	sjmp	00136$
00250$:
	mov	a,#0x04
	cjne	a,_fw_state,00137$
00136$:
	ret
00137$:
;	src/exec.c:342: if (fw_ops_head == fw_ops_done) {
	mov	a,_fw_ops_done
	cjne	a,_fw_ops_head,00142$
;	src/exec.c:344: if (fw_state != ST_WAITING) {
	mov	a,#0x02
	cjne	a,_fw_state,00255$
	sjmp	00140$
00255$:
;	src/exec.c:345: fw_state = ST_WAITING;
	mov	_fw_state,#0x02
;	src/exec.c:346: fw_starved();
;	src/exec.c:348: return;
	ljmp	_fw_starved
00140$:
	ret
00142$:
;	src/exec.c:350: if (fw_state == ST_WAITING) fw_state = ST_RUNNING;
	mov	a,#0x02
	cjne	a,_fw_state,00144$
	mov	_fw_state,#0x01
00144$:
;	src/exec.c:351: strike_move(p_is_first);
	mov	c,_p_is_first
	clr	a
	rlc	a
	mov	dpl,a
	lcall	_strike_move
;	src/exec.c:352: return;
;	src/exec.c:353: default: return;
;	src/exec.c:354: }
;	src/exec.c:355: }
	ret
	.area CSEG    (CODE)
	.area CONST   (CODE)
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
