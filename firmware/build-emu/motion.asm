;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module motion
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _nextph
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
	.globl _mv_limit
	.globl _mv_done
	.globl _m_upcr
	.globl _m_fu
	.globl _m_cr
	.globl _m_slow
	.globl _move_home_PARM_2
	.globl _move_constant_PARM_3
	.globl _move_constant_PARM_2
	.globl _mv_p
	.globl _s_kind
	.globl _s_pin
	.globl _s_ph
	.globl _s_pl
	.globl _c_di
	.globl _c_ui
	.globl _c_ch
	.globl _c_cl
	.globl _motion_init
	.globl _motion_stop
	.globl _move_carriage
	.globl _move_feed
	.globl _move_constant
	.globl _move_home
	.globl _wait_ticks
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
_c_cl::
	.ds 1
_c_ch::
	.ds 1
_c_ui::
	.ds 1
_c_di::
	.ds 1
_s_pl::
	.ds 1
_s_ph::
	.ds 1
_s_pin::
	.ds 1
_s_kind::
	.ds 1
_mv_p::
	.ds 1
_wp:
	.ds 1
_start_PARM_2:
	.ds 2
_t_r:
	.ds 1
_t_k:
	.ds 1
_t_slow:
	.ds 2
_emit_up_PARM_2:
	.ds 1
_table_move_n_65536_25:
	.ds 2
_table_move_hi_65536_26:
	.ds 1
_one_phase_PARM_2:
	.ds 2
_one_phase_PARM_3:
	.ds 2
_move_constant_PARM_2:
	.ds 2
_move_constant_PARM_3:
	.ds 2
_move_home_PARM_2:
	.ds 2
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
	.area	OSEG    (OVR,DATA)
_rec_PARM_2:
	.ds 2
_rec_PARM_3:
	.ds 2
	.area	OSEG    (OVR,DATA)
;--------------------------------------------------------
; indirectly addressable internal ram data
;--------------------------------------------------------
	.area ISEG    (DATA)
_prog:
	.ds 31
;--------------------------------------------------------
; absolute internal ram data
;--------------------------------------------------------
	.area IABS    (ABS,DATA)
	.area IABS    (ABS,DATA)
;--------------------------------------------------------
; bit data
;--------------------------------------------------------
	.area BSEG    (BIT)
_m_slow::
	.ds 1
_m_cr::
	.ds 1
_m_fu::
	.ds 1
_m_upcr::
	.ds 1
_mv_done::
	.ds 1
_mv_limit::
	.ds 1
