// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile/profile.hpp"

namespace tactus::profile {

PrinterProfile default_profile() {
    // All defaults live in the member initialisers of profile.hpp so that the
    // struct, this function and resources/profiles/default.json cannot drift
    // apart unnoticed (a test compares the bundled file with this value).
    return PrinterProfile{};
}

const char* to_string(ProfileShape s) {
    switch (s) {
        case ProfileShape::trapezoid: return "trapezoid";
        case ProfileShape::scurve: return "scurve";
        case ProfileShape::jerk: return "jerk";
        case ProfileShape::automatic: return "auto";
    }
    return "?";
}

const char* to_string(ShaperKind s) {
    switch (s) {
        case ShaperKind::none: return "none";
        case ShaperKind::zv: return "zv";
        case ShaperKind::mzv: return "mzv";
        case ShaperKind::zvd: return "zvd";
        case ShaperKind::ei: return "ei";
        case ShaperKind::automatic: return "auto";
    }
    return "?";
}

const char* to_string(BackMirror m) {
    switch (m) {
        case BackMirror::x: return "x";
        case BackMirror::y: return "y";
        case BackMirror::none: return "none";
    }
    return "?";
}

}  // namespace tactus::profile
