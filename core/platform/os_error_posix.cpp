// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/os_error.hpp"

#include <cerrno>
#include <cstring>

#include "platform/os_error_posix.hpp"

namespace tactus::platform {

OsError os_error_from_errno(int err) {
    OsErrorKind kind = OsErrorKind::other;
    switch (err) {
        case ENOENT:
        case ENXIO:
        case ENODEV: kind = OsErrorKind::not_found; break;
        case EACCES:
        case EPERM: kind = OsErrorKind::permission; break;
        case EBUSY:
        case EWOULDBLOCK: kind = OsErrorKind::busy; break;
        case ENOSYS: kind = OsErrorKind::unsupported; break;
        default: break;
    }
    return OsError{std::strerror(err), kind};
}

OsError last_error() { return os_error_from_errno(errno); }

}  // namespace tactus::platform
