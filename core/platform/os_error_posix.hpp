// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Inside the POSIX implementations only: an errno value as an OsError.
#include "platform/os_error.hpp"

namespace tactus::platform {

OsError os_error_from_errno(int err);

}  // namespace tactus::platform
