// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/file_io.hpp"
#include "profile/profile_json.hpp"
#include "profile/profile_problem.hpp"

using namespace tactus;
using namespace tactus::profile;
using nlohmann::json;

namespace {

// Applies `edit` to the default profile's JSON and parses the result.
template <typename F>
Result<PrinterProfile> edited(F edit) {
    json j = to_json(default_profile());
    edit(j);
    return parse_profile(j.dump());
}

void expect_error(const Result<PrinterProfile>& r, const std::string& where, const std::string& says) {
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, where) << r.error().to_string();
    EXPECT_NE(r.error().message.find(says), std::string::npos) << r.error().to_string();
}

}  // namespace

TEST(Profile, DefaultIsTheSourceFormatAndValid) {
    const auto p = default_profile();
    EXPECT_TRUE(validate(p).has_value());
    EXPECT_EQ(p.geometry.cells_per_line, 27);
    EXPECT_EQ(p.geometry.lines_per_page, 24);
    EXPECT_TRUE(p.geometry.interpoint);
    EXPECT_DOUBLE_EQ(p.paper.width_mm, 210.0);
    EXPECT_DOUBLE_EQ(p.paper.height_mm, 297.0);
}

TEST(Profile, BundledFileEqualsDefault) {
    auto p = load_profile(std::filesystem::path(TACTUS_RESOURCES_DIR) / "profiles" / "default.json");
    ASSERT_TRUE(p.has_value()) << p.error().to_string();
    EXPECT_EQ(*p, default_profile());
}

TEST(Profile, JsonRoundTripKeepsEveryField) {
    auto p = default_profile();
    p.name = "test machine";
    p.geometry.back_mirror = BackMirror::y;
    p.motion.shape = ProfileShape::scurve;
    p.motion.shaper = ShaperKind::mzv;
    p.motion.bidirectional = false;
    p.carriage.backlash_mm = 0.005;
    auto back = parse_profile(to_json(p).dump());
    ASSERT_TRUE(back.has_value()) << back.error().to_string();
    EXPECT_EQ(*back, p);
}

TEST(Profile, OneInertiaWhenRotorFieldsAbsent) {
    auto r = edited([](json& j) {
        j["dynamics"].erase("rotor_inertia_kg_m2");
        j["dynamics"].erase("pulley_radius_m");
        j["dynamics"].erase("motor_stiffness_nm_rad");
    });
    ASSERT_TRUE(r.has_value()) << r.error().to_string();
    EXPECT_EQ(r->dynamics.rotor_inertia_kg_m2, 0.0);
}

TEST(Profile, SaveIsAtomicAndLoadsBack) {
    const auto dir = std::filesystem::temp_directory_path() / "tactus-profile-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto file = dir / "machine.json";
    ASSERT_TRUE(write_file_atomic(file, "old contents").has_value());
    auto p = default_profile();
    p.head.dwell_s = 0.006;
    ASSERT_TRUE(save_profile(p, file).has_value());
    auto back = load_profile(file);
    ASSERT_TRUE(back.has_value()) << back.error().to_string();
    EXPECT_EQ(*back, p);
    // Only the file itself: no temporary left behind.
    int entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1);
    // An invalid profile is refused and the file on disk is untouched.
    p.dynamics.head_mass_kg = -1;
    EXPECT_FALSE(save_profile(p, file).has_value());
    EXPECT_EQ(*load_profile(file), *back);
    std::filesystem::remove_all(dir);
}

TEST(Profile, NegativeMassNamesTheField) {
    expect_error(edited([](json& j) { j["dynamics"]["head_mass_kg"] = -0.2; }),
                 "field dynamics.head_mass_kg", "must be above 0");
}

// A quantity above 0 but far below anything physical is refused with its
// field: a 1e-300 kg head passed the check, and the vibration estimate then
// printed NaN and the plan a 0.00 um residual.
TEST(Profile, TinyPhysicalQuantitiesAreRefused) {
    for (const auto& [section, field] : {std::pair{"dynamics", "head_mass_kg"}, std::pair{"dynamics", "belt_stiffness_n_m"},
                                         std::pair{"dynamics", "rotor_inertia_kg_m2"},
                                         std::pair{"dynamics", "pulley_radius_m"},
                                         std::pair{"dynamics", "motor_stiffness_nm_rad"}, std::pair{"head", "dwell_s"}}) {
        SCOPED_TRACE(field);
        const std::string name = std::string(section) + "." + field;
        expect_error(edited([&](json& j) { j[section][field] = 1e-300; }), "field " + name, "physical minimum");
    }
}

TEST(Profile, ZeroStepsPerMmNamesTheField) {
    expect_error(edited([](json& j) { j["carriage"]["steps_per_mm"] = 0; }),
                 "field carriage.steps_per_mm", "must be above 0");
    expect_error(edited([](json& j) { j["feed"]["steps_per_mm"] = 0; }), "field feed.steps_per_mm",
                 "must be above 0");
}

