; SPDX-License-Identifier: GPL-3.0-or-later
; The step interrupt (timer 2, 16-bit auto-reload, high priority).
;
; Why assembly: SDCC's C costs 94-99 cycles a step, which saturates the 89C52
; near 9,600 steps/s (../shared/design/emulator-notes.md). Here a cruise step
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
        .module step
        .globl  _t2_isr
        .globl  _nextph
        .globl  _m_slow, _m_cr, _m_fu, _m_upcr, _mv_done, _mv_limit
        .globl  _c_cl, _c_ch, _c_ui, _c_di, _s_pl, _s_ph, _s_pin, _s_kind, _mv_p

ACC     = 0xE0
PSW     = 0xD0
DPL     = 0x82
DPH     = 0x83
P1      = 0x90
RCAP2L  = 0xCA
RCAP2H  = 0xCB
TF2     = 0xCF          ; bit T2CON.7
TR2     = 0xCA          ; bit T2CON.2
CSTEP   = 0x90          ; bit P1.0: carriage STEP
LIMIT   = 0xB3          ; bit P3.3: limit switch, low when reached

        .area CSEG (CODE)

_t2_isr:
        jnb     _m_slow, 1$             ; 2  (the slow path is beyond a relative jump)
        ljmp    slow
1$:        setb    CSTEP                   ; 1  step edge: the driver steps on the rise
        clr     TF2                     ; 1
        jnb     _m_cr, 10$              ; 2
        djnz    _c_cl, 99$              ; 2  cruise: RCAP2 already holds T[R]
        djnz    _c_ch, 99$
        lcall   _nextph
99$:    clr     CSTEP                   ; 1
        reti                            ; 2

10$:    jb      _m_fu, 13$              ; 2
        ljmp    fastdn                  ; 2
13$:    push    ACC                     ; 2
        mov     RCAP2H, #0xFF           ; 2  fast entries are <= 256 ticks
        mov     a, _c_ui                ; 1  index + RAMP_FAST_BIAS
        inc     _c_ui                   ; 1
        movc    a, @a+pc                ; 2  the table is 7 bytes on
        mov     RCAP2L, a               ; 1  (2 bytes)
        pop     ACC                     ; 2  (2 bytes)
        ljmp    11$                     ; 2  (3 bytes)
        .include "ramp_up.inc"
11$:    djnz    _c_cl, 12$              ; 2
        djnz    _c_ch, 12$
        ; The ramp ends at full speed, where a step is 46 cycles: loading the
        ; cruise through _nextph (about 55 cycles) here would let the next two
        ; timer events fall inside this interrupt and one would be lost.
        ; _nextph prepared the cruise when it loaded this phase: switch inline.
        jnb     _m_upcr, 14$
        clr     _m_upcr
        clr     _m_fu
        setb    _m_cr
        mov     _c_cl, _s_pl
        mov     _c_ch, _s_ph
        mov     _mv_p, _s_kind
        sjmp    12$
14$:    lcall   _nextph
12$:    clr     CSTEP                   ; 1
        reti                            ; 2

fastdn: push    ACC
        mov     a, _c_di
        dec     _c_di
        movc    a, @a+pc
        mov     RCAP2L, a
        pop     ACC
        ljmp    21$
        .include "ramp_dn.inc"
21$:    djnz    _c_cl, 22$
        djnz    _c_ch, 22$
        lcall   _nextph
22$:    clr     CSTEP
        reti

; Everything that is not a fast carriage step: 16-bit tables, the feed,
; homing, delays. Intervals here are at least 120 ticks.
slow:   push    PSW
        push    ACC
        push    DPL
        push    DPH
        clr     TF2
        mov     a, _s_pin
        orl     P1, a                   ; step edge (no pin for a delay)
        mov     a, _s_kind
        cjne    a, #4, 30$
        lcall   rd16                    ; SLOW_UP
        inc     dptr
        mov     _s_pl, DPL
        mov     _s_ph, DPH
        sjmp    50$
30$:    cjne    a, #5, 40$
        lcall   rd16                    ; SLOW_DN
        mov     a, _s_pl
        clr     c
        subb    a, #2
        mov     _s_pl, a
        mov     a, _s_ph
        subb    a, #0
        mov     _s_ph, a
        sjmp    50$
40$:    cjne    a, #7, 50$
        jb      LIMIT, 50$              ; HOME: switch not reached yet
        clr     TR2                     ; reached: stop here
        setb    _mv_limit
        setb    _mv_done
        sjmp    60$
50$:    djnz    _c_cl, 60$
        djnz    _c_ch, 60$
        lcall   _nextph
60$:    mov     a, _s_pin
        cpl     a
        anl     P1, a
        pop     DPH
        pop     DPL
        pop     ACC
        pop     PSW
        reti

; RCAP2 := the big-endian reload at s_ph:s_pl; DPTR is left at its low byte.
rd16:   mov     DPL, _s_pl
        mov     DPH, _s_ph
        clr     a
        movc    a, @a+dptr
        mov     RCAP2H, a
        inc     dptr
        clr     a
        movc    a, @a+dptr
        mov     RCAP2L, a
        ret

; Loads the phase record at mv_p and advances mv_p. Called from the interrupt
; when a phase's count runs out, and from motion.c (timer stopped) to load the
; first phase. Saves everything it touches.
_nextph:
        push    PSW
        push    ACC
        mov     PSW, #0                 ; bank 0: R0 is address 0
        push    0
        mov     r0, _mv_p
        mov     a, @r0                  ; kind
        mov     _s_kind, a
        inc     r0
        mov     _c_cl, @r0
        inc     r0
        mov     _c_ch, @r0
        inc     r0
        mov     _s_pl, @r0
        inc     r0
        mov     _s_ph, @r0
        inc     r0
        mov     _mv_p, r0
        clr     _m_cr
        clr     _m_fu
        setb    _m_slow
        jnz     1$
        clr     TR2                     ; END
        setb    _mv_done
        sjmp    9$
1$:     cjne    a, #1, 2$
        mov     _c_ui, _s_pl            ; FAST_UP
        clr     _m_slow
        setb    _m_fu
        ; A cruise next: keep its counts and the record after it in s_pl,
        ; s_ph, s_kind (unused on the fast paths) for the inline switch.
        clr     _m_upcr
        mov     a, @r0
        cjne    a, #2, 9$
        inc     r0
        mov     _s_pl, @r0
        inc     r0
        mov     _s_ph, @r0
        mov     a, _mv_p
        add     a, #5
        mov     _s_kind, a
        setb    _m_upcr
        sjmp    9$
2$:     cjne    a, #2, 3$
        clr     _m_slow                 ; COUNT (carriage)
        setb    _m_cr
        sjmp    9$
3$:     cjne    a, #3, 9$
        mov     _c_di, _s_pl            ; FAST_DN
        clr     _m_slow
9$:     pop     0
        pop     ACC
        pop     PSW
        ret
