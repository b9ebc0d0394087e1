// SPDX-License-Identifier: GPL-3.0-or-later
#include "ipp/remote_queues.hpp"

#include <algorithm>

#include "ipp_connection.hpp"

namespace tactus::ipp {
namespace {

std::string text(ipp_t* printer, const char* name) {
    ipp_attribute_t* a = ippFindAttribute(printer, name, IPP_TAG_ZERO);
    const char* v = a ? ippGetString(a, 0, nullptr) : nullptr;
    return v ? v : "";
}

// The host as a URI writes it (an IPv6 address in brackets).
std::string uri_host(const std::string& host) {
    return host.find(':') != std::string::npos && !host.starts_with('[') ? "[" + host + "]" : host;
}

}  // namespace

bool is_tactus_queue(std::string_view device_uri, std::string_view make_and_model) {
    return device_uri.starts_with("tactus:") ||
           make_and_model.starts_with("Tactus Braille Embosser");
}

Result<std::vector<RemoteQueue>> tactus_queues(const std::string& host, int port) {
    auto http = detail::connect(host, port, false);
    if (!http) return std::unexpected(http.error());
    ipp_t* req = ippNewRequest(IPP_OP_CUPS_GET_PRINTERS);
    static const char* const wanted[] = {
        "printer-name", "printer-info",  "printer-location",      "printer-make-and-model",
        "device-uri",   "printer-state", "printer-state-message", "printer-is-accepting-jobs"};
    ippAddStrings(req, IPP_TAG_OPERATION, IPP_TAG_KEYWORD, "requested-attributes",
                  static_cast<int>(std::size(wanted)), nullptr, wanted);
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_NAME, "requesting-user-name", nullptr, cupsUser());
    auto response = detail::call(http->get(), req, "/", "list the queues of " + host);
    if (!response) return std::unexpected(response.error());
    std::vector<RemoteQueue> out;
    // The response is one attribute group per printer, separated by IPP_TAG_ZERO.
    ipp_t* group = ippNew();
    auto flush = [&] {
        const auto device = text(group, "device-uri");
        RemoteQueue q;
        q.name = text(group, "printer-name");
        q.make_and_model = text(group, "printer-make-and-model");
        if (!q.name.empty() && is_tactus_queue(device, q.make_and_model)) {
            q.uri = "ipp://" + uri_host(host) + ":" + std::to_string(port) + "/printers/" + q.name;
            q.info = text(group, "printer-info");
            q.location = text(group, "printer-location");
            ipp_attribute_t* st = ippFindAttribute(group, "printer-state", IPP_TAG_ENUM);
            const int state = st ? ippGetInteger(st, 0) : IPP_PSTATE_IDLE;
            q.state = state == IPP_PSTATE_PROCESSING ? "processing"
                      : state == IPP_PSTATE_STOPPED  ? "stopped"
                                                     : "idle";
            if (const auto m = text(group, "printer-state-message"); !m.empty())
                q.state += ": " + m;
            ipp_attribute_t* acc =
                ippFindAttribute(group, "printer-is-accepting-jobs", IPP_TAG_BOOLEAN);
            q.accepting = !acc || ippGetBoolean(acc, 0) != 0;
            out.push_back(std::move(q));
        }
        ippDelete(group);
        group = ippNew();
    };
    for (ipp_attribute_t* a = ippFirstAttribute(response->get()); a;
         a = ippNextAttribute(response->get())) {
        if (ippGetGroupTag(a) != IPP_TAG_PRINTER) {
            if (ippGetName(a) == nullptr) flush();  // the separator between printers
            continue;
        }
        ippCopyAttribute(group, a, 0);
    }
    flush();
    ippDelete(group);
    std::ranges::sort(out, {}, &RemoteQueue::name);
    return out;
}

}  // namespace tactus::ipp
