// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The far end of a simulated serial line (SimTransport): a controller driven
// by the line's clock. Bytes arrive at a time, the controller runs up to a
// time, and says when it next does something by itself. The C++ simulated
// controller (SimController) is one; the reference firmware's own C compiled
// natively (tests/firmware/native_firmware.hpp) is another, so the host's
// link can be run against the firmware's code in virtual time.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tactus::controller {

class LineEnd {
public:
    virtual ~LineEnd() = default;
    LineEnd() = default;
    LineEnd(const LineEnd&) = default;
    LineEnd& operator=(const LineEnd&) = default;
    // Bytes from the host, arriving at simulated time `now` (seconds).
    virtual void receive(std::span<const std::uint8_t> bytes, double now) = 0;
    // Runs the controller up to `now`.
    virtual void advance(double now) = 0;
    // When something next happens on its own (a step, a strike, a reply byte), if anything.
    [[nodiscard]] virtual std::optional<double> next_event() const = 0;
    // Reply bytes produced so far (and clears them).
    virtual std::vector<std::uint8_t> take_output() = 0;
    // A watchdog reset (RAM kept) or a power cycle (RAM lost) at `now`.
    virtual void warm_reset(double now) = 0;
    virtual void power_loss(double now) = 0;
};

}  // namespace tactus::controller
