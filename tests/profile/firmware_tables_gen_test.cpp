// SPDX-License-Identifier: GPL-3.0-or-later
// profile::make_firmware_tables: the reference firmware's ramp tables, made in
// C++ from a profile. The golden files in tests/data/firmware-tables/ were
// written by firmware/tools/gen-ramp.py, the Python generator this replaced
// (README there): the C++ rule must give the same tables, identity and build
// files, byte for byte, for the bundled profile and for random valid ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "common/file_io.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "../common/process.hpp"

using namespace tactus;
using namespace tactus::profile;
namespace fs = std::filesystem;

namespace {

const fs::path kGolden = fs::path(TACTUS_TEST_DATA) / "firmware-tables";

std::vector<fs::path> golden_cases() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(kGolden))
        if (e.is_directory()) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// The default profile with one JSON edit, parsed (and validated).
template <typename F>
PrinterProfile edited(F edit) {
    auto j = to_json(default_profile());
    edit(j);
    auto p = parse_profile(j.dump());
    EXPECT_TRUE(p.has_value()) << p.error().to_string();
    return p ? *p : default_profile();
}

void expect_refused(const PrinterProfile& p, const std::string& where, const std::string& says) {
    const auto t = make_firmware_tables(p);
    ASSERT_FALSE(t.has_value());
    EXPECT_EQ(t.error().kind, ErrorKind::input);
    EXPECT_NE(t.error().where.find(where), std::string::npos) << t.error().to_string();
    EXPECT_NE(t.error().message.find(says), std::string::npos) << t.error().to_string();
}

}  // namespace

TEST(FirmwareTablesGen, TheGoldenCasesAreThere) {
    // The bundled profile and at least four random ones.
    const auto cases = golden_cases();
    EXPECT_GE(cases.size(), 5U);
    EXPECT_TRUE(fs::exists(kGolden / "default" / "ramp.json"));
}

TEST(FirmwareTablesGen, EveryBuildFileIsTheOnesGenRampPyWrote) {
    for (const auto& dir : golden_cases()) {
        SCOPED_TRACE(dir.filename().string());
        const auto p = load_profile(dir / "profile.json");
        ASSERT_TRUE(p.has_value()) << p.error().to_string();
        const auto t = make_firmware_tables(*p);
        ASSERT_TRUE(t.has_value()) << t.error().to_string();
        const auto files = firmware_build_files(*t, "profile.json");
        ASSERT_EQ(files.size(), 6U);
        for (const auto& f : files) {
            auto want = read_file(dir / f.name);
            ASSERT_TRUE(want.has_value()) << f.name;
            EXPECT_EQ(f.text, *want) << f.name;
        }
        // And the host's copy reads back as the same tables, identity included.
        const auto back = load_firmware_tables(dir / "ramp.json");
        ASSERT_TRUE(back.has_value()) << back.error().to_string();
        EXPECT_EQ(*back, *t);
        EXPECT_EQ(table_identity(*back), back->table_id);
        // Tables made from a profile are tables the profile accepts.
        EXPECT_TRUE(check_firmware_tables(*t, *p).has_value());
    }
}

TEST(FirmwareTablesGen, TheBundledProfilesTablesAreTheFirmwareBuilds) {
    // The bundled profile (resources/profiles/default.json) is the default one
    // the firmware is built from (firmware/Makefile PROFILE).
    const auto p = load_profile(fs::path(TACTUS_RESOURCES_DIR) / "profiles" / "default.json");
    ASSERT_TRUE(p.has_value());
    const auto t = make_firmware_tables(*p);
    ASSERT_TRUE(t.has_value());
    const auto golden = load_firmware_tables(kGolden / "default" / "ramp.json");
    ASSERT_TRUE(golden.has_value());
    EXPECT_EQ(*t, *golden);
    EXPECT_EQ(t->table_id, 0x474cac88U);
    // The profile the app and the CLI start with is the same one.
    const auto built_in = make_firmware_tables(default_profile());
    ASSERT_TRUE(built_in.has_value());
    EXPECT_EQ(*built_in, *t);
    const auto built = load_firmware_tables(TACTUS_FIRMWARE_TABLES);  // the build's, by tactus-gen-ramp
    ASSERT_TRUE(built.has_value());
    EXPECT_EQ(*built, *t);
}

TEST(FirmwareTablesGen, TheToolWritesTheGoldenFiles) {
    // The edge `make -C firmware` runs (firmware/tools/gen-ramp.cpp).
    const auto dir = kGolden / "default";
    const auto out = fs::temp_directory_path() / ("tactus-gen-ramp-" + std::to_string(getpid()));
    fs::remove_all(out);
    const auto [code, text] = test::run({TACTUS_GEN_RAMP, (dir / "profile.json").string(), out.string()});
    ASSERT_EQ(code, 0) << text;
    EXPECT_NE(text.find("id 474cac88"), std::string::npos) << text;
    for (const char* name : {"ramp.h", "ramp_tables.c", "ramp_up.inc", "ramp_dn.inc", "ramp_eq.inc", "ramp.json"})
        EXPECT_EQ(test::read_text((out / name).string()), test::read_text((dir / name).string())) << name;
    fs::remove_all(out);
}

TEST(FirmwareTablesGen, AProfileTheFirmwareCannotRunIsRefusedNamingTheFieldAndTheLimit) {
    using nlohmann::json;
    // 300 mm/s x 80 steps/mm: a 38-cycle step, under the interrupt's 44.
    expect_refused(edited([](json& j) { j["carriage"]["v_max_mm_s"] = 300.0; }), "carriage.v_max_mm_s",
                   "sustains at most 20945 steps/s");
    expect_refused(edited([](json& j) { j["feed"]["v_max_mm_s"] = 200.0; }), "feed.v_max_mm_s",
                   "6776 steps/s the feed's interrupt path sustains");
    // 40 mm/s x 80 steps/mm = 3200 steps/s: the carriage cruises on the fast path only.
    expect_refused(edited([](json& j) { j["carriage"]["v_max_mm_s"] = 40.0; }), "carriage.v_max_mm_s",
                   "cruises at 3600 steps/s or faster");
    expect_refused(edited([](json& j) { j["geometry"]["back_offset_x_mm"] = 1.26; }), "geometry.back_offset_x_mm",
                   "not a whole number of carriage steps");
    expect_refused(edited([](json& j) { j["paper"]["margin_top_mm"] = 30.01; }), "paper.margin_top_mm",
                   "not a whole number of feed steps");
    expect_refused(edited([](json& j) { j["carriage"]["a_max_mm_s2"] = 5000.0; }), "carriage.a_max_mm_s2",
                   "the firmware holds 249");
    // A ramp of minutes would not fit the flash (nor be integrated in time).
    expect_refused(edited([](json& j) { j["feed"]["a_max_mm_s2"] = 10.0; }), "feed.a_max_mm_s2",
                   "at most 2 s");
}
