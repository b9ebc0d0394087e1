// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "encode/messages.hpp"
#include "profile/profile.hpp"

namespace tactus::encode {

// What the controller needs from the printer profile, in its own units: the one
// mapping behind both a direct `emboss` and a queued job, so they configure the
// controller identically.
ControllerConfig controller_config(const profile::PrinterProfile& profile);

}  // namespace tactus::encode
