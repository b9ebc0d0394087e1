// SPDX-License-Identifier: GPL-3.0-or-later
#include "ipp_connection.hpp"

#include <cerrno>
#include <cstring>

namespace tactus::ipp::detail {

Result<Http> connect(const std::string& host, int port, bool tls) {
    const std::string service = std::to_string(port);
    if (http_addrlist_t* addrs = httpAddrGetList(host.c_str(), AF_UNSPEC, service.c_str())) {
        httpAddrFreeList(addrs);
    } else {
        return fail(ErrorKind::device, "no such host", host + ":" + service);
    }
    http_t* h = httpConnect2(host.c_str(), port, nullptr, AF_UNSPEC,
                             tls ? HTTP_ENCRYPTION_ALWAYS : HTTP_ENCRYPTION_IF_REQUESTED, 1, 30000,
                             nullptr);
    if (!h) {
        // httpConnect2 leaves the socket's error in errno (libcups's own last
        // error is not set by a failed connect).
        const int err = errno;
        return fail(ErrorKind::device,
                    "cannot reach the CUPS server: " + std::string(std::strerror(err)),
                    host + ":" + std::to_string(port));
    }
    return Http(h);
}

Result<Ipp> call(http_t* http, ipp_t* request, const std::string& resource, const std::string& what,
                 const std::string& file, bool* transient) {
    // cupsDo*Request take the request and delete it.
    ipp_t* response = file.empty()
                          ? cupsDoRequest(http, request, resource.c_str())
                          : cupsDoFileRequest(http, request, resource.c_str(), file.c_str());
    Ipp owned(response);
    const auto status = cupsLastError();
    if (transient)
        *transient = !owned && (status == IPP_STATUS_ERROR_SERVICE_UNAVAILABLE ||
                                status == IPP_STATUS_ERROR_INTERNAL ||
                                status == IPP_STATUS_ERROR_DEVICE || httpError(http) != 0);
    if (status > IPP_STATUS_OK_EVENTS_COMPLETE) {
        // Not found, not accepting, forbidden, a format it cannot print: the
        // queue or the server refuses (device); a transport failure too.
        const auto kind = status == IPP_STATUS_ERROR_DOCUMENT_FORMAT_NOT_SUPPORTED ||
                                  status == IPP_STATUS_ERROR_ATTRIBUTES_OR_VALUES
                              ? ErrorKind::input
                              : ErrorKind::device;
        return fail(
            kind,
            "cannot " + what + ": " + cupsLastErrorString() + " (" + ippErrorString(status) + ")",
            resource);
    }
    if (!owned)
        return fail(ErrorKind::device, "cannot " + what + ": no answer from the server", resource);
    return owned;
}

}  // namespace tactus::ipp::detail
