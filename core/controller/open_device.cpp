// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/open_device.hpp"

#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "common/try.hpp"

namespace tactus::controller {
namespace {

Result<std::unique_ptr<transport::ByteStream>> open_sim(const transport::DeviceSpec& spec,
                                                        const std::optional<machine::FirmwareTables>& tables) {
    TACTUS_TRY(settings, transport::sim_settings(spec));
    SimOptions sim;
    if (settings.paper_reload_s) sim.reload_paper_after_s = *settings.paper_reload_s;
    TACTUS_TRY(firmware, sim_firmware_for(settings, tables));
    sim.firmware = std::move(firmware);
    auto ctl = std::make_shared<SimController>(sim);
    return std::unique_ptr<transport::ByteStream>(std::make_unique<SimTransport>(ctl, line_options(settings)));
}

}  // namespace

Result<std::optional<machine::FirmwareTables>> sim_firmware_for(
    const transport::SimSettings& settings, const std::optional<machine::FirmwareTables>& tables) {
    if (settings.protocol == 2) return std::optional<machine::FirmwareTables>{};
    if (settings.protocol == 3 && !tables)
        return fail(ErrorKind::usage,
                    "protocol 3 needs the ramp tables of a profile the reference firmware can run",
                    "sim option protocol");
    return tables;
}

Result<std::unique_ptr<transport::ByteStream>> open_device(std::string_view device,
                                                           const std::optional<machine::FirmwareTables>& sim_firmware) {
    TACTUS_TRY(spec, transport::parse_device(device));
    if (spec.scheme == "sim") return open_sim(spec, sim_firmware);
    return transport::open_device(device);
}

}  // namespace tactus::controller
