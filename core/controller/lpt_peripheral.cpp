// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/lpt_peripheral.hpp"

namespace tactus::controller {

std::vector<std::uint8_t> LptPeripheral::take_received() { return std::exchange(received_, {}); }

void LptPeripheral::send(std::span<const std::uint8_t> bytes) {
    outgoing_.insert(outgoing_.end(), bytes.begin(), bytes.end());
}

void LptPeripheral::set_condition(bool paper_out, bool fault, bool online) {
    paper_out_ = paper_out;
    fault_ = fault;
    online_ = online;
    if (mode_ == Mode::compat) show_condition();
}

void LptPeripheral::show_condition() {
    st_.paper_error = paper_out_;
    st_.n_fault = !fault_;
    st_.select = online_;
}

// Nibble mode: nFault, Select, PError and Busy carry data bits 0-3.
void LptPeripheral::show_nibble(unsigned n) {
    st_.n_fault = (n & 1U) != 0;
    st_.select = (n & 2U) != 0;
    st_.paper_error = (n & 4U) != 0;
    st_.busy = (n & 8U) != 0;
}

void LptPeripheral::tick() {
    const bool strobe_fell = prev_.n_strobe && !ctl_.n_strobe;
    prev_ = ctl_;
    switch (mode_) {
        case Mode::compat:
            if (ack_phase_ == 1) {  // nAck pulse after the byte is latched
                st_.n_ack = false;
                ack_phase_ = 2;
                return;
            }
            if (ack_phase_ == 2) {
                st_.n_ack = true;
                st_.busy = false;
                ack_phase_ = 0;
                return;
            }
            if (ctl_.n_select_in && !ctl_.n_auto_fd) {  // event 1: negotiation request
                mode_ = Mode::negotiating;
                saw_strobe_low_ = false;
                st_ = {false, false, true, true, true};  // event 2
                return;
            }
            if (strobe_fell && !st_.busy) {
                received_.push_back(data_);
                st_.busy = true;
                ack_phase_ = 1;
            }
            show_condition();
            return;
        case Mode::negotiating:
            if (!ctl_.n_select_in) {
                // The host gave the negotiation up (its handshake timed out,
                // it reopened the port): compatibility mode again, nAck high.
                // Waiting on for its strobe answered no later negotiation.
                mode_ = Mode::compat;
                st_.n_ack = true;
                st_.busy = false;
                show_condition();
                return;
            }
            if (!ctl_.n_strobe) saw_strobe_low_ = true;
            if (saw_strobe_low_ && ctl_.n_strobe && ctl_.n_auto_fd) {  // events 3-4 seen
                // Events 5-6: nibble mode (request 0x00) accepted, XFlag low,
                // nDataAvail (nFault) low when there is something to send.
                st_.paper_error = false;
                st_.select = false;
                st_.busy = false;
                st_.n_fault = outgoing_.empty();
                st_.n_ack = true;
                mode_ = data_ == 0x00 ? Mode::idle : Mode::compat;
            }
            return;
        case Mode::idle:
            if (!ctl_.n_select_in) {  // event 22: host ends the 1284 mode
                st_.n_ack = false;    // event 24
                mode_ = Mode::term_ack;
                return;
            }
            if (!ctl_.n_auto_fd && !outgoing_.empty()) {  // event 7: host ready
                show_nibble(outgoing_.front() & 0x0FU);
                st_.n_ack = false;  // event 9
                mode_ = Mode::low_shown;
            }
            return;
        case Mode::low_shown:
            if (ctl_.n_auto_fd) {  // event 10
                st_.n_ack = true;  // event 11
                mode_ = Mode::low_done;
            }
            return;
        case Mode::low_done:
            if (!ctl_.n_auto_fd) {
                show_nibble(static_cast<unsigned>(outgoing_.front() >> 4));
                st_.n_ack = false;
                mode_ = Mode::high_shown;
            }
            return;
        case Mode::high_shown:
            if (ctl_.n_auto_fd) {
                // The byte is over: nDataAvail for the next, XFlag (Select),
                // PError and Busy low, as after the negotiation (the firmware
                // sets all four status lines at once: firmware/src/lpt.c).
                outgoing_.pop_front();
                st_.n_ack = true;
                st_.busy = false;
                st_.paper_error = false;
                st_.select = false;
                st_.n_fault = outgoing_.empty();
                mode_ = Mode::idle;
            }
            return;
        case Mode::term_ack:
            if (!ctl_.n_auto_fd) {  // event 25
                st_.n_ack = true;   // event 27
                mode_ = Mode::term_done;
            }
            return;
        case Mode::term_done:
            // Event 28 (HostBusy high): back in compatibility mode. The host
            // may already be negotiating again (nSelectIn high, nAutoFd low):
            // the event has no answer from this side, and a poll can miss it.
            if (ctl_.n_auto_fd || ctl_.n_select_in) {
                mode_ = Mode::compat;
                st_.busy = false;
                show_condition();
            }
            return;
    }
}

}  // namespace tactus::controller
