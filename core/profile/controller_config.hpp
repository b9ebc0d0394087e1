// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "machine/controller_config.hpp"
#include "profile/profile.hpp"

namespace tactus::profile {

// What the controller needs from the printer profile, in its own units: the one
// mapping behind a direct `emboss`, a queued job and the app's Connect, so they
// configure the controller identically.
machine::ControllerConfig controller_config(const PrinterProfile& profile);

}  // namespace tactus::profile
