// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A CUPS queue's address: ipp://host[:port]/printers/NAME (ipps:// for TLS).
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus::ipp {

struct QueueUri {
    std::string uri;  // as given, for printer-uri and messages
    std::string host;
    int port = 631;
    std::string resource;  // "/printers/Embosser"
    bool tls = false;      // ipps
};

// True for the ipp:// and ipps:// schemes (a device string of another kind
// goes to the transports instead).
[[nodiscard]] bool is_queue_uri(std::string_view device);

// A usage error says what is wrong with the address.
Result<QueueUri> parse_queue_uri(std::string_view uri);

}  // namespace tactus::ipp
