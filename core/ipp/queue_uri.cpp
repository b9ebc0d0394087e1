// SPDX-License-Identifier: GPL-3.0-or-later
#include "ipp/queue_uri.hpp"

#if TACTUS_HAVE_IPP
#include <cups/cups.h>
#else
#include "common/unavailable.hpp"
#endif

#include <array>

namespace tactus::ipp {

bool is_queue_uri(std::string_view device) {
    return device.starts_with("ipp://") || device.starts_with("ipps://");
}

Result<QueueUri> parse_queue_uri(std::string_view uri) {
    const std::string text(uri);
    if (!is_queue_uri(text))
        return fail(ErrorKind::usage,
                    "a CUPS queue is ipp://host[:port]/printers/NAME or ipps://...", text);
#if !TACTUS_HAVE_IPP
    return unavailable("sending to a CUPS queue (ipp://)", "libcups", text);
#else
    // libcups splits the URI, with its percent-decoding and default port.
    std::array<char, 32> scheme{};
    std::array<char, 256> userpass{};
    std::array<char, 256> host{};
    std::array<char, 1024> resource{};
    int port = 0;
    const auto status = httpSeparateURI(
        HTTP_URI_CODING_ALL, text.c_str(), scheme.data(), scheme.size(), userpass.data(),
        userpass.size(), host.data(), host.size(), &port, resource.data(), resource.size());
    if (status < HTTP_URI_STATUS_OK || host[0] == '\0')
        return fail(ErrorKind::usage,
                    std::string("not a valid address: ") + httpURIStatusString(status), text);
    const std::string path = resource.data();
    if (!path.starts_with("/printers/") && !path.starts_with("/classes/"))
        return fail(ErrorKind::usage, "the address names no queue: it must end in /printers/NAME",
                    text);
    if (path.find('/', path.find('/', 1) + 1) != std::string::npos || path.back() == '/')
        return fail(ErrorKind::usage, "the address names no queue: it must end in /printers/NAME",
                    text);
    return QueueUri{text, host.data(), port, path, std::string_view(scheme.data()) == "ipps"};
#endif
}

}  // namespace tactus::ipp
