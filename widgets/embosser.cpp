// SPDX-License-Identifier: GPL-3.0-or-later
#include "embosser.hpp"

#include <algorithm>

#include "controller/sim_controller.hpp"
#include "profile/controller_config.hpp"
#include "encode/messages.hpp"
#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"
#include "transport/serial_port.hpp"
#include "controller/sim_transport.hpp"

namespace tactus::gui {

std::vector<DeviceChoice> list_devices(std::vector<std::string>* problems) {
    std::vector<DeviceChoice> out{{"sim", "sim", "Built-in simulated embosser"}};
    for (auto lister : {transport::list_serial_ports, transport::list_hid_uarts, transport::list_parallel_ports}) {
        auto ports = lister();
        if (!ports) {
            if (problems) problems->push_back(ports.error().to_string());
            continue;
        }
        for (const auto& p : *ports) {
            std::string text = p.description;
            if (!p.product.empty() && text.find(p.product) == std::string::npos) text += " - " + p.product;
            if (!p.manufacturer.empty()) text += " (" + p.manufacturer + ")";
            out.push_back({p.device, p.kind, text.empty() ? p.device : text});
        }
    }
    return out;
}

std::string explain_faults(std::uint8_t f) {
    namespace fault = encode::fault;
    std::string out;
    const auto add = [&out](const char* s) {
        if (!out.empty()) out += ' ';
        out += s;
    };
    if (f & fault::paper_out) add("Paper out: put paper in the feeder; the job goes on by itself.");
    if (f & fault::limit_switch)
        add("The carriage reached a limit switch: check that nothing blocks it and that the paper is straight, then resume.");
    if (f & fault::hammer) add("A hammer did not come back: switch the embosser off, free the hammer, then resume from the sheet shown.");
    if (f & fault::power_on_reset) add("The embosser restarted after losing power: the job resumes from the first unfinished sheet.");
    if (f & fault::warm_reset) add("The controller restarted but kept its place: the job continues.");
    if (f & fault::host_timeout) add("The embosser stopped hearing from this computer and paused: check the cable.");
    if (f & fault::underrun) add("The embosser ran out of data in a move (should not happen): report it with the link log.");
    if (f & fault::stream_error) add("The embosser rejected the job data: report it with the link log.");
    return out;
}

std::string explain_status(const encode::Status& s) {
    namespace st = encode::flag;
    std::string out = encode::state_name(s.ack.state);
    out += (s.flags & st::configured) ? ", configured" : ", not configured";
    out += (s.flags & st::homed) ? ", carriage homed" : ", carriage not homed";
    out += (s.flags & st::paper_present) ? ", paper loaded" : ", no paper";
    if (s.flags & st::job_active) out += ", printing sheet " + std::to_string(s.sheet);
    if (s.ack.faults) out += ". " + explain_faults(s.ack.faults);
    return out;
}

Result<Embosser> Embosser::connect(const std::string& device, const profile::PrinterProfile& p) {
    Embosser e;
    e.device_ = device;
    if (device == "sim") {
        controller::SimOptions options;
        options.reload_paper_after_s = 5;  // the simulated operator loads paper
        e.sim_ = std::make_shared<controller::SimController>(options);
        auto transport = std::make_unique<controller::SimTransport>(e.sim_, controller::SimLineOptions{});
        e.sim_transport_ = transport.get();
        e.link_ = std::make_unique<link::Link>(link::Link::over(std::move(transport)));
    } else {
        auto l = link::Link::open(device);
        if (!l) return std::unexpected(l.error());
        e.link_ = std::make_unique<link::Link>(std::move(*l));
    }
    if (auto h = e.link_->hello(); !h) return std::unexpected(located(h.error(), device));
    if (auto c = e.link_->configure(profile::controller_config(p)); !c) return std::unexpected(located(c.error(), device));
    return e;
}

Embosser::Embosser(Embosser&&) noexcept = default;
Embosser& Embosser::operator=(Embosser&&) noexcept = default;
Embosser::~Embosser() = default;

Result<encode::Status> Embosser::status() { return link_->status(); }

void Embosser::simulate_unplug_after(double after_s, double seconds) {
    if (!sim_transport_) return;
    auto* t = static_cast<controller::SimTransport*>(sim_transport_);
    t->unplug_between(t->now() + after_s, t->now() + after_s + seconds);
}

}  // namespace tactus::gui
