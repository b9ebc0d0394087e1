// SPDX-License-Identifier: GPL-3.0-or-later
#include "ipp/remote_queues.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "ipp/queue_uri.hpp"
#include "ipp_connection.hpp"
#include "common/try.hpp"

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

std::string server_of(const std::string& host, int port) {
    return uri_host(host) + ":" + std::to_string(port);
}

std::string queue_uri(const std::string& host, int port, const std::string& name) {
    return "ipp://" + server_of(host, port) + "/printers/" + name;
}

// printer-state (an IPP enum) and printer-state-message, as RemoteQueue::state says them.
std::string state_text(int state, const std::string& message) {
    std::string out = state == IPP_PSTATE_PROCESSING ? "processing"
                      : state == IPP_PSTATE_STOPPED  ? "stopped"
                                                     : "idle";
    if (!message.empty()) out += ": " + message;
    return out;
}

// What the printer picker needs of a libcups destination, if it is a Tactus
// queue. A queue of the default server is reached at that server; one found by
// DNS-SD (device-uri dnssd://...) at the address libcups resolves for it.
std::optional<RemoteQueue> from_dest(cups_dest_t* dest, const std::string& host, int port) {
    const auto option = [dest](const char* name) {
        const char* v = cupsGetOption(name, dest->num_options, dest->options);
        return std::string(v ? v : "");
    };
    if (dest->instance) return std::nullopt;  // an lpoptions instance: the same queue again
    const auto device = option("device-uri");
    RemoteQueue q;
    q.name = dest->name;
    q.make_and_model = option("printer-make-and-model");
    if (!is_tactus_queue(device, q.make_and_model)) return std::nullopt;
    if (device.starts_with("dnssd://")) {
        // cupsConnectDest resolves the service and records its address.
        char resource[1024];
        http_t* http = cupsConnectDest(dest, CUPS_DEST_FLAGS_NONE, 5000, nullptr, resource,
                                       sizeof resource, nullptr, nullptr);
        if (http) httpClose(http);
        q.uri = option("printer-uri-supported");
        auto parsed = parse_queue_uri(q.uri);
        if (!parsed) return std::nullopt;  // not resolved, or no CUPS queue behind it
        q.server = server_of(parsed->host, parsed->port);
    } else {
        q.uri = queue_uri(host, port, q.name);
        q.server = server_of(host, port);
    }
    q.info = option("printer-info");
    q.location = option("printer-location");
    q.state = state_text(std::atoi(option("printer-state").c_str()), {});
    q.accepting = option("printer-is-accepting-jobs") != "false";
    return q;
}

}  // namespace

bool is_tactus_queue(std::string_view device_uri, std::string_view make_and_model) {
    return device_uri.starts_with("tactus:") ||
           make_and_model.starts_with("Tactus Braille Embosser");
}

Result<std::vector<RemoteQueue>> tactus_queues(const std::string& host, int port) {
    TACTUS_TRY(http, detail::connect(host, port, false));
    ipp_t* req = ippNewRequest(IPP_OP_CUPS_GET_PRINTERS);
    static const char* const wanted[] = {
        "printer-name", "printer-info",  "printer-location",      "printer-make-and-model",
        "device-uri",   "printer-state", "printer-state-message", "printer-is-accepting-jobs"};
    ippAddStrings(req, IPP_TAG_OPERATION, IPP_TAG_KEYWORD, "requested-attributes",
                  static_cast<int>(std::size(wanted)), nullptr, wanted);
    ippAddString(req, IPP_TAG_OPERATION, IPP_TAG_NAME, "requesting-user-name", nullptr, cupsUser());
    auto response = detail::call(http.get(), req, "/", "list the queues of " + host);
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
            q.uri = queue_uri(host, port, q.name);
            q.server = server_of(host, port);
            q.info = text(group, "printer-info");
            q.location = text(group, "printer-location");
            ipp_attribute_t* st = ippFindAttribute(group, "printer-state", IPP_TAG_ENUM);
            q.state = state_text(st ? ippGetInteger(st, 0) : IPP_PSTATE_IDLE,
                                 text(group, "printer-state-message"));
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

Result<std::vector<RemoteQueue>> visible_tactus_queues(std::chrono::milliseconds browse) {
    // The default server as libcups sees it (CUPS_SERVER, client.conf, else the
    // local cupsd's socket, which a URI reaches as localhost).
    std::string host = cupsServer();
    const int port = ippPort();
    if (host.empty() || host.starts_with('/')) host = "localhost";
    struct Found {
        std::string host;
        int port;
        std::vector<cups_dest_t*> dests;
    } found{host, port, {}};
    cupsEnumDests(
        CUPS_DEST_FLAGS_NONE, static_cast<int>(browse.count()), nullptr, 0, 0,
        [](void* data, unsigned flags, cups_dest_t* dest) -> int {
            auto* f = static_cast<Found*>(data);
            if (flags & CUPS_DEST_FLAGS_REMOVED) return 1;
            cups_dest_t* copy = nullptr;
            cupsCopyDest(dest, 0, &copy);
            if (copy) f->dests.push_back(copy);
            return 1;
        },
        &found);
    std::vector<RemoteQueue> out;
    for (cups_dest_t* d : found.dests) {
        if (auto q = from_dest(d, host, port)) out.push_back(std::move(*q));
        cupsFreeDests(1, d);
    }
    // cupsEnumDests's own answer says little (0 when DNS-SD is not there,
    // 1 when no server is): no destination and an IPP error mean no server
    // answered (a server without printers answers not-found).
    const auto status = cupsLastError();
    if (out.empty() && found.dests.empty() && status > IPP_STATUS_OK_EVENTS_COMPLETE &&
        status != IPP_STATUS_ERROR_NOT_FOUND)
        return fail(ErrorKind::device, cupsLastErrorString(), server_of(host, port));
    std::ranges::sort(out, {}, &RemoteQueue::uri);
    out.erase(std::ranges::unique(out, {}, &RemoteQueue::uri).begin(), out.end());
    return out;
}

}  // namespace tactus::ipp
