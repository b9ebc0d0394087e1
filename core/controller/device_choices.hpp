// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The embossers a user can pick: the built-in simulator first, then serial
// ports with their USB descriptions, HID UART bridges and parallel ports.
// Enumeration problems are reported, not fatal. (Any other device string, such
// as a pty, can still be typed: transport::check_device validates it.)
#include <string>
#include <vector>

namespace tactus::controller {

struct DeviceChoice {
    std::string device;       // the device string ("sim", "serial:/dev/ttyUSB0", ...)
    std::string kind;         // sim, usb-serial, native, hid-uart, lpt
    std::string description;  // what the user reads: "CP2102 USB to UART (Silicon Labs)"
};

std::vector<DeviceChoice> list_devices(std::vector<std::string>* problems = nullptr);

}  // namespace tactus::controller
