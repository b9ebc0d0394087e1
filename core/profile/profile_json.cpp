// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile/profile_json.hpp"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>
#include <variant>

#include "common/file_io.hpp"
#include "common/try.hpp"

namespace tactus::profile {
namespace {

using nlohmann::json;

template <typename E, std::size_t N>
bool enum_from(std::string_view s, const E (&values)[N], E& out) {
    for (E v : values)
        if (s == to_string(v)) {
            out = v;
            return true;
        }
    return false;
}

constexpr ProfileShape kShapes[] = {ProfileShape::trapezoid, ProfileShape::scurve,
                                    ProfileShape::jerk, ProfileShape::automatic};
constexpr ShaperKind kShapers[] = {ShaperKind::none, ShaperKind::zv,  ShaperKind::mzv,
                                   ShaperKind::zvd,  ShaperKind::ei, ShaperKind::automatic};
constexpr BackMirror kMirrors[] = {BackMirror::x, BackMirror::y, BackMirror::none};

template <typename E, std::size_t N>
std::string choices(const E (&values)[N]) {
    std::string s;
    for (E v : values) s += (s.empty() ? "" : ", ") + std::string("\"") + to_string(v) + "\"";
    return s;
}

using Target = std::variant<double*, int*, bool*, std::string*, ProfileShape*, ShaperKind*,
                            BackMirror*>;
struct Field {
    const char* name;
    Target target;
    bool optional = false;
};

std::string field_where(std::string_view section, std::string_view name) {
    return "field " + (section.empty() ? std::string(name) : std::string(section) + "." + std::string(name));
}

// Reads one object of the profile: every listed field, no others.
Result<void> read_object(const json& parent, std::string_view section,
                         std::initializer_list<Field> fields) {
    const json* obj = &parent;
    if (!section.empty()) {
        const auto it = parent.find(section);
        if (it == parent.end()) return fail(ErrorKind::input, "missing section", field_where({}, section));
        if (!it->is_object()) return fail(ErrorKind::input, "must be an object", field_where({}, section));
        obj = &*it;
    }
    for (const auto& [key, value] : obj->items()) {
        (void)value;
        bool known = false;
        for (const auto& f : fields) known = known || key == f.name;
        if (!known) return fail(ErrorKind::input, "unknown field (misspelt?)", field_where(section, key));
    }
    for (const auto& f : fields) {
        const auto where = field_where(section, f.name);
        const auto it = obj->find(f.name);
        if (it == obj->end()) {
            if (f.optional) continue;
            return fail(ErrorKind::input, "missing", where);
        }
        const json& v = *it;
        Result<void> r;
        std::visit(
            [&](auto* out) {
                using T = std::remove_pointer_t<decltype(out)>;
                if constexpr (std::is_same_v<T, double>) {
                    if (!v.is_number()) r = fail(ErrorKind::input, "must be a number", where);
                    else if (!std::isfinite(v.get<double>())) r = fail(ErrorKind::input, "must be finite", where);
                    else *out = v.get<double>();
                } else if constexpr (std::is_same_v<T, int>) {
                    if (!v.is_number_integer()) r = fail(ErrorKind::input, "must be a whole number", where);
                    else if (v.get<long long>() < std::numeric_limits<int>::min() ||
                             v.get<long long>() > std::numeric_limits<int>::max())
                        r = fail(ErrorKind::input, "out of range", where);
                    else *out = v.get<int>();
                } else if constexpr (std::is_same_v<T, bool>) {
                    if (!v.is_boolean()) r = fail(ErrorKind::input, "must be true or false", where);
                    else *out = v.get<bool>();
                } else if constexpr (std::is_same_v<T, std::string>) {
                    if (!v.is_string()) r = fail(ErrorKind::input, "must be a string", where);
                    else *out = v.get<std::string>();
                } else {
                    bool ok = v.is_string();
                    std::string list;
                    if constexpr (std::is_same_v<T, ProfileShape>) {
                        ok = ok && enum_from(v.get<std::string>(), kShapes, *out);
                        list = choices(kShapes);
                    } else if constexpr (std::is_same_v<T, ShaperKind>) {
                        ok = ok && enum_from(v.get<std::string>(), kShapers, *out);
                        list = choices(kShapers);
                    } else {
                        ok = ok && enum_from(v.get<std::string>(), kMirrors, *out);
                        list = choices(kMirrors);
                    }
                    if (!ok) r = fail(ErrorKind::input, "must be one of " + list, where);
                }
            },
            f.target);
        if (!r) return r;
    }
    return {};
}

json axis_json(const Axis& a) {
    return {{"steps_per_mm", a.steps_per_mm}, {"v_max_mm_s", a.v_max_mm_s},
            {"a_max_mm_s2", a.a_max_mm_s2},   {"j_max_mm_s3", a.j_max_mm_s3},
            {"backlash_mm", a.backlash_mm}};
}

Result<void> read_axis(const json& j, const char* section, Axis& a) {
    return read_object(j, section,
                       {{"steps_per_mm", &a.steps_per_mm},
                        {"v_max_mm_s", &a.v_max_mm_s},
                        {"a_max_mm_s2", &a.a_max_mm_s2},
                        {"j_max_mm_s3", &a.j_max_mm_s3},
                        {"backlash_mm", &a.backlash_mm}});
}

// A SAX handler that only records where parsing failed, so a malformed file is
// reported with its byte offset without using exceptions.
struct ParseErrorCapture : nlohmann::json_sax<json> {
    std::size_t position = 0;
    std::string message;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t pos, const std::string&,
                     const nlohmann::detail::exception& ex) override {
        position = pos;
        message = ex.what();
        return false;
    }
};

}  // namespace

