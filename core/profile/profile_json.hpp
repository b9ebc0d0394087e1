// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Printer profiles as JSON files. Reading is strict: every field of the schema
// must be present (except the optional two-inertia dynamics), unknown fields are
// refused (they are usually typos), and the values are validated; errors name the
// field, e.g. "field carriage.steps_per_mm: must be above 0".
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/result.hpp"
#include "profile/profile.hpp"

namespace tactus::profile {

nlohmann::json to_json(const PrinterProfile& p);
Result<PrinterProfile> from_json(const nlohmann::json& j);
Result<PrinterProfile> parse_profile(std::string_view text);
Result<PrinterProfile> load_profile(const std::filesystem::path& path);
// Validates, then writes atomically (a crash leaves the old file or the new one).
Result<void> save_profile(const PrinterProfile& p, const std::filesystem::path& path);

// Every physical and geometric constraint the planner relies on.
Result<void> validate(const PrinterProfile& p);

}  // namespace tactus::profile
