// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli ports: every cable an embosser could be on, as device strings.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"
#include "transport/serial_port.hpp"

namespace tactus::cli {
namespace {

std::string hex4(int v) {
    char b[8];
    std::snprintf(b, sizeof b, "%04x", v & 0xFFFF);
    return b;
}

void run_ports(bool json) {
    std::vector<transport::PortInfo> ports;
    std::vector<std::string> warnings;
    for (auto lister : {transport::list_serial_ports, transport::list_hid_uarts,
                        transport::list_parallel_ports}) {
        auto r = lister();
        if (r) ports.insert(ports.end(), r->begin(), r->end());
        else warnings.push_back(r.error().to_string());
    }
    for (const auto& w : warnings) std::cerr << "tactus-cli: warning: " << w << '\n';
    if (json) {
        auto arr = nlohmann::json::array();
        for (const auto& p : ports) {
            nlohmann::json j{{"device", p.device}, {"kind", p.kind}, {"description", p.description}};
            if (p.vid) j["vid"] = hex4(*p.vid);
            if (p.pid) j["pid"] = hex4(*p.pid);
            if (!p.serial_number.empty()) j["serial"] = p.serial_number;
            if (!p.manufacturer.empty()) j["manufacturer"] = p.manufacturer;
            if (!p.product.empty()) j["product"] = p.product;
            arr.push_back(j);
        }
        arr.push_back({{"device", "sim"}, {"kind", "sim"}, {"description", "built-in simulated controller"}});
        std::cout << arr.dump(2) << '\n';
        return;
    }
    for (const auto& p : ports) {
        std::cout << p.device << "  [" << p.kind << "] " << p.description;
        if (p.vid && p.pid) std::cout << "  " << hex4(*p.vid) << ':' << hex4(*p.pid);
        if (!p.serial_number.empty()) std::cout << "  serial " << p.serial_number;
        std::cout << '\n';
    }
    std::cout << "sim  [sim] built-in simulated controller\n";
}

}  // namespace

void add_ports_command(CLI::App& app) {
    auto json = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("ports", "List serial, HID-UART and parallel ports an embosser may be on");
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->callback([json] { run_ports(*json); });
}

}  // namespace tactus::cli
