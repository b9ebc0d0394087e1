// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/plan_file.hpp"

#include <initializer_list>
#include <limits>
#include <string>

#include "common/file_io.hpp"
#include "machine/reference_firmware.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "common/try.hpp"

namespace tactus::plan {
namespace {

using nlohmann::json;

json move_json(const motion::StepMove& m) {
    json segs = json::array();
    for (const auto& s : m.segments) segs.push_back({s.interval_q16, s.count, s.add_q16});
    return {{"steps", m.steps}, {"segments", segs}, {"duration_s", m.duration_s}, {"settle_ticks", m.settle_ticks}};
}

// Typed reads with the JSON path in the error.
template <typename T>
Result<T> get(const json& j, const char* key, const std::string& where) {
    if (!j.is_object() || !j.contains(key)) return fail(ErrorKind::input, "missing field", where + "." + key);
    const json& v = j.at(key);
    if constexpr (std::is_same_v<T, double>) {
        if (!v.is_number()) return fail(ErrorKind::input, "not a number", where + "." + key);
        return v.get<double>();
    } else {
        if (!v.is_number_integer()) return fail(ErrorKind::input, "not an integer", where + "." + key);
        const auto x = v.get<std::int64_t>();
        if (x < std::numeric_limits<T>::min() || x > std::numeric_limits<T>::max())
            return fail(ErrorKind::input, "out of range", where + "." + key);
        return static_cast<T>(x);
    }
}

// An optional word from a fixed set: absent gives the first; anything else
// (another word, a number, ...) is an error naming the field, never a throw.
Result<std::string> word(const json& j, const char* key, std::initializer_list<const char*> allowed,
                         const std::string& where) {
    const std::string first = *allowed.begin();
    if (!j.is_object() || !j.contains(key)) return first;
    const json& v = j.at(key);
    if (v.is_string())
        for (const char* a : allowed)
            if (v.get<std::string>() == a) return std::string(a);
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : " or ") + std::string(a);
    return fail(ErrorKind::input, "expected " + list, where + "." + key);
}

Result<motion::StepMove> move_from(const json& j, const std::string& where) {
    motion::StepMove m;
    TACTUS_TRY(steps, get<std::int32_t>(j, "steps", where));
    m.steps = steps;
    if (auto d = get<double>(j, "duration_s", where)) m.duration_s = *d;
    // The encoder sends it as the wait before the strike: absent is 0, a
    // wrong type is an error, never a silent 0.
    if (j.contains("settle_ticks")) {
        TACTUS_TRY(settle, get<std::uint32_t>(j, "settle_ticks", where));
        m.settle_ticks = settle;
    }
    if (!j.contains("segments") || !j["segments"].is_array())
        return fail(ErrorKind::input, "missing segment list", where + ".segments");
    for (std::size_t i = 0; i < j["segments"].size(); ++i) {
        const auto& s = j["segments"][i];
        const auto w = where + ".segments[" + std::to_string(i) + "]";
        if (!s.is_array() || s.size() != 3 || !s[0].is_number_integer() ||
            !s[1].is_number_integer() || !s[2].is_number_integer())
            return fail(ErrorKind::input, "expected [interval_q16, count, add_q16]", w);
        const auto iv = s[0].get<std::int64_t>(), n = s[1].get<std::int64_t>(), a = s[2].get<std::int64_t>();
        if (iv < 0 || iv > 0xFFFFFFFFLL || n < 0 || n > 0xFFFF || a < INT32_MIN || a > INT32_MAX)
            return fail(ErrorKind::input, "out of range", w);
        m.segments.push_back({static_cast<std::uint32_t>(iv), static_cast<std::uint16_t>(n),
                              static_cast<std::int32_t>(a)});
    }
    return m;
}

}  // namespace

json plan_file_head(const profile::PrinterProfile& profile, const std::optional<machine::FirmwareTables>& firmware) {
    json head = {{"tactus_plan", kPlanFileFormat},
                 {"protocol", firmware ? machine::reference_firmware::kProtocol : machine::reference_firmware::kLegacyProtocol},
                 {"profile", profile::to_json(profile)}};
    if (firmware) head["firmware_tables"] = json::parse(profile::ramp_json(*firmware));
    return head;
}

