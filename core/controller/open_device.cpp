// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/open_device.hpp"


#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "transport/device.hpp"

namespace tactus::controller {
namespace {

Result<std::unique_ptr<transport::ByteStream>> open_sim(const transport::DeviceSpec& spec) {
    auto settings = transport::sim_settings(spec);
    if (!settings) return std::unexpected(settings.error());
    SimOptions sim;
    if (settings->paper_reload_s) sim.reload_paper_after_s = *settings->paper_reload_s;
    auto ctl = std::make_shared<SimController>(sim);
    return std::unique_ptr<transport::ByteStream>(std::make_unique<SimTransport>(ctl, line_options(*settings)));
}

}  // namespace

Result<std::unique_ptr<transport::ByteStream>> open_device(std::string_view device) {
    auto spec = transport::parse_device(device);
    if (!spec) return std::unexpected(spec.error());
    if (spec->scheme == "sim") return open_sim(*spec);
    return transport::open_device(device);
}

}  // namespace tactus::controller
