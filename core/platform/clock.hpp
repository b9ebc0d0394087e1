// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A moment as a calendar date and time of day, in UTC or in this machine's
// time zone: gmtime_r/localtime_r on POSIX, gmtime_s/localtime_s on Windows.
#include <ctime>

namespace tactus::platform {

std::tm utc_time(std::time_t t);
std::tm local_time(std::time_t t);

}  // namespace tactus::platform
