// SPDX-License-Identifier: GPL-3.0-or-later
#include "cups_options.hpp"

#include <cups/cups.h>

#include <string>

namespace tactus::cups {

CupsOptions parse_cups_options(std::string_view argument) {
    const std::string arg(argument);
    cups_option_t* parsed = nullptr;
    const int n = cupsParseOptions(arg.c_str(), 0, &parsed);
    CupsOptions out;
    for (int i = 0; i < n; ++i) out[parsed[i].name] = parsed[i].value ? parsed[i].value : "";
    cupsFreeOptions(n, parsed);
    return out;
}

}  // namespace tactus::cups