_table_move_sloc0_1_0:
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
;Allocation info for local variables in function 'rec'
;------------------------------------------------------------
;count                     Allocated with name '_rec_PARM_2'
;ptr                       Allocated with name '_rec_PARM_3'
;kind                      Allocated to registers r7 
;------------------------------------------------------------
;	src/motion.c:28: static void rec(uint8_t kind, uint16_t count, uint16_t ptr) {
;	-----------------------------------------
;	 function rec
;	-----------------------------------------
_rec:
	ar7 = 0x07
	ar6 = 0x06
	ar5 = 0x05
	ar4 = 0x04
	ar3 = 0x03
	ar2 = 0x02
	ar1 = 0x01
	ar0 = 0x00
	mov	r7,dpl
;	src/motion.c:29: wp[0] = kind;
	mov	a,_wp
	mov	r0,a
	mov	@r0,ar7
;	src/motion.c:30: if (kind == K_END) return; /* the interrupt reads nothing after it */
	mov	a,r7
	jnz	00102$
	ret
00102$:
;	src/motion.c:31: wp[1] = (uint8_t)count;                      /* DJNZ form: 0 means 256 */
	mov	a,_wp
	inc	a
	mov	r1,a
	mov	r7,_rec_PARM_2
	mov	@r1,ar7
;	src/motion.c:32: wp[2] = (uint8_t)(((count - 1) >> 8) + 1);
	mov	a,#0x02
	add	a,_wp
	mov	r1,a
	mov	r6,_rec_PARM_2
	mov	r7,(_rec_PARM_2 + 1)
	dec	r6
	cjne	r6,#0xff,00110$
	dec	r7
00110$:
	mov	ar6,r7
	inc	r6
	mov	@r1,ar6
;	src/motion.c:33: wp[3] = (uint8_t)ptr;
	mov	a,#0x03
	add	a,_wp
	mov	r1,a
	mov	r7,_rec_PARM_3
	mov	@r1,ar7
;	src/motion.c:34: wp[4] = (uint8_t)(ptr >> 8);
	mov	a,#0x04
	add	a,_wp
	mov	r1,a
	mov	r7,(_rec_PARM_3 + 1)
	mov	@r1,ar7
;	src/motion.c:35: wp += 5;
	mov	a,#0x05
	add	a,_wp
	mov	_wp,a
;	src/motion.c:36: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'rd16'
;------------------------------------------------------------
;p                         Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/motion.c:38: static uint16_t rd16(FW_CODE uint8_t *p) { return (uint16_t)(((uint16_t)p[0] << 8) | p[1]); }
;	-----------------------------------------
;	 function rd16
;	-----------------------------------------
_rd16:
	mov	r6,dpl
	mov  r7,dph
	clr	a
	movc	a,@a+dptr
	mov	r4,a
	mov	r5,#0x00
	mov	dpl,r6
	mov	dph,r7
	inc	dptr
	clr	a
	movc	a,@a+dptr
	mov	r6,#0x00
	orl	a,r5
	mov	dpl,a
	mov	a,r6
	orl	a,r4
	mov	dph,a
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'start'
;------------------------------------------------------------
;second                    Allocated with name '_start_PARM_2'
;first                     Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/motion.c:42: static void start(uint16_t first, uint16_t second) {
;	-----------------------------------------
;	 function start
;	-----------------------------------------
_start:
	mov	r6,dpl
	mov	r7,dph
;	src/motion.c:43: TR2 = 0;
;	assignBit
	clr	_TR2
;	src/motion.c:44: mv_done = 0;
;	assignBit
	clr	_mv_done
;	src/motion.c:45: mv_limit = 0;
;	assignBit
	clr	_mv_limit
;	src/motion.c:46: mv_p = (uint8_t)prog;
	mov	_mv_p,#_prog
;	src/motion.c:47: nextph();
	push	ar7
	push	ar6
	lcall	_nextph
	pop	ar6
	pop	ar7
;	src/motion.c:48: TL2 = (uint8_t)first;
	mov	_TL2,r6
;	src/motion.c:49: TH2 = (uint8_t)(first >> 8);
	mov	_TH2,r7
;	src/motion.c:50: RCAP2L = (uint8_t)second;
	mov	_RCAP2L,_start_PARM_2
;	src/motion.c:51: RCAP2H = (uint8_t)(second >> 8);
	mov	_RCAP2H,(_start_PARM_2 + 1)
;	src/motion.c:52: TF2 = 0;
;	assignBit
	clr	_TF2
;	src/motion.c:53: if (!mv_done) TR2 = 1;
	jb	_mv_done,00103$
;	assignBit
	setb	_TR2
00103$:
;	src/motion.c:54: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'motion_init'
;------------------------------------------------------------
;	src/motion.c:56: void motion_init(void) {
;	-----------------------------------------
;	 function motion_init
;	-----------------------------------------
_motion_init:
;	src/motion.c:57: T2CON = 0; /* timer, 16-bit auto-reload */
	mov	_T2CON,#0x00
;	src/motion.c:58: PT2 = 1;   /* steps above the UART and the strobe: latency is one instruction */
;	assignBit
	setb	_PT2
;	src/motion.c:59: ET2 = 1;
;	assignBit
	setb	_ET2
;	src/motion.c:60: mv_done = 1;
;	assignBit
	setb	_mv_done
;	src/motion.c:61: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'motion_stop'
;------------------------------------------------------------
;	src/motion.c:63: void motion_stop(void) {
;	-----------------------------------------
;	 function motion_stop
;	-----------------------------------------
_motion_stop:
;	src/motion.c:64: TR2 = 0;
;	assignBit
	clr	_TR2
;	src/motion.c:65: TF2 = 0;
;	assignBit
	clr	_TF2
;	src/motion.c:66: mv_done = 1;
;	assignBit
	setb	_mv_done
;	src/motion.c:67: }
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'emit_up'
;------------------------------------------------------------
;hi                        Allocated with name '_emit_up_PARM_2'
;lo                        Allocated to registers r7 
;top                       Allocated to registers r6 
;------------------------------------------------------------
;	src/motion.c:79: static void emit_up(uint8_t lo, uint8_t hi) {
;	-----------------------------------------
;	 function emit_up
;	-----------------------------------------
_emit_up:
	mov	r7,dpl
;	src/motion.c:81: if (lo < t_k) {
	clr	c
	mov	a,r7
	subb	a,_t_k
	jnc	00102$
;	src/motion.c:82: top = hi < t_k ? hi : (uint8_t)(t_k - 1);
	clr	c
	mov	a,_emit_up_PARM_2
	subb	a,_t_k
	jnc	00108$
	mov	r6,_emit_up_PARM_2
	sjmp	00109$
00108$:
	mov	r5,_t_k
	dec	r5
	mov	ar6,r5
00109$:
;	src/motion.c:83: rec(K_SLOW_UP, (uint8_t)(top - lo + 1), (uint16_t)(t_slow + 2 * lo));
	mov	a,r6
	clr	c
	subb	a,r7
	mov	r5,a
	inc	r5
	mov	_rec_PARM_2,r5
	mov	(_rec_PARM_2 + 1),#0x00
	mov	ar4,r7
	mov	r5,#0x00
	mov	a,r4
	add	a,r4
	mov	r4,a
	mov	a,r5
	rlc	a
	mov	r5,a
	mov	a,r4
	add	a,_t_slow
	mov	r4,a
	mov	a,r5
	addc	a,(_t_slow + 1)
	mov	r5,a
	mov	_rec_PARM_3,r4
	mov	(_rec_PARM_3 + 1),r5
	mov	dpl,#0x04
	push	ar6
	lcall	_rec
	pop	ar6
;	src/motion.c:84: lo = (uint8_t)(top + 1);
	inc	r6
	mov	ar7,r6
00102$:
;	src/motion.c:86: if (lo <= hi && lo >= t_k) rec(K_FAST_UP, (uint8_t)(hi - lo + 1), (uint8_t)(RAMP_FAST_BIAS + lo - t_k));
	clr	c
	mov	a,_emit_up_PARM_2
	subb	a,r7
	jc	00106$
	mov	a,r7
	subb	a,_t_k
	jc	00106$
	mov	a,_emit_up_PARM_2
	clr	c
	subb	a,r7
	mov	r6,a
	inc	r6
	mov	_rec_PARM_2,r6
	mov	(_rec_PARM_2 + 1),#0x00
	mov	a,#0x07
	add	a,r7
	mov	r6,_t_k
	clr	c
	subb	a,r6
	mov	r7,a
	mov	_rec_PARM_3,r7
	mov	(_rec_PARM_3 + 1),#0x00
	mov	dpl,#0x01
;	src/motion.c:87: }
	ljmp	_rec
00106$:
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'emit_dn'
;------------------------------------------------------------
;hi                        Allocated to registers r7 
;cnt                       Allocated to registers r6 
;------------------------------------------------------------
;	src/motion.c:90: static void emit_dn(uint8_t hi) {
;	-----------------------------------------
;	 function emit_dn
;	-----------------------------------------
_emit_dn:
	mov	r7,dpl
;	src/motion.c:92: if (hi >= t_k) {
	clr	c
	mov	a,r7
	subb	a,_t_k
	jc	00102$
;	src/motion.c:93: cnt = (uint8_t)(hi - t_k + 1);
	mov	a,r7
	clr	c
	subb	a,_t_k
	mov	r6,a
	inc	r6
;	src/motion.c:94: rec(K_FAST_DN, cnt, (uint8_t)(RAMP_FAST_BIAS + hi - t_k));
	mov	_rec_PARM_2,r6
	mov	(_rec_PARM_2 + 1),#0x00
	mov	ar6,r7
	mov	a,#0x07
	add	a,r6
	mov	r5,_t_k
	clr	c
	subb	a,r5
	mov	r6,a
	mov	_rec_PARM_3,r6
	mov	(_rec_PARM_3 + 1),#0x00
	mov	dpl,#0x03
	lcall	_rec
;	src/motion.c:95: hi = (uint8_t)(t_k - 1);
	mov	r6,_t_k
	dec	r6
	mov	ar7,r6
00102$:
;	src/motion.c:97: if (hi >= 1) rec(K_SLOW_DN, hi, (uint16_t)(t_slow + 2 * hi));
	cjne	r7,#0x01,00116$
00116$:
	jc	00105$
	mov	_rec_PARM_2,r7
	clr	a
	mov	(_rec_PARM_2 + 1),a
	mov	r6,a
	mov	a,r7
	add	a,r7
	mov	r7,a
	mov	a,r6
	rlc	a
	mov	r6,a
	mov	a,r7
	add	a,_t_slow
	mov	r7,a
	mov	a,r6
	addc	a,(_t_slow + 1)
	mov	r6,a
	mov	_rec_PARM_3,r7
	mov	(_rec_PARM_3 + 1),r6
	mov	dpl,#0x05
;	src/motion.c:98: }
	ljmp	_rec
00105$:
	ret
;------------------------------------------------------------
;Allocation info for local variables in function 'table_move'
;------------------------------------------------------------
;n                         Allocated with name '_table_move_n_65536_25'
;a                         Allocated to registers r6 
;hi                        Allocated with name '_table_move_hi_65536_26'
;------------------------------------------------------------
;	src/motion.c:100: static void table_move(uint16_t n) {
;	-----------------------------------------
;	 function table_move
;	-----------------------------------------
_table_move:
	mov	_table_move_n_65536_25,dpl
	mov	(_table_move_n_65536_25 + 1),dph
;	src/motion.c:102: wp = prog;
	mov	_wp,#_prog
;	src/motion.c:103: if (n >= 2 * (uint16_t)t_r) {
	mov	r5,_t_r
	mov	r4,#0x00
	mov	a,r5
	add	a,r5
	mov	r5,a
	mov	a,r4
	rlc	a
	mov	r4,a
	mov	r2,_table_move_n_65536_25
	mov	r3,(_table_move_n_65536_25 + 1)
	clr	c
	mov	a,r2
	subb	a,r5
	mov	a,r3
	subb	a,r4
	jnc	00188$
	ljmp	00116$
00188$:
;	src/motion.c:105: a = (uint8_t)(t_r + 1);
	mov	r5,_t_r
	inc	r5
;	src/motion.c:106: if (a >= 3) emit_up(2, t_r);
	cjne	r5,#0x03,00189$
00189$:
	jc	00102$
	mov	_emit_up_PARM_2,_t_r
	mov	dpl,#0x02
	push	ar3
	push	ar2
	lcall	_emit_up
	pop	ar2
	pop	ar3
00102$:
;	src/motion.c:107: if (n > 2 * (uint16_t)t_r) rec(t_k <= t_r ? K_COUNT : K_SCOUNT, n - 2 * (uint16_t)t_r, 0);
	mov	r5,_t_r
	mov	r4,#0x00
	mov	a,r5
	add	a,r5
	mov	r5,a
	mov	a,r4
	rlc	a
	mov	r4,a
	clr	c
	mov	a,r5
	subb	a,r2
	mov	a,r4
	subb	a,r3
	jnc	00104$
	clr	c
	mov	a,_t_r
	subb	a,_t_k
	mov	_table_move_sloc0_1_0,c
	jc	00120$
	mov	r4,#0x02
	mov	r5,#0x00
	sjmp	00121$
00120$:
	mov	r4,#0x06
	mov	r5,#0x00
00121$:
	mov	dpl,r4
	mov	r5,_t_r
	mov	r4,#0x00
	mov	a,r5
	add	a,r5
	mov	r5,a
	mov	a,r4
	rlc	a
	mov	r4,a
	mov	a,r2
	clr	c
	subb	a,r5
	mov	r5,a
	mov	a,r3
	subb	a,r4
	mov	r4,a
	mov	_rec_PARM_2,r5
	mov	(_rec_PARM_2 + 1),r4
	clr	a
	mov	_rec_PARM_3,a
	mov	(_rec_PARM_3 + 1),a
	push	ar3
	push	ar2
	lcall	_rec
	pop	ar2
	pop	ar3
00104$:
;	src/motion.c:108: hi = (uint8_t)(t_r - 1);
	mov	r5,_t_r
	dec	r5
;	src/motion.c:109: if (n - 2 < hi) hi = (uint8_t)(n - 2);
	mov	a,r2
	add	a,#0xfe
	mov	r4,a
	mov	a,r3
	addc	a,#0xff
	mov	r7,a
	push	ar2
	push	ar3
	mov	ar3,r5
	mov	r6,#0x00
	clr	c
	mov	a,r4
	subb	a,r3
	mov	a,r7
	subb	a,r6
	pop	ar3
	pop	ar2
	jnc	00106$
	mov	r6,_table_move_n_65536_25
	dec	r6
	dec	r6
	mov	ar5,r6
00106$:
;	src/motion.c:110: emit_dn(hi);
	mov	dpl,r5
	push	ar3
	push	ar2
	lcall	_emit_dn
	pop	ar2
	pop	ar3
	sjmp	00117$
00116$:
;	src/motion.c:113: a = (uint8_t)((n + 2) / 2);
	mov	a,#0x02
	add	a,r2
	mov	r6,a
	clr	a
	addc	a,r3
	clr	c
	rrc	a
	xch	a,r6
	rrc	a
	xch	a,r6
	mov	r7,a
;	src/motion.c:114: if (a >= 3) emit_up(2, (uint8_t)(a - 1));
	cjne	r6,#0x03,00194$
00194$:
	jc	00108$
	mov	ar7,r6
	dec	r7
	mov	_emit_up_PARM_2,r7
	mov	dpl,#0x02
	push	ar6
	push	ar3
	push	ar2
	lcall	_emit_up
	pop	ar2
	pop	ar3
	pop	ar6
00108$:
;	src/motion.c:115: if (n >= 3) {
	clr	c
	mov	a,r2
	subb	a,#0x03
	mov	a,r3
	subb	a,#0x00
	jc	00117$
;	src/motion.c:116: hi = (uint8_t)(n - a);
	mov	a,_table_move_n_65536_25
	mov	r7,a
	clr	c
	subb	a,r6
	mov	_table_move_hi_65536_26,a
;	src/motion.c:117: if (hi > n - 2) hi = (uint8_t)(n - 2);
	mov	a,r2
	add	a,#0xfe
	mov	r4,a
	mov	a,r3
	addc	a,#0xff
	mov	r5,a
	push	ar2
	push	ar3
	mov	r3,_table_move_hi_65536_26
	mov	r6,#0x00
	clr	c
	mov	a,r4
	subb	a,r3
	mov	a,r5
	subb	a,r6
	pop	ar3
	pop	ar2
	jnc	00110$
	dec	r7
	dec	r7
	mov	_table_move_hi_65536_26,r7
00110$:
;	src/motion.c:118: if (hi) emit_dn(hi);
	mov	a,_table_move_hi_65536_26
	jz	00117$
	mov	dpl,_table_move_hi_65536_26
	push	ar3
	push	ar2
	lcall	_emit_dn
	pop	ar2
	pop	ar3
00117$:
;	src/motion.c:121: rec(t_k <= t_r ? K_COUNT : K_SCOUNT, n < 2 ? n : 2, 0);
	clr	c
	mov	a,_t_r
	subb	a,_t_k
	mov	_table_move_sloc0_1_0,c
	jc	00122$
	mov	r6,#0x02
	mov	r7,#0x00
	sjmp	00123$
00122$:
	mov	r6,#0x06
	mov	r7,#0x00
00123$:
	clr	c
	mov	a,r2
	subb	a,#0x02
	mov	a,r3
	subb	a,#0x00
	jnc	00124$
	mov	ar5,r2
	mov	ar7,r3
	sjmp	00125$
00124$:
	mov	r5,#0x02
	mov	r7,#0x00
00125$:
	mov	_rec_PARM_2,r5
	mov	(_rec_PARM_2 + 1),r7
	clr	a
	mov	_rec_PARM_3,a
	mov	(_rec_PARM_3 + 1),a
	mov	dpl,r6
	push	ar3
	push	ar2
	lcall	_rec
;	src/motion.c:122: rec(K_END, 1, 0);
	mov	_rec_PARM_2,#0x01
	clr	a
	mov	(_rec_PARM_2 + 1),a
	mov	_rec_PARM_3,a
	mov	(_rec_PARM_3 + 1),a
	mov	dpl,a
	lcall	_rec
;	src/motion.c:123: start(rd16(t_slow), n >= 2 ? rd16(t_slow + 2) : 0xFFFF);
	mov	dpl,_t_slow
	mov	dph,(_t_slow + 1)
	lcall	_rd16
	mov	r6,dpl
	mov	r7,dph
	pop	ar2
	pop	ar3
	clr	c
	mov	a,r2
	subb	a,#0x02
	mov	a,r3
	subb	a,#0x00
	mov	_table_move_sloc0_1_0,c
	jc	00126$
	mov	dpl,_t_slow
	mov	dph,(_t_slow + 1)
	inc	dptr
	inc	dptr
	push	ar7
	push	ar6
	lcall	_rd16
	mov	r4,dpl
	mov	r5,dph
	pop	ar6
	pop	ar7
	sjmp	00127$
00126$:
	mov	r4,#0xff
	mov	r5,#0xff
00127$:
	mov	_start_PARM_2,r4
	mov	(_start_PARM_2 + 1),r5
	mov	dpl,r6
	mov	dph,r7
;	src/motion.c:124: }
	ljmp	_start
;------------------------------------------------------------
;Allocation info for local variables in function 'move_carriage'
;------------------------------------------------------------
;n                         Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/motion.c:126: void move_carriage(uint16_t n) {
;	-----------------------------------------
;	 function move_carriage
;	-----------------------------------------
_move_carriage:
	mov	r6,dpl
	mov	r7,dph
;	src/motion.c:127: s_pin = PIN_CSTEP;
	mov	_s_pin,#0x01
;	src/motion.c:128: t_r = RAMP_R;
	mov	_t_r,#0xfa
;	src/motion.c:129: t_k = RAMP_K;
	mov	_t_k,#0x08
;	src/motion.c:130: t_slow = ramp_slow;
	mov	_t_slow,#_ramp_slow
	mov	(_t_slow + 1),#(_ramp_slow >> 8)
;	src/motion.c:131: table_move(n);
	mov	dpl,r6
	mov	dph,r7
;	src/motion.c:132: }
	ljmp	_table_move
;------------------------------------------------------------
;Allocation info for local variables in function 'move_feed'
;------------------------------------------------------------
;n                         Allocated to registers r6 r7 
;------------------------------------------------------------
;	src/motion.c:134: void move_feed(uint16_t n) {
;	-----------------------------------------
;	 function move_feed
;	-----------------------------------------
_move_feed:
	mov	r6,dpl
	mov	r7,dph
;	src/motion.c:135: s_pin = PIN_FSTEP;
	mov	_s_pin,#0x04
;	src/motion.c:136: t_r = FEED_R;
	mov	_t_r,#0xb4
;	src/motion.c:137: t_k = (uint8_t)(FEED_R + 1);
	mov	_t_k,#0xb5
;	src/motion.c:138: t_slow = feed_table;
	mov	_t_slow,#_feed_table
	mov	(_t_slow + 1),#(_feed_table >> 8)
;	src/motion.c:139: table_move(n);
	mov	dpl,r6
	mov	dph,r7
;	src/motion.c:140: }
	ljmp	_table_move
;------------------------------------------------------------
;Allocation info for local variables in function 'one_phase'
;------------------------------------------------------------
;n                         Allocated with name '_one_phase_PARM_2'
;interval                  Allocated with name '_one_phase_PARM_3'
;kind                      Allocated to registers r7 
;------------------------------------------------------------
;	src/motion.c:143: static void one_phase(uint8_t kind, uint16_t n, uint16_t interval) {
;	-----------------------------------------
;	 function one_phase
;	-----------------------------------------
_one_phase:
	mov	r7,dpl
;	src/motion.c:144: wp = prog;
	mov	_wp,#_prog
;	src/motion.c:145: rec(kind, n, 0);
	mov	_rec_PARM_2,_one_phase_PARM_2
	mov	(_rec_PARM_2 + 1),(_one_phase_PARM_2 + 1)
	clr	a
	mov	_rec_PARM_3,a
	mov	(_rec_PARM_3 + 1),a
	mov	dpl,r7
	lcall	_rec
;	src/motion.c:146: rec(K_END, 1, 0);
	mov	_rec_PARM_2,#0x01
	clr	a
	mov	(_rec_PARM_2 + 1),a
	mov	_rec_PARM_3,a
	mov	(_rec_PARM_3 + 1),a
	mov	dpl,a
	lcall	_rec
;	src/motion.c:147: start((uint16_t)(0 - interval), (uint16_t)(0 - interval));
	clr	c
	clr	a
	subb	a,_one_phase_PARM_3
	mov	r6,a
	clr	a
	subb	a,(_one_phase_PARM_3 + 1)
	mov	r7,a
	mov	_start_PARM_2,r6
	mov	(_start_PARM_2 + 1),r7
	mov	dpl,r6
	mov	dph,r7
;	src/motion.c:148: }
	ljmp	_start
;------------------------------------------------------------
;Allocation info for local variables in function 'move_constant'
;------------------------------------------------------------
;n                         Allocated with name '_move_constant_PARM_2'
;interval                  Allocated with name '_move_constant_PARM_3'
;pin                       Allocated to registers 
;------------------------------------------------------------
;	src/motion.c:150: void move_constant(uint8_t pin, uint16_t n, uint16_t interval) {
;	-----------------------------------------
;	 function move_constant
;	-----------------------------------------
_move_constant:
	mov	_s_pin,dpl
;	src/motion.c:152: one_phase(K_SCOUNT, n, interval);
	mov	_one_phase_PARM_2,_move_constant_PARM_2
	mov	(_one_phase_PARM_2 + 1),(_move_constant_PARM_2 + 1)
	mov	_one_phase_PARM_3,_move_constant_PARM_3
	mov	(_one_phase_PARM_3 + 1),(_move_constant_PARM_3 + 1)
	mov	dpl,#0x06
;	src/motion.c:153: }
	ljmp	_one_phase
;------------------------------------------------------------
;Allocation info for local variables in function 'move_home'
;------------------------------------------------------------
;interval                  Allocated with name '_move_home_PARM_2'
;n                         Allocated to registers 
;------------------------------------------------------------
;	src/motion.c:155: void move_home(uint16_t n, uint16_t interval) {
;	-----------------------------------------
;	 function move_home
;	-----------------------------------------
_move_home:
	mov	_one_phase_PARM_2,dpl
	mov	(_one_phase_PARM_2 + 1),dph
;	src/motion.c:156: s_pin = PIN_CSTEP;
	mov	_s_pin,#0x01
;	src/motion.c:157: one_phase(K_HOME, n, interval);
	mov	_one_phase_PARM_3,_move_home_PARM_2
	mov	(_one_phase_PARM_3 + 1),(_move_home_PARM_2 + 1)
	mov	dpl,#0x07
;	src/motion.c:158: }
	ljmp	_one_phase
;------------------------------------------------------------
;Allocation info for local variables in function 'wait_ticks'
;------------------------------------------------------------
;ticks                     Allocated to registers 
;------------------------------------------------------------
;	src/motion.c:160: void wait_ticks(uint16_t ticks) {
;	-----------------------------------------
;	 function wait_ticks
;	-----------------------------------------
_wait_ticks:
	mov	_one_phase_PARM_3,dpl
	mov	(_one_phase_PARM_3 + 1),dph
;	src/motion.c:161: s_pin = 0;
	mov	_s_pin,#0x00
;	src/motion.c:162: one_phase(K_SCOUNT, 1, ticks);
	mov	_one_phase_PARM_2,#0x01
	mov	(_one_phase_PARM_2 + 1),#0x00
	mov	dpl,#0x06
;	src/motion.c:163: }
	ljmp	_one_phase
	.area CSEG    (CODE)
	.area CONST   (CODE)
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
