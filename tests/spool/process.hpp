// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The spool's end-to-end tests use the one process helper (tests/common).
#include "../common/process.hpp"

namespace tactus::spool::test {
using tactus::test::Process;
using tactus::test::read_text;
using tactus::test::run;
}  // namespace tactus::spool::test
