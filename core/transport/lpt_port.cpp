// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/lpt_port.hpp"
#include "common/try.hpp"

#include <map>
#include <mutex>
#include <thread>

namespace tactus::transport {

namespace {
std::mutex g_cables_mutex;
std::map<std::string, LptCable>& cables() {
    static std::map<std::string, LptCable> m;
    return m;
}
}  // namespace

void register_lpt_cable(const std::string& name, LptCable cable) {
    const std::scoped_lock lock(g_cables_mutex);
    cables()[name] = std::move(cable);
}

const LptCable* registered_lpt_cable(const DeviceSpec& spec) {
    const std::scoped_lock lock(g_cables_mutex);
    const auto it = cables().find(spec.path);
    return it == cables().end() ? nullptr : &it->second;
}

double LptPort::now() const {
    if (lines_)
        if (auto c = lines_->clock()) return *c;
    return ByteStream::now();
}

void LptPort::sleep(std::chrono::microseconds duration) {
    if (lines_ && lines_->run_for(duration)) return;
    ByteStream::sleep(duration);
}

Result<std::unique_ptr<LptPort>> LptPort::open(Opener opener, std::string name, LptTimings t) {
    std::unique_ptr<LptPort> p(new LptPort(std::move(opener), std::move(name), t));
    TACTUS_TRY_VOID(p->reopen());
    return p;
}

Result<void> LptPort::reopen() {
    lines_.reset();
    TACTUS_TRY(l, opener_());
    lines_ = std::move(l);
    ctl_ = LptControl{};  // compatibility mode, idle
    if (auto r = lines_->write_control(ctl_); !r) return r;
    // The host's port opens whether or not a controller is on the cable: the
    // controller is there once it shows ready. A pulled cable or a switched-off
    // embosser leaves the status lines floating high, Busy among them, so a
    // reconnect keeps waiting for it instead of failing on its first byte.
    auto ready = wait_for([](const LptStatus& st) { return !st.busy; });
    if (!ready) return std::unexpected(ready.error());
    if (!*ready)
        return fail(ErrorKind::device, "no controller ready on the port (Busy stays high: cable out, or the embosser off)",
                    name_);
    return {};
}

// Polls the status lines until `ok`, or the handshake time runs out (false).
Result<bool> LptPort::wait_for(const std::function<bool(const LptStatus&)>& ok) {
    const double deadline = now() + std::chrono::duration<double>(timings_.handshake).count();
    for (;;) {
        TACTUS_TRY(st, lines_->read_status());
        if (ok(st)) return true;
        if (now() > deadline) return false;
        lines_->settle();
    }
}

// Compatibility mode, one byte: wait until not Busy, data on D0-D7, pulse
// nStrobe low; the peripheral latches it, raises Busy, pulses nAck, drops Busy.
Result<void> LptPort::write_byte(std::uint8_t b) {
    TACTUS_TRY(ready, wait_for([](const LptStatus& s) { return !s.busy; }));
    if (!ready) return fail(ErrorKind::device, "printer busy: the controller does not take data (Busy stays high)", name_);
    if (auto r = lines_->write_data(b); !r) return r;
    lines_->settle();
    ctl_.n_strobe = false;
    if (auto r = lines_->write_control(ctl_); !r) return r;
    lines_->settle();
    ctl_.n_strobe = true;
    if (auto r = lines_->write_control(ctl_); !r) return r;
    TACTUS_TRY(done, wait_for([](const LptStatus& s) { return !s.busy; }));
    if (!done) return fail(ErrorKind::device, "no acknowledge from the controller (Busy stuck high)", name_);
    return {};
}

Result<void> LptPort::write(std::span<const std::uint8_t> bytes) {
    if (!lines_) return fail(ErrorKind::device, "device not open", name_);
    for (const std::uint8_t b : bytes)
        if (auto r = write_byte(b); !r) return r;
    return {};
}

// IEEE 1284 negotiation for nibble mode (events 0-6). Returns whether the
// peripheral has data (nDataAvail = nFault low).
Result<bool> LptPort::negotiate_nibble() {
    if (auto r = lines_->write_data(0x00); !r) return std::unexpected(r.error());  // nibble mode
    ctl_.n_select_in = true;
    ctl_.n_auto_fd = false;
    TACTUS_TRY_VOID(lines_->write_control(ctl_));
    auto e2 = wait_for([](const LptStatus& s) {
        return !s.n_ack && s.paper_error && s.n_fault && s.select;
    });
    if (!e2) return std::unexpected(e2.error());
    if (!*e2) {
        ctl_ = LptControl{};
        (void)lines_->write_control(ctl_);
        return fail(ErrorKind::device, "the controller does not answer IEEE 1284 negotiation (not 1284-capable?)", name_);
    }
    ctl_.n_strobe = false;
    TACTUS_TRY_VOID(lines_->write_control(ctl_));
    lines_->settle();
    ctl_.n_strobe = true;
    ctl_.n_auto_fd = true;
    TACTUS_TRY_VOID(lines_->write_control(ctl_));
    TACTUS_TRY(e6, wait_for([](const LptStatus& s) { return s.n_ack; }));
    if (!e6) return fail(ErrorKind::device, "IEEE 1284 negotiation did not complete", name_);
    TACTUS_TRY(st, lines_->read_status());
    return !st.n_fault;
}

// Two nibbles (events 7-11 twice): nFault, Select, PError, Busy carry bits 0-3.
Result<std::uint8_t> LptPort::read_nibble_byte() {
    std::uint8_t value = 0;
    for (int half = 0; half < 2; ++half) {
        ctl_.n_auto_fd = false;  // HostBusy low: ready for a nibble
        TACTUS_TRY_VOID(lines_->write_control(ctl_));
        TACTUS_TRY(e9, wait_for([](const LptStatus& s) { return !s.n_ack; }));
        if (!e9) return fail(ErrorKind::device, "nibble transfer stalled (no nAck)", name_);
        TACTUS_TRY(st, lines_->read_status());
        const unsigned nib = (st.n_fault ? 1U : 0U) | (st.select ? 2U : 0U) |
                             (st.paper_error ? 4U : 0U) | (st.busy ? 8U : 0U);
        value = static_cast<std::uint8_t>(value | (nib << (4 * half)));
        ctl_.n_auto_fd = true;
        TACTUS_TRY_VOID(lines_->write_control(ctl_));
        TACTUS_TRY(e11, wait_for([](const LptStatus& s) { return s.n_ack; }));
        if (!e11) return fail(ErrorKind::device, "nibble transfer stalled (nAck stuck low)", name_);
    }
    return value;
}

// Back to compatibility mode (events 22-28).
Result<void> LptPort::terminate() {
    ctl_.n_select_in = false;
    ctl_.n_auto_fd = true;
    if (auto r = lines_->write_control(ctl_); !r) return r;
    TACTUS_TRY(e24, wait_for([](const LptStatus& s) { return !s.n_ack; }));
    ctl_.n_auto_fd = false;
    if (auto r = lines_->write_control(ctl_); !r) return r;
    TACTUS_TRY(e27, wait_for([](const LptStatus& s) { return s.n_ack; }));
    ctl_.n_auto_fd = true;
    if (auto r = lines_->write_control(ctl_); !r) return r;
    if (!e24 || !e27) return fail(ErrorKind::device, "IEEE 1284 termination did not complete", name_);
    return {};
}

Result<std::size_t> LptPort::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    if (!lines_) return fail(ErrorKind::device, "device not open", name_);
    const double deadline = now() + std::chrono::duration<double>(timeout).count();
    for (;;) {
        TACTUS_TRY(avail, negotiate_nibble());
        std::size_t n = 0;
        bool more = avail;
        while (more && n < buffer.size()) {
            TACTUS_TRY(b, read_nibble_byte());
            buffer[n++] = b;
            TACTUS_TRY(st, lines_->read_status());
            more = !st.n_fault;
        }
        TACTUS_TRY_VOID(terminate());
        if (n > 0) return n;
        if (now() >= deadline) return std::size_t{0};
        // Nothing yet: poll again shortly (the 8051 answers within a frame time).
        lines_->settle();
        sleep(timings_.poll_interval);
    }
}

Result<LptPort::Condition> LptPort::condition() {
    if (!lines_) return fail(ErrorKind::device, "device not open", name_);
    TACTUS_TRY(st, lines_->read_status());
    return Condition{st.paper_error, !st.n_fault, st.select};
}

}  // namespace tactus::transport
