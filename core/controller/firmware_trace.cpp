// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/firmware_trace.hpp"

#include <charconv>

#include "machine/firmware_tables.hpp"
#include "machine/limits.hpp"

namespace tactus::controller {
namespace {

// Port 1 bits (firmware/src/board.h).
constexpr std::uint32_t kCarriageStep = 0x01, kCarriageDir = 0x02, kFeedStep = 0x04, kFeedDir = 0x08,
                        kConvex = 0x10, kConcave = 0x20, kMotorEnable = 0x40;

std::vector<std::string_view> words(std::string_view l) {
    std::vector<std::string_view> w;
    std::size_t i = 0;
    while (i < l.size()) {
        while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
        const std::size_t b = i;
        while (i < l.size() && l[i] != ' ' && l[i] != '\t') ++i;
        if (i > b) w.push_back(l.substr(b, i - b));
    }
    return w;
}

double unit_seconds(std::string_view u) {
    if (u == "s") return 1;
    if (u == "ms") return 1e-3;
    if (u == "us") return 1e-6;
    if (u == "ns") return 1e-9;
    if (u == "ps") return 1e-12;
    if (u == "fs") return 1e-15;
    return 0;
}

}  // namespace

Result<void> FirmwareTrace::push(std::string_view text, std::vector<LoggedStrike>& out) {
    pending_.append(text);
    std::size_t start = 0;
    for (std::size_t nl; (nl = pending_.find('\n', start)) != std::string::npos; start = nl + 1)
        line(std::string_view(pending_).substr(start, nl - start), out);
    pending_.erase(0, start);
    if (!in_header_ && port_id_.empty())
        return fail(ErrorKind::input, "the pin trace has no port 1 (set hw vcd[0] add port_1_cfg 2)", "VCD");
    return {};
}

void FirmwareTrace::line(std::string_view l, std::vector<LoggedStrike>& out) {
    const auto w = words(l);
    if (w.empty()) return;
    if (w[0] == "$timescale" && w.size() >= 2) {
        // "$timescale 1ps $end": a number and a unit.
        const auto ts = w[1];
        std::size_t digits = 0;
        while (digits < ts.size() && ts[digits] >= '0' && ts[digits] <= '9') ++digits;
        double n = 1;
        if (digits > 0) std::from_chars(ts.data(), ts.data() + digits, n);
        tick_s_ = n * unit_seconds(ts.substr(digits));
    } else if (w[0] == "$var" && w.size() >= 5) {
        const std::string id(w[3]);
        if (w[4] == "port1_value") port_id_ = id;
        // s51 names a traced RAM cell after its address; run_firmware_emulator
        // traces _fw_sheet's two bytes, lowest address first (SDCC stores little-endian).
        if (w[4].starts_with("iram_")) (sheet_lo_id_.empty() ? sheet_lo_id_ : sheet_hi_id_) = id;
    } else if (w[0] == "$enddefinitions") {
        in_header_ = false;
    } else if (w[0][0] == '#') {
        std::uint64_t t = 0;
        std::from_chars(w[0].data() + 1, w[0].data() + w[0].size(), t);
        // The timer event behind whatever changes at this time: every step
        // and hammer edge comes kPinEdgeTicks after its event.
        now_s_ = static_cast<double>(t) * tick_s_ - machine::kPinEdgeTicks / machine::kTickHz;
    } else if (w[0][0] == 'b' && w.size() >= 2) {
        std::uint32_t v = 0;
        bool known = true;
        for (const char c : w[0].substr(1)) {
            if (c != '0' && c != '1') known = false;
            v = (v << 1) | (c == '1' ? 1U : 0U);
        }
        if (known) change(std::string(w[1]), v, out);
    }
}

void FirmwareTrace::change(const std::string& id, std::uint32_t v, std::vector<LoggedStrike>& out) {
    if (id == sheet_lo_id_ || id == sheet_hi_id_) {
        const std::uint16_t before = sheet_;
        sheet_ = id == sheet_lo_id_ ? static_cast<std::uint16_t>((sheet_ & 0xFF00) | (v & 0xFF))
                                    : static_cast<std::uint16_t>((sheet_ & 0x00FF) | ((v & 0xFF) << 8));
        if (before == 0 && sheet_ != 0) feed_ = 0;  // SHEET_BEGIN: the sheet's top edge is the origin
        return;
    }
    if (id != port_id_) return;
    const std::uint32_t rise = v & ~port_;
    const std::uint32_t fall = port_ & ~v;
    // The stepper drivers step only while enabled (P1.6 low): a reset sets
    // every port pin high, drivers disabled, and those edges move nothing.
    const bool enabled = (v & kMotorEnable) == 0;
    if (enabled && (rise & kCarriageStep)) carriage_ += (v & kCarriageDir) ? 1 : -1;
    if (enabled && (rise & kFeedStep)) feed_ += (v & kFeedDir) ? 1 : -1;
    if (keep_edges_) {
        using K = PinEdge::Kind;
        if (enabled && (rise & kCarriageStep)) edges_.push_back({K::carriage_step, now_s_});
        if (enabled && (rise & kFeedStep)) edges_.push_back({K::feed_step, now_s_});
        if (rise & (kConvex | kConcave)) edges_.push_back({K::hammer_down, now_s_});
        // Not the pins' first value (0xFF before the firmware sets them up).
        if ((fall & (kConvex | kConcave)) && port_ != 0xFF) edges_.push_back({K::hammer_up, now_s_});
    }
    int k = 0;
    for (const auto& [bit, hammer] : {std::pair{kConvex, plan::Hammer::convex}, std::pair{kConcave, plan::Hammer::concave}}) {
        auto& pending = hammer_on_[k++];
        // A strike is a pulse long enough to move the hammer: the reset's
        // glitch (every pin high for the microseconds before main sets
        // port 1) drives the solenoids too briefly to emboss.
        if ((fall & bit) && pending) {
            if (now_s_ - pending->time_s >= kMinHammerPulseS) out.push_back(*pending);
            pending.reset();
        }
        if (!(rise & bit)) continue;
        LoggedStrike s;
        s.sheet = sheet_;
        s.hammer = hammer;
        s.side = hammer == plan::Hammer::convex ? plan::Side::front : plan::Side::back;
        s.carriage_step = carriage_;
        s.feed_step = feed_;
        s.time_s = now_s_;
        s.x_mm = carriage_ / carriage_spm_;
        s.y_mm = feed_ / feed_spm_;
        pending = s;
    }
    port_ = v;
}

}  // namespace tactus::controller
