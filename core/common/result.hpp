// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Errors are values in core: every fallible stage returns Result<T>. The message
// says what went wrong; `where` says where (file:line, byte offset, field name)
// so the CLI can print "where: what" and the GUI can point at it.
#include <expected>
#include <string>
#include <utility>

namespace tactus {

struct Error {
    std::string message;  // why, in plain words
    std::string where;    // "file:line", "byte 1234", "field carriage.v_max"; may be empty

    [[nodiscard]] std::string to_string() const {
        return where.empty() ? message : where + ": " + message;
    }
};

template <typename T>
using Result = std::expected<T, Error>;

inline std::unexpected<Error> fail(std::string message, std::string where = {}) {
    return std::unexpected<Error>(Error{std::move(message), std::move(where)});
}

// Prefix the location of an error produced deeper down (e.g. the file name
// around a line number found by a parser).
inline Error located(Error e, const std::string& outer) {
    if (outer.empty()) return e;
    e.where = e.where.empty() ? outer : outer + ":" + e.where;
    return e;
}

}  // namespace tactus
