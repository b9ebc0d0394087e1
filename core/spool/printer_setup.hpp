// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A newcomer's printer: the spool printer for a device string, set up on first
// use and named after the device, so `emboss --queue --device X` and the app's
// Ctrl+P on X work on a fresh machine and find the same printer later.
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "spool/records.hpp"
#include "spool/spool.hpp"

namespace tactus::spool {

// "serial:/dev/ttyUSB0?baud=9600" -> "ttyUSB0", "pty:/dev/pts/3" -> "pts-3",
// "hid:10c4:ea80" -> "hid-10c4-ea80", "sim" -> "sim".
std::string printer_name_for_device(std::string_view device);

// The first printer whose device string is `device`; else a new one with
// `profile_json`, named after the device ("-2", "-3", ... when the name is
// taken). `created` tells which. The device string is checked (Spool::add_printer).
Result<PrinterRecord> printer_for_device(Spool& spool, std::string_view device, std::string_view profile_json,
                                         bool* created = nullptr);

}  // namespace tactus::spool
