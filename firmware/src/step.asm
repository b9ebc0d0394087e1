; SPDX-License-Identifier: GPL-3.0-or-later
; The step interrupt (timer 2, 16-bit auto-reload, high priority).
;
; Why assembly: SDCC's C costs 94-99 cycles a step, which saturates the 89C52
; near 9,600 steps/s (docs/emulator.md). Here a cruise step
; costs 15 machine cycles and a ramp step 30, counted from the interrupt's
; LCALL to its RETI (bench/firmware measures them).
;
; Timing is exact by construction: in auto-reload mode the timer reloads from
; RCAP2 at the overflow itself, so interrupt latency never shifts the schedule.
; The price is that RCAP2 is written one step ahead: the interrupt for step k
; writes the interval before step k + 2 (motion.c lays the program out so).
;
; A move is a program of phases (motion.c fills mv_prog), each a record of
; 5 bytes: kind, count low, count high, table pointer low, pointer high.
; Counts are in DJNZ form: low byte 1..256 (0 = 256) and high byte = 1 + whole
; 256-blocks beyond the low byte.
;   kind 0 END      stop the timer, set mv_done
;   kind 1 FAST_UP  carriage step, RCAP2L from the inline table, index rising
;   kind 2 COUNT    carriage step, nothing written (cruise, last two steps)
;   kind 3 FAST_DN  carriage step, RCAP2L from the inline table, index falling
;   kind 4 SLOW_UP  step on s_pin, RCAP2 from a 16-bit table, pointer rising
;   kind 5 SLOW_DN  the same, pointer falling
;   kind 6 SCOUNT   step on s_pin (none if 0), nothing written: feed cruise, delays
;   kind 7 HOME     step on s_pin until the limit switch (P3.3, active low)
;   kind 8 HOFF     both hammers off (no step): the end of the hammer pulse
;   kind 9 LAST     step on s_pin, RCAP2 := 0: a move's last two steps
;
; Every phase is scheduled from the timer, never from when the main loop
; gets to it: a program's last event reloads the counter from 0 (LAST, or a
; one-event phase started with RCAP2 = 0), and the timer keeps running after
; END, so the counter says how many cycles ago that event was. timer_go then
; starts the next program at an exact offset from it (the main loop only has
; to get there before that offset runs out). After 65,536 idle cycles the
; interrupt stops the timer: the next program starts from when it is given.
; A hammer comes down at a timer event too (a one-event SCOUNT phase whose
; s_pin is the hammer), and goes up at the next (HOFF).
        .module step
        .globl  _t2_isr
        .globl  _nextph
        .globl  _timer_go
        .globl  _m_slow, _m_cr, _m_fu, _m_upcr, _m_updn, _mv_done, _mv_limit
        .globl  _c_cl, _c_ch, _c_ui, _c_di, _s_pl, _s_ph, _s_pin, _s_kind, _mv_p, _t2_a

ACC     = 0xE0
PSW     = 0xD0
DPL     = 0x82
DPH     = 0x83
P1      = 0x90
RCAP2L  = 0xCA
RCAP2H  = 0xCB
TF2     = 0xCF          ; bit T2CON.7
TR2     = 0xCA          ; bit T2CON.2
TL2     = 0xCC
TH2     = 0xCD
EA      = 0xAF          ; bit IE.7
ACC0    = 0xE0          ; bit ACC.0
ACC1    = 0xE1          ; bit ACC.1
ACC2    = 0xE2          ; bit ACC.2
CSTEP   = 0x90          ; bit P1.0: carriage STEP
LIMIT   = 0xB3          ; bit P3.3: limit switch, low when reached
        .include "ramp_eq.inc"  ; RAMP_DN_CL, RAMP_DN_CH, RAMP_DN_TOP (gen-ramp.py)

        .area CSEG (CODE)

