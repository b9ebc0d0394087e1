// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opening an embosser from its device string (docs/transports.md): the cables
// through the transport stage, and `sim` as the simulated 89C52 in this process.
// The simulator lives in this stage, so the one function that knows every
// scheme lives here too.
#include <memory>
#include <optional>
#include <string_view>

#include "common/result.hpp"
#include "machine/firmware_tables.hpp"
#include "transport/byte_stream.hpp"
#include "transport/device.hpp"

namespace tactus::controller {

// `sim_firmware`: the ramp tables the caller's profile makes
// (profile::make_firmware_tables). A `sim` device then speaks protocol 3 with
// them, as the reference firmware built from that profile does, unless its
// string says `protocol=2`; without them it speaks protocol 2 (and
// `protocol=3` is refused). Other devices ignore them.
Result<std::unique_ptr<transport::ByteStream>> open_device(
    std::string_view device, const std::optional<machine::FirmwareTables>& sim_firmware = std::nullopt);

// The tables a simulator with these settings runs (nullopt: protocol 2), or
// the reason it cannot: `protocol=3` without tables.
Result<std::optional<machine::FirmwareTables>> sim_firmware_for(
    const transport::SimSettings& settings, const std::optional<machine::FirmwareTables>& tables);

}  // namespace tactus::controller
