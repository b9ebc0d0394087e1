// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile/firmware_tables.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "common/file_io.hpp"
#include "machine/limits.hpp"
#include "profile/controller_config.hpp"
#include "common/try.hpp"

namespace tactus::profile {
namespace {

using nlohmann::json;

Result<machine::RampTable> read_table(const json& j, const std::string& name) {
    const auto it = j.find(name);
    if (it == j.end() || !it->is_object()) return fail(ErrorKind::input, "missing", "field " + name);
    machine::RampTable t;
    const auto iv = it->find("intervals");
    if (iv == it->end() || !iv->is_array() || iv->size() < 2)
        return fail(ErrorKind::input, "must be an array of at least 2 intervals", "field " + name + ".intervals");
    for (const auto& v : *iv) {
        if (!v.is_number_unsigned() || v.get<std::uint64_t>() == 0 || v.get<std::uint64_t>() > 0xFFFF)
            return fail(ErrorKind::input, "every interval must be 1..65535 ticks", "field " + name + ".intervals");
        t.intervals.push_back(static_cast<std::uint16_t>(v.get<std::uint64_t>()));
    }
    for (const auto& [key, dst, min] : {std::tuple{"grid_steps", &t.grid_steps, 1U},
                                        std::tuple{"backlash_steps", &t.backlash_steps, 0U}}) {
        const auto f = it->find(key);
        if (f == it->end() || !f->is_number_unsigned() || f->get<std::uint64_t>() < min ||
            f->get<std::uint64_t>() > 0xFFFF)
            return fail(ErrorKind::input, "must be a whole number of steps", "field " + name + "." + key);
        *dst = static_cast<std::uint32_t>(f->get<std::uint64_t>());
    }
    return t;
}

}  // namespace

Result<machine::FirmwareTables> parse_firmware_tables(std::string_view text) {
    const json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) return fail(ErrorKind::input, "not a JSON object", "ramp tables");
    machine::FirmwareTables t;
    const auto id = j.find("table_id");
    if (id == j.end() || !id->is_string() || id->get<std::string>().size() != 8)
        return fail(ErrorKind::input, "must be 8 hex digits", "field table_id");
    try {
        std::size_t used = 0;
        t.table_id = static_cast<std::uint32_t>(std::stoul(id->get<std::string>(), &used, 16));
        if (used != 8) return fail(ErrorKind::input, "must be 8 hex digits", "field table_id");
    } catch (const std::exception&) {
        return fail(ErrorKind::input, "must be 8 hex digits", "field table_id");
    }
    TACTUS_TRY(c, read_table(j, "carriage"));
    TACTUS_TRY(f, read_table(j, "feed"));
    t.carriage = std::move(c);
    t.feed = std::move(f);
    const auto gap = j.find("start_gap_ticks");
    if (gap == j.end() || !gap->is_number_unsigned() || gap->get<std::uint64_t>() == 0 ||
        gap->get<std::uint64_t>() > 0xFFFF)
        return fail(ErrorKind::input, "must be 1..65535 machine cycles (a ramp.json from this firmware's gen-ramp.py has it)",
                    "field start_gap_ticks");
    t.start_gap_ticks = static_cast<std::uint32_t>(gap->get<std::uint64_t>());
    return t;
}

Result<machine::FirmwareTables> load_firmware_tables(const std::filesystem::path& path) {
    TACTUS_TRY(text, read_file(path, std::size_t{1} << 20));
    auto t = parse_firmware_tables(text);
    if (!t) return std::unexpected(located(t.error(), path.string()));
    return t;
}

Result<void> check_firmware_tables(const machine::FirmwareTables& t, const PrinterProfile& p) {
    for (const auto& [name, table, axis] : {std::tuple{"carriage", &t.carriage, &p.carriage},
                                            std::tuple{"feed", &t.feed, &p.feed}}) {
        const auto cruise = static_cast<long>(std::lround(machine::kTickHz / (axis->v_max_mm_s * axis->steps_per_mm)));
        if (table->intervals.back() != cruise)
            return fail(ErrorKind::input, "the firmware's tables cruise at " + std::to_string(table->intervals.back()) +
                            " ticks a step, this profile at " + std::to_string(cruise) +
                            ": the firmware was built for another profile (rebuild it with "
                            "make -C firmware PROFILE=...)",
                        std::string("field ") + name + ".v_max_mm_s");
        const auto backlash = static_cast<long>(std::lround(axis->backlash_mm * axis->steps_per_mm));
        if (static_cast<long>(table->backlash_steps) != backlash)
            return fail(ErrorKind::input, "the firmware adds " + std::to_string(table->backlash_steps) +
                            " backlash steps, this profile " + std::to_string(backlash) +
                            ": the firmware was built for another profile",
                        std::string("field ") + name + ".backlash_mm");
    }
    return {};
}

machine::StrikeTiming strike_timing(const PrinterProfile& p) {
    const double omega = std::sqrt(p.dynamics.belt_stiffness_n_m / p.dynamics.head_mass_kg);
    const double settle_s = 4.0 / (std::max(p.dynamics.damping_ratio, 0.05) * omega);
    auto ticks = [](double s) {
        return static_cast<std::uint16_t>(std::clamp(std::round(s * machine::kTickHz), 1.0, 65535.0));
    };
    // The hammer pulse is CONFIGURE's in v2 too: one mapping (controller_config).
    return {ticks(settle_s), controller_config(p).hammer_ticks};
}

}  // namespace tactus::profile
