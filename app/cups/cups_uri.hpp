// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The CUPS device URI of an embosser: "tactus:" followed by the Tactus device
// string (docs/transports.md), percent-encoded where a URI needs it:
//   tactus:serial:/dev/ttyUSB0?baud=57600   tactus:hid:10c4:ea80:0001
//   tactus:pty:/dev/pts/3?baud=230400       tactus:lpt:/dev/parport0
// An opaque URI (no "//") keeps the device string whole, so the rule for what
// a device string means stays in transport::parse_device alone.
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus::cups {

inline constexpr std::string_view kUriScheme = "tactus";

// "serial:/dev/ttyUSB0?baud=57600" -> "tactus:serial:/dev/ttyUSB0?baud=57600".
std::string uri_from_device(std::string_view device);

// The device string a tactus: URI names, checked by the transport's parser.
// Errors say what is wrong with the URI ("not a tactus: URI", a bad %-escape,
// or the device string's own error).
Result<std::string> device_from_uri(std::string_view uri);

}  // namespace tactus::cups
