// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer profile: everything plan and estimate need to know about one
// embosser. Lengths in millimetres, times in seconds, masses in kilograms. A
// profile is a plain value; profile_json.hpp reads, validates and writes it.
#include <cstdint>
#include <string>

namespace tactus::profile {

struct Paper {
    double width_mm = 210.0;  // A4
    double height_mm = 297.0;
    double margin_left_mm = 25.0;
    double margin_right_mm = 25.0;
    double margin_top_mm = 30.0;
    double margin_bottom_mm = 30.0;
    bool operator==(const Paper&) const = default;
};

// How the back page is turned relative to the front as the sheet is flipped.
enum class BackMirror : std::uint8_t {
    x,     // turned over about its vertical centre line (the usual book flip): x -> width - x
    y,     // turned over about its horizontal centre line: y -> height - y
    none,  // the back is addressed in front coordinates already
};

struct Geometry {
    double dot_pitch_mm = 2.5;    // between dots of one cell, both directions
    double cell_pitch_mm = 6.0;   // between cells on a line
    double line_pitch_mm = 10.0;  // between braille lines
    int cells_per_line = 27;
    int lines_per_page = 24;
    bool eight_dot = false;
    bool interpoint = true;
    // Back-side dots land here relative to the mirrored front grid, so the two
    // sides never hit the same spot. Half a dot pitch down keeps back rows between front rows.
    double back_offset_x_mm = 1.25;
    double back_offset_y_mm = 1.25;
    BackMirror back_mirror = BackMirror::x;
    bool operator==(const Geometry&) const = default;
};

// The two hammers ride one carriage; the carriage coordinate is where the convex
// hammer points on the paper, the concave one sits `concave_offset_mm` further in +x.
struct Head {
    double concave_offset_mm = 12.0;
    double dwell_s = 0.004;  // hammer down and back up, per strike, carriage at rest
    bool operator==(const Head&) const = default;
};

struct Axis {
    double steps_per_mm = 80.0;
    double v_max_mm_s = 250.0;
    double a_max_mm_s2 = 20000.0;
    double j_max_mm_s3 = 4.0e6;
    double backlash_mm = 0.01;
    bool operator==(const Axis&) const = default;
};

enum class ProfileShape : std::uint8_t { trapezoid, scurve, jerk, automatic };
enum class ShaperKind : std::uint8_t { none, zv, mzv, zvd, ei, automatic };

struct Motion {
    bool bidirectional = true;
    ProfileShape shape = ProfileShape::automatic;  // automatic: auto-tune per move
    ShaperKind shaper = ShaperKind::automatic;
    // How far a step may fire from its ideal time, as a fraction of its own step
    // interval: the commanded position then stays within this fraction of a step
    // of the planned trajectory. 0 holds every step to one timer tick (more step
    // segments, more bytes on the line: docs/motion.md, "Step timing").
    double step_tolerance = 0.5;
    bool operator==(const Motion&) const = default;
};

// The head on its belt. With rotor inertia and pulley radius the model has two
// inertias (motor rotor + head, coupled by the belt); without, one mass on a spring.
struct Dynamics {
    double head_mass_kg = 0.25;
    double belt_stiffness_n_m = 90000.0;
    double damping_ratio = 0.8;
    // The two-inertia model of the source; 0 rotor inertia selects one inertia.
    // Defaults: a NEMA 17 rotor (54 g cm2), a 20-tooth GT2 pulley, and the
    // stepper's magnetic stiffness (0.45 N m holding torque x 50 pole pairs).
    double rotor_inertia_kg_m2 = 5.4e-6;
    double pulley_radius_m = 6.366e-3;
    double motor_stiffness_nm_rad = 22.5;
    bool operator==(const Dynamics&) const = default;
};

struct Vibration {
    // Largest head position error allowed while the hammer is down; 2 % of the dot pitch.
    double tolerance_um = 50.0;
    double damping_band = 0.5;    // the machine's damping may be off by +-50 %
    double frequency_band = 0.2;  // and its natural frequency by +-20 %
    bool operator==(const Vibration&) const = default;
};

// The dot spacings of tactile graphics (docs/graphics.md, "Dots", which cites
// where the defaults come from): along a solid line, along a dotted one, the
// gap between a dashed line's dashes, and a texture's rows and the dots along them.
struct Graphic {
    double line_dot_spacing_mm = 1.5;
    double dotted_dot_spacing_mm = 3.0;
    double dash_gap_mm = 4.5;
    double texture_pitch_mm = 5.0;
    double texture_dot_spacing_mm = 2.5;
    bool operator==(const Graphic&) const = default;
};

struct PrinterProfile {
    std::string name = "Tactus A4 interpoint (source embosser)";
    Paper paper;
    Geometry geometry;
    Head head;
    Axis carriage;
    Axis feed{.steps_per_mm = 40.0,
              .v_max_mm_s = 150.0,
              .a_max_mm_s2 = 5000.0,
              .j_max_mm_s3 = 1.0e6,
              .backlash_mm = 0.02};
    Motion motion;
    Dynamics dynamics;
    Vibration vibration;
    Graphic graphic;
    bool operator==(const PrinterProfile&) const = default;
};

// The source embosser's format: A4, 27 cells x 24 lines, interpoint.
PrinterProfile default_profile();

const char* to_string(ProfileShape s);
const char* to_string(ShaperKind s);
const char* to_string(BackMirror m);

}  // namespace tactus::profile