json sheet_to_json(const SheetPlan& sh) {
    json passes = json::array();
    for (const auto& p : sh.passes) {
        json strikes = json::array();
        for (std::size_t i = 0; i < p.strikes.size(); ++i) {
            const auto& s = p.strikes[i];
            strikes.push_back({{"hammer", s.hammer == plan::Hammer::convex ? "convex" : "concave"},
                               {"side", s.side == plan::Side::front ? "front" : "back"},
                               {"x_mm", s.x_mm},
                               {"y_mm", s.y_mm},
                               {"carriage_step", s.carriage_step},
                               {"time_s", s.time_s},
                               {"move", move_json(p.moves[i])}});
        }
        passes.push_back({{"side", p.side == plan::Side::front ? "front" : "back"},
                          {"y_mm", p.y_mm},
                          {"feed_step", p.feed_step},
                          {"direction", p.direction},
                          {"feed", move_json(p.feed)},
                          {"strikes", strikes},
                          {"duration_s", p.duration_s}});
    }
    return {{"index", sh.index}, {"passes", passes}, {"duration_s", sh.duration_s}};
}

json plan_to_json(const PlanFile& file) {
    json out = plan_file_head(file.profile, file.firmware);
    json sheets = json::array();
    for (const auto& sh : file.plan.sheets) sheets.push_back(sheet_to_json(sh));
    out["duration_s"] = file.plan.duration_s;
    out["sheets"] = std::move(sheets);
    return out;
}

