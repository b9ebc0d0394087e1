// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Tactus queues a CUPS server offers, for the printer picker beside the
// local cables: CUPS-Get-Printers, kept when the queue runs the Tactus
// backend (device-uri tactus:...) or was made from the Tactus PPD
// (printer-make-and-model, for servers that hide device-uri from clients).
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"

namespace tactus::ipp {

struct RemoteQueue {
    std::string uri;             // ipp://host:port/printers/NAME: what `--device` takes
    std::string name;            // printer-name
    std::string info;            // printer-info: what the administrator called it
    std::string location;        // printer-location
    std::string make_and_model;  // printer-make-and-model
    std::string state;           // idle, processing or stopped, with printer-state-message
    bool accepting = true;       // printer-is-accepting-jobs
    std::string server;          // host:port of the CUPS server that offers it (for labels)
};

// "tactus:..." device or the PPD's model name: the one test of "a Tactus queue".
[[nodiscard]] bool is_tactus_queue(std::string_view device_uri, std::string_view make_and_model);

// The Tactus queues of the server at host:port, by name. A server that is not
// there is a device error.
Result<std::vector<RemoteQueue>> tactus_queues(const std::string& host, int port = 631);

// The Tactus queues this machine sees through libcups's destinations
// (cupsEnumDests): the queues of its CUPS server (the local cupsd, or the one
// CUPS_SERVER or client.conf names), and shared queues found on the network
// by DNS-SD within `browse`. Blocks for up to `browse` and the server's
// answer: call it off the GUI thread. No server at all is a device error whose
// `where` is the server asked and whose message is CUPS's own reason; what
// failed (listing the queues) is the caller's to say, in its own language.
Result<std::vector<RemoteQueue>> visible_tactus_queues(
    std::chrono::milliseconds browse = std::chrono::milliseconds(1500));

}  // namespace tactus::ipp
