// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A build may leave a third-party library out (the Windows build made on Linux
// does, and any build configured with a TACTUS_WITH_* option off:
// docs/windows.md). What needs it then refuses with one wording, naming the
// feature and the library, as a usage error (exit code 2 in the CLI). The
// wording names no system: the same options can be off on Linux.
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus {

[[nodiscard]] inline std::string unavailable_message(std::string_view feature, std::string_view library) {
    return std::string(feature) + " is not available in this build (it was built without " +
           std::string(library) + ")";
}

[[nodiscard]] inline std::unexpected<Error> unavailable(std::string_view feature, std::string_view library,
                                                        std::string where = {}) {
    return fail(ErrorKind::usage, unavailable_message(feature, library), std::move(where));
}

}  // namespace tactus
