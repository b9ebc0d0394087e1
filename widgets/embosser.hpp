// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer side of the app without Qt: which devices there are, a connection
// to one (always including the in-process simulator, whose strike log lets the
// app check what was embossed), and one job run over core's link with progress,
// pause, cancel and resume-from-sheet. Faults come back in plain words with what
// to do about them.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "link/link.hpp"
#include "plan/plan.hpp"
#include "profile/profile.hpp"

namespace tactus::controller {
class SimController;
}

namespace tactus::gui {

struct DeviceChoice {
    std::string device;       // the device string Link::open takes ("sim", "serial:/dev/ttyUSB0", ...)
    std::string kind;         // sim, usb-serial, native, hid-uart, lpt
    std::string description;  // what the user reads: "CP2102 USB to UART (Silicon Labs)"
};

// The simulator first, then serial ports with their USB descriptions, HID bridges
// and parallel ports. Enumeration problems are reported, not fatal.
std::vector<DeviceChoice> list_devices(std::vector<std::string>* problems = nullptr);

// A fault or status flag, in words, with what to do.
std::string explain_faults(std::uint8_t fault_flags);
std::string explain_status(const encode::Status& s);

class Embosser {
public:
    // Opens the device and starts a session. "sim" is the built-in simulator.
    static Result<Embosser> connect(const std::string& device, const profile::PrinterProfile& p);
    Embosser(Embosser&&) noexcept;
    Embosser& operator=(Embosser&&) noexcept;
    ~Embosser();

    [[nodiscard]] const std::string& device() const { return device_; }
    Result<encode::Status> status();
    link::Link& link() { return *link_; }
    // The simulator's controller (for checking the strikes), or null on real hardware.
    [[nodiscard]] controller::SimController* simulator() const { return sim_.get(); }
    // Makes the simulated cable fail from now on for `seconds` (tests of an
    // embosser disappearing mid-job).
    void simulate_unplug_after(double after_s, double seconds);

private:
    Embosser() = default;
    std::string device_;
    std::shared_ptr<controller::SimController> sim_;
    void* sim_transport_ = nullptr;  // the SimTransport inside link_, when simulated
    std::unique_ptr<link::Link> link_;
};

}  // namespace tactus::gui
