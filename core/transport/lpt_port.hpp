// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parallel port: host-to-controller bytes in compatibility (Centronics) mode
// with the nStrobe/Busy/nAck handshake, controller-to-host frames in IEEE 1284
// nibble mode over the status lines, and the controller's condition on those
// lines between transfers (PError = paper out, nFault = fault, Select = online).
// ParallelPortLines is the cable as the host drives it: libieee1284 for the
// real port, the simulated controller's peripheral side in tests.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "transport/byte_stream.hpp"
#include "transport/device.hpp"
#include "transport/serial_port.hpp"

namespace tactus::transport {

// Control lines as driven by the host, at their electrical levels (true = high).
struct LptControl {
    bool n_strobe = true;
    bool n_auto_fd = true;
    bool n_init = true;
    bool n_select_in = false;  // low: compatibility mode; high: IEEE 1284 active
    bool operator==(const LptControl&) const = default;
};

// Status lines as driven by the peripheral, at their electrical levels.
struct LptStatus {
    bool n_ack = true;
    bool busy = false;
    bool paper_error = false;
    bool select = true;
    bool n_fault = true;
    bool operator==(const LptStatus&) const = default;
};

class ParallelPortLines {
public:
    virtual ~ParallelPortLines() = default;
    virtual Result<void> write_data(std::uint8_t value) = 0;
    virtual Result<void> write_control(const LptControl& lines) = 0;
    virtual Result<LptStatus> read_status() = 0;
    // Lets the lines settle (the 1284 minimum setup/hold time; a test cable
    // lets its peripheral react).
    virtual void settle() = 0;
    // The peripheral's own clock in seconds, when it has one: an emulated
    // chip's simulated time, which runs only as the cable lets it. The port
    // then times its handshakes and the link its timeouts on it (ByteStream::now).
    [[nodiscard]] virtual std::optional<double> clock() const { return std::nullopt; }
    // Lets a peripheral with its own clock run this long on it while the host
    // waits (ByteStream::sleep); false: it has none, the host sleeps.
    virtual bool run_for(std::chrono::microseconds) { return false; }
};

struct LptTimings {
    std::chrono::microseconds handshake{200000};  // a peripheral that does not answer in time
    // Between two nibble-mode polls that found no reply. An emulated chip
    // runs this long between them, so it is also how far its motion gets per poll.
    std::chrono::microseconds poll_interval{500};
};

class LptPort final : public ByteStream {
public:
    using Opener = std::function<Result<std::unique_ptr<ParallelPortLines>>()>;
    static Result<std::unique_ptr<LptPort>> open(Opener opener, std::string name,
                                                 LptTimings timings = {});

    Result<void> write(std::span<const std::uint8_t> bytes) override;
    Result<std::size_t> read(std::span<std::uint8_t> buffer,
                             std::chrono::microseconds timeout) override;
    Result<void> reopen() override;
    // Centronics is byte-paced by the peripheral: no fixed line rate.
    [[nodiscard]] std::string describe() const override { return name_; }
    // The peripheral's clock when the cable has one (ParallelPortLines::clock).
    [[nodiscard]] double now() const override;
    void sleep(std::chrono::microseconds duration) override;

    // The controller's condition, read from the status lines in compatibility mode.
    struct Condition {
        bool paper_out = false;
        bool fault = false;
        bool online = false;
    };
    Result<Condition> condition();

private:
    LptPort(Opener opener, std::string name, LptTimings t)
        : opener_(std::move(opener)), name_(std::move(name)), timings_(t) {}
    Result<void> write_byte(std::uint8_t b);
    Result<bool> wait_for(const std::function<bool(const LptStatus&)>& ok);
    Result<bool> negotiate_nibble();
    Result<std::uint8_t> read_nibble_byte();
    Result<void> terminate();
    Opener opener_;
    std::string name_;
    LptTimings timings_;
    std::unique_ptr<ParallelPortLines> lines_;
    LptControl ctl_;
};

// lpt:/dev/parport0 (or lpt:parport0) through libieee1284; lpt:NAME?... a
// cable registered under NAME (register_lpt_cable).
Result<std::unique_ptr<ByteStream>> open_lpt(const DeviceSpec& spec);

// A cable that is not a port of this machine, opened by the program that
// knows it: `lpt:emu?fw=...`, the firmware's pins in the s51 emulator, which
// tactus-cli registers (core runs no emulator). The factory reads the
// device string's options; its timings are the port's.
struct LptCable {
    std::function<Result<std::unique_ptr<ParallelPortLines>>(const DeviceSpec&)> open;
    LptTimings timings;
};
void register_lpt_cable(const std::string& name, LptCable cable);
// The registered cable named by `spec.path`, if any.
const LptCable* registered_lpt_cable(const DeviceSpec& spec);
Result<std::vector<PortInfo>> list_parallel_ports();

}  // namespace tactus::transport