TEST(Profile, HammerOffsetWiderThanPaper) {
    expect_error(edited([](json& j) { j["head"]["concave_offset_mm"] = 250; }),
                 "field head.concave_offset_mm", "wider than the paper");
}

TEST(Profile, ToleranceUnreachableAtAnySpeed) {
    expect_error(edited([](json& j) { j["vibration"]["tolerance_um"] = 2; }),
                 "field vibration.tolerance_um", "unreachable at any speed");
    expect_error(edited([](json& j) { j["vibration"]["tolerance_um"] = 0; }),
                 "field vibration.tolerance_um", "must be above 0");
}

TEST(Profile, FormatMustFitBetweenMargins) {
    expect_error(edited([](json& j) { j["geometry"]["cells_per_line"] = 28; }),
                 "field geometry.cells_per_line", "28 cells need 164.5 mm");
    expect_error(edited([](json& j) { j["geometry"]["lines_per_page"] = 25; }),
                 "field geometry.lines_per_page", "25 lines need");
    expect_error(edited([](json& j) { j["geometry"]["back_offset_x_mm"] = 40; }),
                 "field geometry.back_offset_x_mm", "off the paper");
}

TEST(Profile, ImpossibleDynamicsAndPitches) {
    expect_error(edited([](json& j) { j["dynamics"]["damping_ratio"] = -0.1; }),
                 "field dynamics.damping_ratio", "between 0 and 0.99");
    expect_error(edited([](json& j) { j["dynamics"]["pulley_radius_m"] = 0; }),
                 "field dynamics.pulley_radius_m", "must be above 0");
    expect_error(edited([](json& j) { j["geometry"]["cell_pitch_mm"] = 2; }),
                 "field geometry.cell_pitch_mm", "must exceed the dot pitch");
    expect_error(edited([](json& j) { j["carriage"]["v_max_mm_s"] = 5000; }),
                 "field carriage.v_max_mm_s", "more than the controller can time");
    expect_error(edited([](json& j) { j["carriage"]["a_max_mm_s2"] = 1e300; }),
                 "field carriage.a_max_mm_s2", "must not exceed");
}

TEST(Profile, MotionSoSlowThePlannerWouldNeverFinishIsRefused) {
    // Were it accepted, planning would never return.
    expect_error(edited([](json& j) { j["carriage"]["v_max_mm_s"] = 1e-6; }), "field carriage.v_max_mm_s",
                 "would take days");
    expect_error(edited([](json& j) { j["feed"]["a_max_mm_s2"] = 1e-300; }), "field feed.a_max_mm_s2",
                 "would take days");
    expect_error(edited([](json& j) { j["carriage"]["j_max_mm_s3"] = 1e-300; }), "field carriage.j_max_mm_s3",
                 "would take days");
}

TEST(Profile, MissingUnknownAndMistypedFields) {
    expect_error(edited([](json& j) { j["carriage"].erase("j_max_mm_s3"); }),
                 "field carriage.j_max_mm_s3", "missing");
    expect_error(edited([](json& j) { j.erase("vibration"); }), "field vibration", "missing section");
    expect_error(edited([](json& j) { j["geometry"]["dot_pich_mm"] = 2.5; }),
                 "field geometry.dot_pich_mm", "unknown field");
    expect_error(edited([](json& j) { j["geometry"]["dot_pitch_mm"] = "2.5"; }),
                 "field geometry.dot_pitch_mm", "must be a number");
    expect_error(edited([](json& j) { j["motion"]["shaper"] = "zz"; }), "field motion.shaper",
                 "must be one of \"none\"");
    expect_error(edited([](json& j) { j["geometry"]["cells_per_line"] = 27.5; }),
                 "field geometry.cells_per_line", "whole number");
    expect_error(edited([](json& j) { j["extras"] = json::object(); }), "field extras", "unknown section");
    expect_error(edited([](json& j) { j["motion"]["step_tolerance"] = 0.75; }), "field motion.step_tolerance",
                 "must be between 0 and 0.5");
}

TEST(Profile, StepToleranceIsOptionalAndKept) {
    auto j = to_json(default_profile());
    j["motion"].erase("step_tolerance");  // profiles written before the field existed
    auto p = from_json(j);
    ASSERT_TRUE(p) << p.error().to_string();
    EXPECT_DOUBLE_EQ(p->motion.step_tolerance, 0.5);
    j["motion"]["step_tolerance"] = 0.0;
    p = from_json(j);
    ASSERT_TRUE(p) << p.error().to_string();
    EXPECT_DOUBLE_EQ(p->motion.step_tolerance, 0.0);
}

TEST(Profile, MalformedJsonGivesByteOffset) {
    auto r = parse_profile("{\"paper\": {\"width_mm\": 210,, }");
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, "byte 28");  // 1-based: the second comma
    EXPECT_NE(r.error().message.find("not valid JSON"), std::string::npos);
}

TEST(Profile, LoadNamesTheFile) {
    const auto file = std::filesystem::temp_directory_path() / "tactus-bad-profile.json";
    json j = to_json(default_profile());
    j["dynamics"]["head_mass_kg"] = -1;
    ASSERT_TRUE(write_file_atomic(file, j.dump()).has_value());
    auto r = load_profile(file);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().where, file.string() + ":field dynamics.head_mass_kg");
    std::filesystem::remove(file);
    EXPECT_FALSE(load_profile(file).has_value());
}

