// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/open_device.hpp"

#include <optional>
#include <string>

#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "transport/device.hpp"

namespace tactus::controller {
namespace {

Result<std::unique_ptr<transport::ByteStream>> open_sim(const transport::DeviceSpec& spec) {
    SimLineOptions line;
    line.speed = 1;  // the built-in simulator takes as long as the machine would
    SimOptions sim;
    for (const auto& [k, v] : spec.options) {
        if (k == "speed" && v == "max") {
            line.speed = 0;  // as fast as this computer can run it
            continue;
        }
        const auto d = transport::option_number(v);
        const std::string where = "sim option " + k;
        if (!d || *d < 0) return fail(ErrorKind::usage, "\"" + v + "\" is not a non-negative number", where);
        if (k == "baud") line.baud = *d;
        else if (k == "noise") line.noise.drop = line.noise.flip = line.noise.dup = *d;
        else if (k == "seed") line.noise.seed = static_cast<std::uint64_t>(*d);
        else if (k == "paper-reload") sim.reload_paper_after_s = *d;
        else if (k == "speed") {
            if (*d <= 0) return fail(ErrorKind::usage, "\"" + v + "\" is not a speed above 0 (or max)", where);
            line.speed = *d;
        } else return fail(ErrorKind::usage, "unknown option (baud, noise, seed, paper-reload, speed)", where);
    }
    if (line.baud < 300) return fail(ErrorKind::usage, "baud rate below 300", "sim option baud");
    auto ctl = std::make_shared<SimController>(sim);
    return std::unique_ptr<transport::ByteStream>(std::make_unique<SimTransport>(ctl, line));
}

}  // namespace

Result<std::unique_ptr<transport::ByteStream>> open_device(std::string_view device) {
    auto spec = transport::parse_device(device);
    if (!spec) return std::unexpected(spec.error());
    if (spec->scheme == "sim") return open_sim(*spec);
    return transport::open_device(device);
}

}  // namespace tactus::controller
