// SPDX-License-Identifier: GPL-3.0-or-later
#include "controller/device_choices.hpp"

#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"
#include "transport/serial_port.hpp"

namespace tactus::controller {

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

}  // namespace tactus::controller