json to_json(const PrinterProfile& p) {
    json d = {{"head_mass_kg", p.dynamics.head_mass_kg},
              {"belt_stiffness_n_m", p.dynamics.belt_stiffness_n_m},
              {"damping_ratio", p.dynamics.damping_ratio}};
    if (p.dynamics.rotor_inertia_kg_m2 > 0) {
        d["rotor_inertia_kg_m2"] = p.dynamics.rotor_inertia_kg_m2;
        d["pulley_radius_m"] = p.dynamics.pulley_radius_m;
        d["motor_stiffness_nm_rad"] = p.dynamics.motor_stiffness_nm_rad;
    }
    return {
        {"name", p.name},
        {"paper",
         {{"width_mm", p.paper.width_mm},
          {"height_mm", p.paper.height_mm},
          {"margin_left_mm", p.paper.margin_left_mm},
          {"margin_right_mm", p.paper.margin_right_mm},
          {"margin_top_mm", p.paper.margin_top_mm},
          {"margin_bottom_mm", p.paper.margin_bottom_mm}}},
        {"geometry",
         {{"dot_pitch_mm", p.geometry.dot_pitch_mm},
          {"cell_pitch_mm", p.geometry.cell_pitch_mm},
          {"line_pitch_mm", p.geometry.line_pitch_mm},
          {"cells_per_line", p.geometry.cells_per_line},
          {"lines_per_page", p.geometry.lines_per_page},
          {"eight_dot", p.geometry.eight_dot},
          {"interpoint", p.geometry.interpoint},
          {"back_offset_x_mm", p.geometry.back_offset_x_mm},
          {"back_offset_y_mm", p.geometry.back_offset_y_mm},
          {"back_mirror", to_string(p.geometry.back_mirror)}}},
        {"head", {{"concave_offset_mm", p.head.concave_offset_mm}, {"dwell_s", p.head.dwell_s}}},
        {"carriage", axis_json(p.carriage)},
        {"feed", axis_json(p.feed)},
        {"motion",
         {{"bidirectional", p.motion.bidirectional},
          {"profile", to_string(p.motion.shape)},
          {"shaper", to_string(p.motion.shaper)},
          {"step_tolerance", p.motion.step_tolerance}}},
        {"dynamics", d},
        {"vibration",
         {{"tolerance_um", p.vibration.tolerance_um},
          {"damping_band", p.vibration.damping_band},
          {"frequency_band", p.vibration.frequency_band}}},
        {"graphic",
         {{"line_dot_spacing_mm", p.graphic.line_dot_spacing_mm},
          {"dotted_dot_spacing_mm", p.graphic.dotted_dot_spacing_mm},
          {"dash_gap_mm", p.graphic.dash_gap_mm},
          {"texture_pitch_mm", p.graphic.texture_pitch_mm},
          {"texture_dot_spacing_mm", p.graphic.texture_dot_spacing_mm}}},
    };
}

