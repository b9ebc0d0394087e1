// SPDX-License-Identifier: GPL-3.0-or-later
#include "cups_uri.hpp"

#include <cctype>

#include "transport/device.hpp"

namespace tactus::cups {
namespace {

// Characters a device string may carry in a URI as they are (RFC 3986
// unreserved, plus the delimiters device strings use).
bool keep(unsigned char c) {
    return std::isalnum(c) || std::string_view("-._~:/?&=,+@").find(static_cast<char>(c)) != std::string_view::npos;
}

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::string uri_from_device(std::string_view device) {
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string out(kUriScheme);
    out += ':';
    for (const char ch : device) {
        const auto c = static_cast<unsigned char>(ch);
        if (keep(c)) {
            out += ch;
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

Result<std::string> device_from_uri(std::string_view uri) {
    const std::string prefix = std::string(kUriScheme) + ":";
    if (uri.substr(0, prefix.size()) != prefix)
        return fail(ErrorKind::usage, "not a " + prefix + " URI (expected e.g. tactus:serial:/dev/ttyUSB0)", std::string(uri));
    const auto rest = uri.substr(prefix.size());
    if (rest.starts_with("//"))
        return fail(ErrorKind::usage, "write the device string right after \"tactus:\" (e.g. tactus:serial:/dev/ttyUSB0), without \"//\"",
                    std::string(uri));
    std::string device;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] != '%') {
            device += rest[i];
            continue;
        }
        const bool whole = i + 2 < rest.size();
        const int hi = whole ? hex_value(rest[i + 1]) : -1;
        const int lo = whole ? hex_value(rest[i + 2]) : -1;
        if (hi < 0 || lo < 0)
            return fail(ErrorKind::usage, "bad %-escape at character " + std::to_string(prefix.size() + i + 1) +
                            " (a % must be followed by two hex digits)",
                        std::string(uri));
        device += static_cast<char>(hi * 16 + lo);
        i += 2;
    }
    if (device.empty()) return fail(ErrorKind::usage, "the URI names no device (expected e.g. tactus:serial:/dev/ttyUSB0)", std::string(uri));
    if (auto spec = transport::parse_device(device); !spec) return std::unexpected(located(spec.error(), std::string(uri)));
    return device;
}

}  // namespace tactus::cups