// The problem is data the desktop app words in its own language; the English
// message of validate() is worded from the same record.
TEST(ProfileProblem, GivesTheFieldTheKindAndTheNumbers) {
    auto p = default_profile();
    p.paper.width_mm = 1;  // the 25 mm left margin no longer fits
    const auto problem = first_problem(p);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->field, "paper.margin_left_mm");
    EXPECT_EQ(problem->kind, ProblemKind::out_of_range);
    EXPECT_EQ(problem->value, 25);
    EXPECT_EQ(problem->limit, 0);
    EXPECT_EQ(problem->high, 1);
    EXPECT_EQ(problem->unit, "mm");
    const auto v = validate(p);
    ASSERT_FALSE(v);
    EXPECT_EQ(v.error().where, "field paper.margin_left_mm");
    EXPECT_EQ(v.error().message, describe(*problem));
    EXPECT_EQ(v.error().message, "is 25 mm, must be between 0 and 1 mm");

    auto q = default_profile();
    q.geometry.cells_per_line = 40;  // wider than the default paper's room
    const auto wide = first_problem(q);
    ASSERT_TRUE(wide);
    EXPECT_EQ(wide->kind, ProblemKind::line_too_wide);
    EXPECT_EQ(wide->count, 40);
    EXPECT_GT(wide->value, wide->limit);
    EXPECT_FALSE(first_problem(default_profile()));
}

// The graphic dot spacings: read, written, optional (a profile from before
// the section, or one setting a single spacing, keeps the defaults), and
// refused outside their physical range with the field and the bounds.
TEST(ProfileGraphic, SpacingsRoundTripAndAreOptional) {
    auto p = default_profile();
    p.graphic = {2.0, 3.5, 5.0, 6.0, 3.0};
    const auto back = parse_profile(to_json(p).dump());
    ASSERT_TRUE(back) << back.error().to_string();
    EXPECT_EQ(back->graphic, p.graphic);
    const auto without = edited([](json& j) { j.erase("graphic"); });
    ASSERT_TRUE(without) << without.error().to_string();
    EXPECT_EQ(without->graphic, Graphic{});
    const auto one = edited([](json& j) {
        j["graphic"] = json::object();
        j["graphic"]["line_dot_spacing_mm"] = 1.8;
    });
    ASSERT_TRUE(one) << one.error().to_string();
    EXPECT_DOUBLE_EQ(one->graphic.line_dot_spacing_mm, 1.8);
    EXPECT_DOUBLE_EQ(one->graphic.texture_pitch_mm, Graphic{}.texture_pitch_mm);
    expect_error(edited([](json& j) { j["graphic"]["line_spacing"] = 1.5; }), "field graphic.line_spacing",
                 "unknown field");
}

TEST(ProfileGraphic, OutOfRangeSpacingsAreRefused) {
    // Closer than 1.2 half dot pitches: the hammer's least distance after rounding.
    expect_error(edited([](json& j) { j["graphic"]["line_dot_spacing_mm"] = 1.0; }),
                 "field graphic.line_dot_spacing_mm", "is 1 mm, must be between 1.5 and 5 mm");
    expect_error(edited([](json& j) { j["graphic"]["line_dot_spacing_mm"] = 6; }),
                 "field graphic.line_dot_spacing_mm", "must be between 1.5 and 5 mm");
    // A dotted line that a finger could not tell from a solid one.
    expect_error(edited([](json& j) { j["graphic"]["dotted_dot_spacing_mm"] = 2.0; }),
                 "field graphic.dotted_dot_spacing_mm", "must be between 2.25 and 20 mm");
    expect_error(edited([](json& j) { j["graphic"]["dash_gap_mm"] = 2.0; }), "field graphic.dash_gap_mm",
                 "must be between 3 and 30 mm");
    expect_error(edited([](json& j) { j["graphic"]["texture_pitch_mm"] = 1.0; }), "field graphic.texture_pitch_mm",
                 "must be between 2.5 and 50 mm");
    expect_error(edited([](json& j) { j["graphic"]["texture_dot_spacing_mm"] = 0.5; }),
                 "field graphic.texture_dot_spacing_mm", "must be between 1.5 and 50 mm");
    expect_error(edited([](json& j) { j["graphic"]["dash_gap_mm"] = "wide"; }), "field graphic.dash_gap_mm",
                 "must be a number");
    // The bounds follow the cell's dot pitch: a 3 mm pitch needs 1.8 mm along a line.
    const auto wider = edited([](json& j) {
        j["geometry"]["dot_pitch_mm"] = 3.0;
        j["geometry"]["back_offset_x_mm"] = 1.5;
        j["geometry"]["back_offset_y_mm"] = 1.5;
    });
    expect_error(wider, "field graphic.line_dot_spacing_mm", "must be between 1.8 and 6 mm");
}