; Latency compensation: every edge (carriage and feed
; steps, a hammer going down or up) is made by one XRL P1 exactly EDGE_TICKS
; machine cycles after its timer event (the overflow), whatever the latency.
; The latency is the instruction the interrupt waits for: the rest of the one
; under way, or, after a RETI (the UART's or the strobe's), the rest of it and
; the next one. With no MUL or DIV in the image (4 cycles; tools/stack-depth.py
; fails the build on them) s51 showed 0-4 cycles with the compensation taken
; out (0 or 1 nearly always, 2-4 about 1 edge in 1,000 with the UART busy),
; and one edge in a noisy run past a window of 0-4. The interrupt reads TL2,
; which counts cycles since the overflow from RCAP2L (the reload, not yet
; rewritten: the vectoring LCALL starts 2 cycles after the overflow in s51,
; then PUSH, XCH, CLR TF2, JNB and two more put the read at 12 + latency),
; and a tree of bit tests (LATENCY) burns the rest: 9 - latency cycles for a
; latency of 0 to LAT_MAX. The edge then comes at 13 (the SUBB's end) + 9 +
; 1 (MOV) = EDGE_TICKS after the overflow, counted the way s51's trace stamps
; a port write (at its instruction's start). The host takes EDGE_TICKS off where it
; compares pin traces with a plan (core/machine/firmware_tables.hpp,
; kPinEdgeTicks; FirmwareEdgeDelay checks the two agree).
;
; The worst latency is 5 cycles (firmware/README.md, "Step timing"): a RETI
; and the instruction after it (3), then a low-priority request s51 takes
; first at that boundary (it goes by its list, not the priority): its
; vectoring and the vector's first instruction, a NOP (tools/vectors.py), 2.
; With SDCC's LJMP there (3) an edge came 2 cycles late about once in 3.5
; million (tests/firmware/emu_latency_test.py forces it).
;
; The cost is on every step: the cruise path is 30 - latency cycles (the
; issue's bar is 70 % of the CPU at the top rate, 46 cycles a step), and
; the ramp's top paths (46-50 cycles a step) must end within about 2 cycles
; of the next timer event, or that event's latency grows past the window. A
; latency past LAT_MAX (6 or 7) puts its edge 2 cycles late.
LAT_MAX = 5
EDGE_TICKS = 23

; The read and the chain, in both entries (after the same 7 cycles: PUSH,
; XCH, CLR, JNB). SUBB reads TL2 = RCAP2L + the cycles since the overflow
; (12 + latency in s51), so A = RCAP2L - TL2 - 1 has 3 - latency in its low
; 3 bits (latency 0-5: 011, 010, 001, 000, 111, 110). The tree takes
; 9 - latency cycles on every branch: latency 4 and 5 (bit 2 set) two tests
; and a NOP or none, latency 0-3 three tests and their pads (bit 0 set: 1,
; bit 1 set: 2). A latency of 6 or 7 would come 2 cycles late, never 8.
        .macro  LATENCY, ?l1, ?l2, ?l3
        setb    c                       ; 1
        mov     a, RCAP2L               ; 1
        subb    a, TL2                  ; 1
        jb      ACC2, l2                ; 2
        jnb     ACC0, l1                ; 2
        nop                             ; 1
l1:     jnb     ACC1, l3                ; 2
        sjmp    l3                      ; 2
l2:     jnb     ACC0, l3                ; 2
        nop                             ; 1
l3:
        .endm

_t2_isr:
        push    PSW                     ; 2
        xch     a, _t2_a                ; 1  ACC kept in RAM: no stack
        clr     TF2                     ; 1
        jnb     _m_cr, 10$              ; 2  (before the read: it costs no cycle there)
        LATENCY                         ; 3 + 9 - latency
        mov     a, _s_pin               ; 1
        xrl     P1, a                   ; 1  the edge: every step pin is low here
        djnz    _c_cl, 99$              ; 2  cruise: RCAP2 already holds T[R]
        djnz    _c_ch, 99$
        ; The cruise ends at full speed: loading the descent through _nextph
        ; (about 50 cycles) would hold the next edges back. A cruise is only
        ; in a whole ramp, so the descent is always the whole fast table
        ; (ramp_eq.inc), and _nextph left mv_p past it with the ascent.
        clr     _m_cr
        clr     _m_fu
        mov     _c_cl, #RAMP_DN_CL
        mov     _c_ch, #RAMP_DN_CH
        mov     _c_di, #RAMP_DN_TOP
99$:    clr     CSTEP                   ; 1
        xch     a, _t2_a                ; 1
        pop     PSW                     ; 2
        reti                            ; 2

10$:    LATENCY                         ; the same, for every other phase
        mov     a, _s_pin               ; 1
        xrl     P1, a                   ; 1  the edge: the step pins are low here,
                                        ;    the hammers as motion.c sets s_pin
        jb      _m_fu, up               ; 2
        jb      _m_slow, 11$            ; 2
        ljmp    fastdn                  ; 2
11$:    ljmp    slow

        ; The ascent's end at full speed: loading the next phase through
        ; _nextph (about 55 cycles) would let the next timer events fall
        ; inside this interrupt. _nextph loaded what follows with the
        ; ascent: a cruise (its count, mv_p past it and the descent), or a
        ; short move's turn (the descent's count and mv_p; its index in s_ph).
        ; (m_upcr and m_updn need no clearing: _nextph sets both whenever it
        ; loads a fast ascent, the only phase that reads them.)
turn:   clr     _m_fu                   ; 1
        mov     _c_di, _s_ph            ; 2
        sjmp    upx                     ; 2
cruise: setb    _m_cr                   ; 1  tested first: m_fu may stay
        sjmp    upx                     ; 2
        ; The ascent writes low bytes only: the slow ascent before it wrote
        ; T[K], whose high byte is 0xFF like every fast entry's (motion.c).
up:     mov     a, _c_ui                ; 1  index + RAMP_FAST_BIAS
        inc     _c_ui                   ; 1
        djnz    _c_di, upx              ; 2  the ascent counts in c_di (<= 256 steps)
        jb      _m_updn, turn           ; 2
        jb      _m_upcr, cruise         ; 2
        setb    c                       ; the ascent's table, through DPTR
        ljmp    last
upx:    clr     CSTEP                   ; 1
        movc    a, @a+pc                ; 2  the table is 7 bytes on:
        mov     RCAP2L, a               ; 1  (2 bytes)
        xch     a, _t2_a                ; 1  (2 bytes)
        pop     PSW                     ; 2  (2 bytes)
        reti                            ; 2  (1 byte)
uptab:  .include "ramp_up.inc"

fastdn: mov     a, _c_di                ; 1
        dec     _c_di                   ; 1
        djnz    _c_cl, dnx              ; 2
        djnz    _c_ch, dnx
        clr     c                       ; the descent's table, through DPTR
        ljmp    last
dnx:    clr     CSTEP                   ; 1
        movc    a, @a+pc                ; 2  the table is 7 bytes on
        mov     RCAP2L, a               ; 1
        xch     a, _t2_a                ; 1
        pop     PSW                     ; 2
        reti                            ; 2
dntab:  .include "ramp_dn.inc"

        ; A fast phase's last step with no inline switch (its interval is
        ; about 256 cycles): its reload from the table through DPTR (C: the
        ; ascent's), then the next phase through nextph_isr.
last:   clr     CSTEP
        push    DPL
        push    DPH
        mov     DPTR, #(dntab - 7)
        jnc     1$
        mov     DPTR, #(uptab - 7)
1$:     movc    a, @a+dptr
        mov     RCAP2L, a
        pop     DPH
        pop     DPL
        xch     a, _t2_a
        pop     PSW
        ljmp    nextph_isr              ; it returns from the interrupt

; Everything that is not a fast carriage step: 16-bit tables, the feed,
; homing, delays, hammers. Intervals here are at least 120 ticks.
slow:   push    DPL
        push    DPH
        mov     a, _s_kind
        jz      70$                     ; idle after END (s_pin is 0)
        cjne    a, #4, 30$
        mov     DPL, _s_pl              ; SLOW_UP: RCAP2 := the big-endian reload at
        mov     DPH, _s_ph              ; s_ph:s_pl, DPTR left at its low byte
        clr     a                       ; (inline: a call would cost the stack
        movc    a, @a+dptr              ; 2 bytes, README "Stack")
        mov     RCAP2H, a
        inc     dptr
        clr     a
        movc    a, @a+dptr
        mov     RCAP2L, a
        inc     dptr
        mov     _s_pl, DPL
        mov     _s_ph, DPH
        sjmp    50$
30$:    cjne    a, #5, 40$
        mov     DPL, _s_pl              ; SLOW_DN: RCAP2 := the big-endian reload at
        mov     DPH, _s_ph              ; s_ph:s_pl, DPTR left at its low byte
        clr     a                       ; (inline: a call would cost the stack
        movc    a, @a+dptr              ; 2 bytes, README "Stack")
        mov     RCAP2H, a
        inc     dptr
        clr     a
        movc    a, @a+dptr
        mov     RCAP2L, a
        mov     a, _s_pl
        clr     c
        subb    a, #2
        mov     _s_pl, a
        mov     a, _s_ph
        subb    a, #0
        mov     _s_ph, a
        sjmp    50$
40$:    cjne    a, #7, 45$
        jb      LIMIT, 50$              ; HOME: switch not reached yet
        clr     TR2                     ; reached: stop here
        setb    _mv_limit
        setb    _mv_done
        sjmp    60$
45$:    cjne    a, #8, 46$
        anl     P1, #0xCF               ; HOFF: both hammers up (the edge was made)
        sjmp    50$
46$:    cjne    a, #9, 50$
        clr     a                       ; LAST: the counter restarts from 0
        mov     RCAP2L, a               ; at the move's last step
        mov     RCAP2H, a
50$:    djnz    _c_cl, 60$
        djnz    _c_ch, 60$
        ; A phase change: lower the pins, restore everything, and jump to
        ; nextph_isr, which saves what it touches and returns from the
        ; interrupt. Its 3 bytes then sit where these 3 were, not on top of
        ; them (README, "Stack"). The pins fall before the phase is loaded
        ; instead of after: only the rising edges are timed.
        anl     P1, #0xFA               ; step pins low (the hammers stay)
        pop     DPH
        pop     DPL
        xch     a, _t2_a
        pop     PSW
        ljmp    nextph_isr
60$:    anl     P1, #0xFA               ; step pins low (the hammers stay)
        pop     DPH
        pop     DPL
        xch     a, _t2_a
        pop     PSW
        reti
70$:    clr     TR2                     ; 65,536 cycles idle: no reference now
        sjmp    60$

; void timer_go(uint16_t x): runs the program nextph loaded, its first event
; x machine cycles after the last event of the one before (DPTR = x). The
; counter is stopped for exactly FROZEN cycles while it is moved forward, so
; the offset holds to the cycle. Called with the timer interrupt disabled.
; Late (the main loop came after x) or no reference: the first event comes x
; cycles from now.
FROZEN  = 9
_timer_go:
        clr     c
        mov     a, #FROZEN
        subb    a, DPL
        mov     r2, a                   ; adj = FROZEN - x (mod 65536)
        clr     a
        subb    a, DPH
        mov     r3, a
        clr     EA
        jnb     TR2, 80$                ; stopped: no reference
        jb      TF2, 80$                ; the idle overflow came first
        clr     TR2                     ; frozen from here ...
        mov     a, TL2
        add     a, r2
        mov     TL2, a
        mov     a, TH2
        addc    a, r3
        mov     TH2, a
        jc      80$                     ; late: it would wrap
        setb    TR2                     ; ... to here
        setb    EA
        ret
80$:    clr     TR2
        clr     c                       ; counter := -x
        clr     a
        subb    a, DPL
        mov     TL2, a
        clr     a
        subb    a, DPH
        mov     TH2, a
        clr     TF2
        setb    TR2
        setb    EA
        ret

; Loads the phase record at mv_p and advances mv_p (nextph.inc). Two entries:
; _nextph for motion.c (timer stopped), which returns; nextph_isr, jumped to
; by the interrupt once it has restored everything and lowered the step pins,
; which returns from the interrupt itself. The interrupt's phase change then
; holds 2 + 3 bytes of stack instead of 2 + 4 + 2 + 3 (README, "Stack").
; Both save everything they touch.
_nextph:
        push    PSW
        push    ACC
        mov     PSW, #0                 ; bank 0: R0 is address 0
        push    0
        .include "nextph.inc"
9$:     pop     0
        pop     ACC
        pop     PSW
        ret

nextph_isr:
        push    PSW
        push    ACC
        mov     PSW, #0
        push    0
        .include "nextph.inc"
9$:     pop     0
        pop     ACC
        pop     PSW
        reti
