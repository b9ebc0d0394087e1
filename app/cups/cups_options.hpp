// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The options argument CUPS gives filters and backends (argv[5]), parsed by
// libcups itself so quoting and "noname" booleans mean what CUPS means.
#include <string_view>

#include "job_options.hpp"

namespace tactus::cups {

CupsOptions parse_cups_options(std::string_view argument);

}  // namespace tactus::cups
