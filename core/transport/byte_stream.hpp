// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One byte-stream interface for every cable: serial, pty, HID-UART bridge, LPT
// and the in-process simulator. The link only ever sees this.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "common/result.hpp"

namespace tactus::transport {

class ByteStream {
public:
    virtual ~ByteStream() = default;
    ByteStream() = default;
    ByteStream(const ByteStream&) = delete;
    ByteStream& operator=(const ByteStream&) = delete;

    // Writes all bytes (may block for flow control). An error means the device is gone.
    virtual Result<void> write(std::span<const std::uint8_t> bytes) = 0;
    // Reads what is available, waiting at most `timeout` for the first byte.
    // Returns 0 on timeout; an error means the device is gone.
    virtual Result<std::size_t> read(std::span<std::uint8_t> buffer,
                                     std::chrono::microseconds timeout) = 0;
    // Closes and opens the same device again (after an unplug).
    virtual Result<void> reopen() = 0;
    // Seconds on this stream's clock: monotonic wall time for real devices,
    // simulated time for the in-process simulator (which runs faster than real time).
    [[nodiscard]] virtual double now() const;
    // Waits on this stream's clock (reconnect back-off, pacing): the simulator
    // runs its controller meanwhile instead of sleeping.
    virtual void sleep(std::chrono::microseconds duration);
    // Line rate in bytes per second (start and stop bits included), 0 if unknown.
    [[nodiscard]] virtual double bytes_per_second() const { return 0; }
    [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace tactus::transport