Result<PrinterProfile> from_json(const json& j) {
    if (!j.is_object()) return fail(ErrorKind::input, "a printer profile must be a JSON object", "byte 0");
    PrinterProfile p;
    p.dynamics.rotor_inertia_kg_m2 = 0;  // optional two-inertia fields: absent means one inertia
    p.dynamics.pulley_radius_m = 0;
    p.dynamics.motor_stiffness_nm_rad = 0;
    static constexpr const char* kSections[] = {"name",     "paper", "geometry", "head",
                                                 "carriage", "feed",  "motion",   "dynamics",
                                                 "vibration", "graphic"};
    for (const auto& [key, value] : j.items()) {
        (void)value;
        bool known = false;
        for (const char* s : kSections) known = known || key == s;
        if (!known) return fail(ErrorKind::input, "unknown section (misspelt?)", "field " + key);
    }
    Result<void> r;
    if (const auto it = j.find("name"); it != j.end()) {
        if (!it->is_string()) return fail(ErrorKind::input, "must be a string", "field name");
        p.name = it->get<std::string>();
    }
    if (r) r = read_object(j, "paper",
                           {{"width_mm", &p.paper.width_mm},
                            {"height_mm", &p.paper.height_mm},
                            {"margin_left_mm", &p.paper.margin_left_mm},
                            {"margin_right_mm", &p.paper.margin_right_mm},
                            {"margin_top_mm", &p.paper.margin_top_mm},
                            {"margin_bottom_mm", &p.paper.margin_bottom_mm}});
    if (r) r = read_object(j, "geometry",
                           {{"dot_pitch_mm", &p.geometry.dot_pitch_mm},
                            {"cell_pitch_mm", &p.geometry.cell_pitch_mm},
                            {"line_pitch_mm", &p.geometry.line_pitch_mm},
                            {"cells_per_line", &p.geometry.cells_per_line},
                            {"lines_per_page", &p.geometry.lines_per_page},
                            {"eight_dot", &p.geometry.eight_dot},
                            {"interpoint", &p.geometry.interpoint},
                            {"back_offset_x_mm", &p.geometry.back_offset_x_mm},
                            {"back_offset_y_mm", &p.geometry.back_offset_y_mm},
                            {"back_mirror", &p.geometry.back_mirror}});
    if (r) r = read_object(j, "head",
                           {{"concave_offset_mm", &p.head.concave_offset_mm},
                            {"dwell_s", &p.head.dwell_s}});
    if (r) r = read_axis(j, "carriage", p.carriage);
    if (r) r = read_axis(j, "feed", p.feed);
    if (r) r = read_object(j, "motion",
                           {{"bidirectional", &p.motion.bidirectional},
                            {"profile", &p.motion.shape},
                            {"shaper", &p.motion.shaper},
                            {"step_tolerance", &p.motion.step_tolerance, true}});
    if (r) r = read_object(j, "dynamics",
                           {{"head_mass_kg", &p.dynamics.head_mass_kg},
                            {"belt_stiffness_n_m", &p.dynamics.belt_stiffness_n_m},
                            {"damping_ratio", &p.dynamics.damping_ratio},
                            {"rotor_inertia_kg_m2", &p.dynamics.rotor_inertia_kg_m2, true},
                            {"pulley_radius_m", &p.dynamics.pulley_radius_m, true},
                            {"motor_stiffness_nm_rad", &p.dynamics.motor_stiffness_nm_rad, true}});
    if (r) r = read_object(j, "vibration",
                           {{"tolerance_um", &p.vibration.tolerance_um},
                            {"damping_band", &p.vibration.damping_band},
                            {"frequency_band", &p.vibration.frequency_band}});
    // Optional, as a section and field by field: a profile written before it
    // existed, or one that changes a single spacing, keeps the other defaults.
    if (r && j.contains("graphic"))
        r = read_object(j, "graphic",
                        {{"line_dot_spacing_mm", &p.graphic.line_dot_spacing_mm, true},
                         {"dotted_dot_spacing_mm", &p.graphic.dotted_dot_spacing_mm, true},
                         {"dash_gap_mm", &p.graphic.dash_gap_mm, true},
                         {"texture_pitch_mm", &p.graphic.texture_pitch_mm, true},
                         {"texture_dot_spacing_mm", &p.graphic.texture_dot_spacing_mm, true}});
    if (!r) return std::unexpected(r.error());
    TACTUS_TRY_VOID(validate(p));
    return p;
}

Result<PrinterProfile> parse_profile(std::string_view text) {
    json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) {
        ParseErrorCapture capture;
        json::sax_parse(text, &capture);
        return fail(ErrorKind::input, "not valid JSON: " + capture.message, "byte " + std::to_string(capture.position));
    }
    return from_json(j);
}

Result<PrinterProfile> load_profile(const std::filesystem::path& path) {
    TACTUS_TRY(text, read_file(path, std::size_t{1} << 20));
    auto p = parse_profile(text);
    if (!p) return std::unexpected(located(p.error(), path.string()));
    return p;
}

Result<void> save_profile(const PrinterProfile& p, const std::filesystem::path& path) {
    if (auto v = validate(p); !v) return v;
    return write_file_atomic(path, to_json(p).dump(2) + "\n");
}

}  // namespace tactus::profile
