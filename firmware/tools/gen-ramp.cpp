// SPDX-License-Identifier: GPL-3.0-or-later
// gen-ramp PROFILE.json OUTDIR: the firmware's motion tables from a printer
// profile, written as the build's sources (ramp.h, ramp_tables.c,
// ramp_up.inc, ramp_dn.inc, ramp_eq.inc) and ramp.json, the host's copy.
//
// The rule is Tactus's core (profile::make_firmware_tables, the same code the
// simulated controller and the host's planner run); this is its thin edge for
// `make -C firmware`, which compiles it from the core sources with the host's
// C++ compiler (firmware/README.md, "Building"), and for the CMake build.
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/file_io.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"

int main(int argc, char** argv) {
    using namespace tactus;
    if (argc != 3) {
        std::fprintf(stderr, "usage: gen-ramp PROFILE.json OUTDIR\n");
        return 2;
    }
    const std::filesystem::path path = argv[1];
    const std::filesystem::path out = argv[2];
    auto profile = profile::load_profile(path);
    if (!profile) {
        std::fprintf(stderr, "%s\n", profile.error().to_string().c_str());
        return 1;
    }
    auto tables = profile::make_firmware_tables(*profile);
    if (!tables) {
        std::fprintf(stderr, "%s: %s\n", path.string().c_str(), tables.error().to_string().c_str());
        return 1;
    }
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) {
        std::fprintf(stderr, "%s: %s\n", out.string().c_str(), ec.message().c_str());
        return 1;
    }
    for (const auto& f : profile::firmware_build_files(*tables, path.filename().string())) {
        if (auto w = write_file_atomic(out / f.name, f.text); !w) {
            std::fprintf(stderr, "%s\n", w.error().to_string().c_str());
            return 1;
        }
    }
    std::printf("%s\n", profile::describe_firmware_tables(*tables, *profile).c_str());
    return 0;
}
