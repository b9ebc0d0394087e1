// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Errors are values in core: every fallible stage returns Result<T>. The message
// says what went wrong; `where` says where (file:line, byte offset, field name)
// so the CLI can print "where: what" and the GUI can point at it.
#include <cstdint>
#include <expected>
#include <string>
#include <utility>

namespace tactus {

// What kind of thing went wrong, so an edge can react without reading the
// message: the CLI maps kinds to its exit codes in one table, the GUI and the
// spool tell a bad document from a missing embosser.
enum class ErrorKind : std::uint8_t {
    input,     // a file, profile, table, plan or document that is malformed or unreadable
    usage,     // a value the user typed that cannot be used (option, device string, preset)
    device,    // the embosser or its cable: missing, busy, gone, not answering
    io,        // the machine's own storage: cannot write, disk full, no permission
    protocol,  // the controller answered, but not as docs/protocol.md says it must
    internal,  // a bug in Tactus: a broken invariant, never the user's fault
};

[[nodiscard]] constexpr const char* to_string(ErrorKind k) {
    switch (k) {
        case ErrorKind::input: return "input";
        case ErrorKind::usage: return "usage";
        case ErrorKind::device: return "device";
        case ErrorKind::io: return "io";
        case ErrorKind::protocol: return "protocol";
        case ErrorKind::internal: return "internal";
    }
    return "internal";
}

struct Error {
    std::string message;  // why, in plain words
    std::string where;    // "file:line", "byte 1234", "field carriage.v_max"; may be empty
    ErrorKind kind;       // no default: every error says which kind it is

    [[nodiscard]] std::string to_string() const {
        return where.empty() ? message : where + ": " + message;
    }
};

template <typename T>
using Result = std::expected<T, Error>;

inline std::unexpected<Error> fail(ErrorKind kind, std::string message, std::string where = {}) {
    return std::unexpected<Error>(Error{std::move(message), std::move(where), kind});
}

// Prefix the location of an error produced deeper down (e.g. the file name
// around a line number found by a parser).
inline Error located(Error e, const std::string& outer) {
    if (outer.empty()) return e;
    e.where = e.where.empty() ? outer : outer + ":" + e.where;
    return e;
}

}  // namespace tactus
