;--------------------------------------------------------
; File Created by SDCC : free open source ANSI-C Compiler
; Version 4.2.0 #13081 (Linux)
;--------------------------------------------------------
	.module ramp_tables
	.optsdcc -mmcs51 --model-small
	
;--------------------------------------------------------
; Public variables in this module
;--------------------------------------------------------
	.globl _fw_table_id
	.globl _feed_table
	.globl _ramp_slow
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
;--------------------------------------------------------
; overlayable items in internal ram
;--------------------------------------------------------
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
	.area CSEG    (CODE)
	.area CONST   (CODE)
_ramp_slow:
	.db #0xf2	; 242
	.db #0x17	; 23
	.db #0xfb	; 251
	.db #0x62	; 98	'b'
	.db #0xfd	; 253
	.db #0x53	; 83	'S'
	.db #0xfe	; 254
	.db #0x03	; 3
	.db #0xfe	; 254
	.db #0x62	; 98	'b'
	.db #0xfe	; 254
	.db #0x9f	; 159
	.db #0xfe	; 254
	.db #0xc9	; 201
	.db #0xfe	; 254
	.db #0xe9	; 233
_feed_table:
	.db #0xdb	; 219
	.db #0xa5	; 165
	.db #0xf3	; 243
	.db #0xde	; 222
	.db #0xf8	; 248
	.db #0xf3	; 243
	.db #0xfa	; 250
	.db #0xc0	; 192
	.db #0xfb	; 251
	.db #0xb9	; 185
	.db #0xfc	; 252
	.db #0x58	; 88	'X'
	.db #0xfc	; 252
	.db #0xc7	; 199
	.db #0xfd	; 253
	.db #0x1b	; 27
	.db #0xfd	; 253
	.db #0x5c	; 92
	.db #0xfd	; 253
	.db #0x8f	; 143
	.db #0xfd	; 253
	.db #0xbb	; 187
	.db #0xfd	; 253
	.db #0xde	; 222
	.db #0xfd	; 253
	.db #0xfd	; 253
	.db #0xfe	; 254
	.db #0x18	; 24
	.db #0xfe	; 254
	.db #0x2f	; 47
	.db #0xfe	; 254
	.db #0x44	; 68	'D'
	.db #0xfe	; 254
	.db #0x55	; 85	'U'
	.db #0xfe	; 254
	.db #0x67	; 103	'g'
	.db #0xfe	; 254
	.db #0x74	; 116	't'
	.db #0xfe	; 254
	.db #0x83	; 131
	.db #0xfe	; 254
	.db #0x8e	; 142
	.db #0xfe	; 254
	.db #0x9a	; 154
	.db #0xfe	; 254
	.db #0xa3	; 163
	.db #0xfe	; 254
	.db #0xae	; 174
	.db #0xfe	; 254
	.db #0xb6	; 182
	.db #0xfe	; 254
	.db #0xbe	; 190
	.db #0xfe	; 254
	.db #0xc5	; 197
	.db #0xfe	; 254
	.db #0xcd	; 205
	.db #0xfe	; 254
	.db #0xd4	; 212
	.db #0xfe	; 254
	.db #0xd9	; 217
	.db #0xfe	; 254
	.db #0xe0	; 224
	.db #0xfe	; 254
	.db #0xe4	; 228
	.db #0xfe	; 254
	.db #0xeb	; 235
	.db #0xfe	; 254
	.db #0xee	; 238
	.db #0xfe	; 254
	.db #0xf4	; 244
	.db #0xfe	; 254
	.db #0xf8	; 248
	.db #0xfe	; 254
	.db #0xfc	; 252
	.db #0xff	; 255
	.db #0x00	; 0
	.db #0xff	; 255
	.db #0x04	; 4
	.db #0xff	; 255
	.db #0x07	; 7
	.db #0xff	; 255
	.db #0x0b	; 11
	.db #0xff	; 255
	.db #0x0e	; 14
	.db #0xff	; 255
	.db #0x11	; 17
	.db #0xff	; 255
	.db #0x14	; 20
	.db #0xff	; 255
	.db #0x16	; 22
	.db #0xff	; 255
	.db #0x1a	; 26
	.db #0xff	; 255
	.db #0x1c	; 28
	.db #0xff	; 255
	.db #0x1f	; 31
	.db #0xff	; 255
	.db #0x21	; 33
	.db #0xff	; 255
	.db #0x23	; 35
	.db #0xff	; 255
	.db #0x26	; 38
	.db #0xff	; 255
	.db #0x27	; 39
	.db #0xff	; 255
	.db #0x2a	; 42
	.db #0xff	; 255
	.db #0x2c	; 44
	.db #0xff	; 255
	.db #0x2e	; 46
	.db #0xff	; 255
	.db #0x2f	; 47
	.db #0xff	; 255
	.db #0x31	; 49	'1'
	.db #0xff	; 255
	.db #0x33	; 51	'3'
	.db #0xff	; 255
	.db #0x35	; 53	'5'
	.db #0xff	; 255
	.db #0x36	; 54	'6'
	.db #0xff	; 255
	.db #0x38	; 56	'8'
	.db #0xff	; 255
	.db #0x39	; 57	'9'
	.db #0xff	; 255
	.db #0x3a	; 58
	.db #0xff	; 255
	.db #0x3d	; 61
	.db #0xff	; 255
	.db #0x3d	; 61
	.db #0xff	; 255
	.db #0x3f	; 63
	.db #0xff	; 255
	.db #0x40	; 64
	.db #0xff	; 255
	.db #0x41	; 65	'A'
	.db #0xff	; 255
	.db #0x42	; 66	'B'
	.db #0xff	; 255
	.db #0x44	; 68	'D'
	.db #0xff	; 255
	.db #0x44	; 68	'D'
	.db #0xff	; 255
	.db #0x46	; 70	'F'
	.db #0xff	; 255
	.db #0x47	; 71	'G'
	.db #0xff	; 255
	.db #0x47	; 71	'G'
	.db #0xff	; 255
	.db #0x49	; 73	'I'
	.db #0xff	; 255
	.db #0x4a	; 74	'J'
	.db #0xff	; 255
	.db #0x4b	; 75	'K'
	.db #0xff	; 255
	.db #0x4b	; 75	'K'
	.db #0xff	; 255
	.db #0x4d	; 77	'M'
	.db #0xff	; 255
	.db #0x4d	; 77	'M'
	.db #0xff	; 255
	.db #0x4e	; 78	'N'
	.db #0xff	; 255
	.db #0x4f	; 79	'O'
	.db #0xff	; 255
	.db #0x4f	; 79	'O'
	.db #0xff	; 255
	.db #0x51	; 81	'Q'
	.db #0xff	; 255
	.db #0x51	; 81	'Q'
	.db #0xff	; 255
	.db #0x52	; 82	'R'
	.db #0xff	; 255
	.db #0x53	; 83	'S'
	.db #0xff	; 255
	.db #0x53	; 83	'S'
	.db #0xff	; 255
	.db #0x54	; 84	'T'
	.db #0xff	; 255
	.db #0x54	; 84	'T'
	.db #0xff	; 255
	.db #0x55	; 85	'U'
	.db #0xff	; 255
	.db #0x56	; 86	'V'
	.db #0xff	; 255
	.db #0x57	; 87	'W'
	.db #0xff	; 255
	.db #0x57	; 87	'W'
	.db #0xff	; 255
	.db #0x57	; 87	'W'
	.db #0xff	; 255
	.db #0x58	; 88	'X'
	.db #0xff	; 255
	.db #0x59	; 89	'Y'
	.db #0xff	; 255
	.db #0x59	; 89	'Y'
	.db #0xff	; 255
	.db #0x59	; 89	'Y'
	.db #0xff	; 255
	.db #0x5a	; 90	'Z'
	.db #0xff	; 255
	.db #0x5b	; 91
	.db #0xff	; 255
	.db #0x5b	; 91
	.db #0xff	; 255
	.db #0x5b	; 91
	.db #0xff	; 255
	.db #0x5c	; 92
	.db #0xff	; 255
	.db #0x5c	; 92
	.db #0xff	; 255
	.db #0x5d	; 93
	.db #0xff	; 255
	.db #0x5d	; 93
	.db #0xff	; 255
	.db #0x5d	; 93
	.db #0xff	; 255
	.db #0x5e	; 94
	.db #0xff	; 255
	.db #0x5e	; 94
	.db #0xff	; 255
	.db #0x5f	; 95
	.db #0xff	; 255
	.db #0x5e	; 94
	.db #0xff	; 255
	.db #0x5f	; 95
	.db #0xff	; 255
	.db #0x60	; 96
	.db #0xff	; 255
	.db #0x60	; 96
	.db #0xff	; 255
	.db #0x60	; 96
	.db #0xff	; 255
	.db #0x60	; 96
	.db #0xff	; 255
	.db #0x61	; 97	'a'
	.db #0xff	; 255
	.db #0x61	; 97	'a'
	.db #0xff	; 255
	.db #0x61	; 97	'a'
	.db #0xff	; 255
	.db #0x61	; 97	'a'
	.db #0xff	; 255
	.db #0x62	; 98	'b'
	.db #0xff	; 255
	.db #0x62	; 98	'b'
	.db #0xff	; 255
	.db #0x62	; 98	'b'
	.db #0xff	; 255
	.db #0x62	; 98	'b'
	.db #0xff	; 255
	.db #0x62	; 98	'b'
	.db #0xff	; 255
	.db #0x63	; 99	'c'
	.db #0xff	; 255
	.db #0x63	; 99	'c'
	.db #0xff	; 255
	.db #0x63	; 99	'c'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x63	; 99	'c'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x63	; 99	'c'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x64	; 100	'd'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x65	; 101	'e'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
	.db #0xff	; 255
	.db #0x66	; 102	'f'
_fw_table_id:
	.db #0x47	; 71	'G'
	.db #0x4c	; 76	'L'
	.db #0xac	; 172
	.db #0x88	; 136
	.area XINIT   (CODE)
	.area CABS    (ABS,CODE)
