// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The controller's fault and status flags in plain words, with what to do
// about them (the app's printer panel says them; a screen reader reads them).
#include <cstdint>
#include <string>

#include "encode/messages.hpp"

namespace tactus::link {

std::string explain_faults(std::uint8_t fault_flags);
std::string explain_status(const encode::Status& s);

}  // namespace tactus::link
