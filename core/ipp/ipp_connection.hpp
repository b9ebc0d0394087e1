// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Inside the ipp stage only (it includes libcups): one HTTP connection to a
// CUPS server and one IPP request over it, with libcups's errors as values.
#include <cups/cups.h>

#include <memory>
#include <string>

#include "common/result.hpp"

namespace tactus::ipp::detail {

struct HttpClose {
    void operator()(http_t* h) const { httpClose(h); }
};
struct IppDelete {
    void operator()(ipp_t* i) const { ippDelete(i); }
};
using Http = std::unique_ptr<http_t, HttpClose>;
using Ipp = std::unique_ptr<ipp_t, IppDelete>;

// Connects (30 s at most); a server that is not there is a device error
// naming host and port.
Result<Http> connect(const std::string& host, int port, bool tls);

// Sends `request` (consumed) to `resource`, with `file` as the document when
// not empty; an IPP error status becomes an error with the server's words.
// `what` names the operation in the message ("send the job"). `transient`,
// when given, says whether the server was not reached or not ready (worth
// asking again: cupsd restarting) rather than refusing the request.
Result<Ipp> call(http_t* http, ipp_t* request, const std::string& resource, const std::string& what,
                 const std::string& file = {}, bool* transient = nullptr);

}  // namespace tactus::ipp::detail
