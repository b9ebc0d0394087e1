// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/clock.hpp"

namespace tactus::platform {

std::tm utc_time(std::time_t t) {
    std::tm tm{};
    ::gmtime_r(&t, &tm);
    return tm;
}

std::tm local_time(std::time_t t) {
    std::tm tm{};
    ::localtime_r(&t, &tm);
    return tm;
}

}  // namespace tactus::platform
