// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the operating system said when a call failed: its own words (strerror,
// FormatMessage) and the few kinds callers react to. The stages above turn it
// into an Error (common/result.hpp) with their own wording and location.
#include <cstdint>
#include <expected>
#include <string>

namespace tactus::platform {

enum class OsErrorKind : std::uint8_t {
    other,
    not_found,     // no such file or device
    permission,    // access denied
    busy,          // in use by another program (or a lock held elsewhere)
    unsupported,   // this system has no way to do it
};

struct OsError {
    std::string what;  // the system's words, or a sentence for a check made here
    OsErrorKind kind = OsErrorKind::other;
};

template <typename T>
using OsResult = std::expected<T, OsError>;

// The error of the call that just failed (errno on POSIX, GetLastError on Windows).
OsError last_error();

inline std::unexpected<OsError> os_fail(std::string what, OsErrorKind kind = OsErrorKind::other) {
    return std::unexpected<OsError>(OsError{std::move(what), kind});
}

}  // namespace tactus::platform
