// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The firmware build's ramp tables (TACTUS_FIRMWARE_TABLES, set per test target),
// loaded once per test program.
#include <gtest/gtest.h>

#include "profile/firmware_tables.hpp"

namespace tactus::test {

inline const machine::FirmwareTables& firmware_tables() {
    static const machine::FirmwareTables t = [] {
        auto r = profile::load_firmware_tables(TACTUS_FIRMWARE_TABLES);
        EXPECT_TRUE(r) << r.error().to_string();
        return r ? *r : machine::FirmwareTables{};
    }();
    return t;
}

}  // namespace tactus::test
