// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opening an embosser from its device string (docs/transports.md): the cables
// through the transport stage, and `sim` as the simulated 89C52 in this process.
// The simulator lives in this stage, so the one function that knows every
// scheme lives here too.
#include <memory>
#include <string_view>

#include "common/result.hpp"
#include "transport/byte_stream.hpp"

namespace tactus::controller {

Result<std::unique_ptr<transport::ByteStream>> open_device(std::string_view device);

}  // namespace tactus::controller
