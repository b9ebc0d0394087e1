// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes plan files (`tactus-cli emboss --plan`): any text is a plan or an
// error naming the field, never an abort (a side given as a number once
// aborted the process). A plan that loads saves and loads back to itself.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <nlohmann/json.hpp>

#include "plan/plan_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) return 0;
    auto p = plan::plan_from_json(j);
    if (!p) return 0;
    auto again = plan::plan_from_json(plan::plan_to_json(*p));
    if (!again || again->plan.sheets.size() != p->plan.sheets.size() || again->plan.strikes != p->plan.strikes ||
        again->protocol != p->protocol)
        std::abort();
    return 0;
}
