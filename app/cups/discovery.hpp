// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Device discovery for CUPS (backend(7), run with no arguments): one line per
// cable `tactus-cli ports` sees,
//   class uri "make and model" "info" "IEEE 1284 device ID" "location"
// The ports are not opened: opening a serial port can reset the board on it,
// and discovery runs whenever someone opens "Add printer".
#include <string>
#include <vector>

#include "transport/serial_port.hpp"

namespace tactus::cups {

// Make and model of every Tactus queue; the PPD's *NickName and
// *1284DeviceID say the same, so CUPS pairs the two when adding a printer.
inline constexpr const char* kMake = "Tactus";
inline constexpr const char* kModel = "Braille Embosser";

// The IEEE 1284 device ID for a port: MFG, MDL, CMD and CLS identify the
// embosser (what the PPD matches); DES and SN tell cables apart.
std::string device_id(const transport::PortInfo& port);

// One discovery line. USB serial adapters and HID bridges are "direct" (CUPS's
// class for USB and parallel), built-in and Bluetooth ports "serial".
std::string discovery_line(const transport::PortInfo& port);

// Every port of every kind the transports list; a lister that fails (no
// hidraw, no parport module) is skipped, its error returned for the log.
std::vector<transport::PortInfo> list_all_ports(std::vector<std::string>& warnings);

}  // namespace tactus::cups