Result<PlanFile> plan_from_json(const json& j) {
    if (!j.is_object() || !j.contains("tactus_plan"))
        return fail(ErrorKind::input, "not a Tactus plan (no \"tactus_plan\" field; make one with `tactus-cli plan --json`)",
                    "plan");
    if (j["tactus_plan"] == 1)
        return fail(ErrorKind::input, "plan file format 1 records neither the profile nor the protocol it was made for (nor "
                    "the settles before strikes); make it again with `tactus-cli plan --json`",
                    "plan.tactus_plan");
    if (j["tactus_plan"] != kPlanFileFormat)
        return fail(ErrorKind::input, "unsupported plan file format " + j["tactus_plan"].dump() + " (this Tactus reads " +
                        std::to_string(kPlanFileFormat) + ")",
                    "plan.tactus_plan");
    PlanFile file;
    TACTUS_TRY(protocol, get<std::uint8_t>(j, "protocol", "plan"));
    file.protocol = protocol;
    if (file.protocol != machine::reference_firmware::kLegacyProtocol && file.protocol != machine::reference_firmware::kProtocol)
        return fail(ErrorKind::input, "link protocol " + std::to_string(file.protocol) + " is not one this Tactus speaks (2 or 3)",
                    "plan.protocol");
    if (!j.contains("profile")) return fail(ErrorKind::input, "missing field", "plan.profile");
    auto prof = profile::from_json(j["profile"]);
    if (!prof) return std::unexpected(located(prof.error(), "plan.profile"));
    file.profile = std::move(*prof);
    if (file.protocol == machine::reference_firmware::kProtocol) {
        if (!j.contains("firmware_tables"))
            return fail(ErrorKind::input, "a protocol-3 plan carries the ramp tables its moves are made of; this one has none",
                        "plan.firmware_tables");
        auto tables = profile::parse_firmware_tables(j["firmware_tables"].dump());
        if (!tables) return std::unexpected(located(tables.error(), "plan.firmware_tables"));
        if (auto c = profile::check_firmware_tables(*tables, file.profile); !c)
            return std::unexpected(located(c.error(), "plan.firmware_tables"));
        file.firmware = std::move(*tables);
    } else if (j.contains("firmware_tables")) {
        return fail(ErrorKind::input, "a protocol-2 plan has no ramp tables (its moves are step schedules)", "plan.firmware_tables");
    }
    plan::JobPlan& out = file.plan;
    if (auto d = get<double>(j, "duration_s", "plan")) out.duration_s = *d;
    if (!j.contains("sheets") || !j["sheets"].is_array()) return fail(ErrorKind::input, "missing sheets", "plan.sheets");
    if (j["sheets"].empty()) return fail(ErrorKind::input, "the plan has no sheets", "plan.sheets");
    for (std::size_t si = 0; si < j["sheets"].size(); ++si) {
        const auto& js = j["sheets"][si];
        const auto ws = "plan.sheets[" + std::to_string(si) + "]";
        plan::SheetPlan sheet;
        TACTUS_TRY(idx, get<std::uint16_t>(js, "index", ws));
        sheet.index = idx;
        const std::size_t previous = out.sheets.empty() ? 0 : out.sheets.back().index;
        if (sheet.index <= previous)
            return fail(ErrorKind::input, sheet.index == 0 ? std::string("sheets are numbered from 1")
                                         : "sheet " + std::to_string(sheet.index) + " comes after sheet " +
                                               std::to_string(previous) + " (sheets are in order, each once)",
                        ws + ".index");
        if (!js.contains("passes") || !js["passes"].is_array()) return fail(ErrorKind::input, "missing passes", ws + ".passes");
        for (std::size_t pi = 0; pi < js["passes"].size(); ++pi) {
            const auto& jp = js["passes"][pi];
            const auto wp = ws + ".passes[" + std::to_string(pi) + "]";
            plan::Pass p;
            p.sheet = sheet.index;
            TACTUS_TRY(side, word(jp, "side", {"front", "back"}, wp));
            p.side = side == "back" ? plan::Side::back : plan::Side::front;
            if (auto y = get<double>(jp, "y_mm", wp)) p.y_mm = *y;
            TACTUS_TRY(fs, get<std::int32_t>(jp, "feed_step", wp));
            p.feed_step = fs;
            if (jp.contains("direction") && !jp["direction"].is_number())
                return fail(ErrorKind::input, "not a number", wp + ".direction");
            p.direction = jp.contains("direction") && jp["direction"].get<double>() < 0 ? -1 : 1;
            if (!jp.contains("feed")) return fail(ErrorKind::input, "missing field", wp + ".feed");
            TACTUS_TRY(feed, move_from(jp["feed"], wp + ".feed"));
            p.feed = feed;
            if (!jp.contains("strikes") || !jp["strikes"].is_array())
                return fail(ErrorKind::input, "missing strikes", wp + ".strikes");
            for (std::size_t k = 0; k < jp["strikes"].size(); ++k) {
                const auto& jk = jp["strikes"][k];
                const auto wk = wp + ".strikes[" + std::to_string(k) + "]";
                plan::Strike s;
                TACTUS_TRY(hammer, word(jk, "hammer", {"convex", "concave"}, wk));
                s.hammer = hammer == "concave" ? plan::Hammer::concave : plan::Hammer::convex;
                TACTUS_TRY(strike_side, word(jk, "side", {"front", "back"}, wk));
                s.side = strike_side == "back" ? plan::Side::back : plan::Side::front;
                TACTUS_TRY(cs, get<std::int32_t>(jk, "carriage_step", wk));
                s.carriage_step = cs;
                if (auto v = get<double>(jk, "x_mm", wk)) s.x_mm = *v;
                if (auto v = get<double>(jk, "y_mm", wk)) s.y_mm = *v;
                if (auto v = get<double>(jk, "time_s", wk)) s.time_s = *v;
                if (!jk.contains("move")) return fail(ErrorKind::input, "missing field", wk + ".move");
                TACTUS_TRY(m, move_from(jk["move"], wk + ".move"));
                p.moves.push_back(m);
                p.strikes.push_back(s);
                ++out.strikes;
            }
            if (auto d = get<double>(jp, "duration_s", wp)) p.duration_s = *d;
            sheet.passes.push_back(std::move(p));
        }
        out.sheets.push_back(std::move(sheet));
    }
    return file;
}

Result<PlanFile> load_plan(const std::filesystem::path& path) {
    TACTUS_TRY(text, read_file(path));
    const auto j = json::parse(text, nullptr, false);
    if (j.is_discarded()) return fail(ErrorKind::input, "not valid JSON", path.string());
    auto p = plan_from_json(j);
    if (!p) return std::unexpected(located(p.error(), path.string()));
    return p;
}

}  // namespace tactus::plan

namespace tactus::plan {

Result<void> save_plan(const PlanFile& file, const std::filesystem::path& path) {
    TACTUS_TRY_VOID(write_file_atomic(path, plan_to_json(file).dump() + "\n"));
    return {};
}

}  // namespace tactus::plan
