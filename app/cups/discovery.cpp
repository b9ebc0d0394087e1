// SPDX-License-Identifier: GPL-3.0-or-later
#include "discovery.hpp"

#include <cstdio>

#include "cups_uri.hpp"
#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"

namespace tactus::cups {
namespace {

// Device IDs separate fields with ';' and keys with ':'; discovery lines quote
// with '"'. None of these may appear inside a value.
std::string id_value(std::string s) {
    for (char& c : s)
        if (c == ';' || c == ':' || c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
}

std::string quoted(std::string s) {
    for (char& c : s)
        if (c == '"' || c == '\\' || static_cast<unsigned char>(c) < 0x20) c = ' ';
    return '"' + s + '"';
}

std::string hex4(int v) {
    char b[8];
    std::snprintf(b, sizeof b, "%04x", v & 0xFFFF);
    return b;
}

std::string info(const transport::PortInfo& p) {
    std::string s = std::string(kMake) + " embosser on " + p.description;
    if (p.vid && p.pid) s += " (" + hex4(*p.vid) + ":" + hex4(*p.pid) + ")";
    return s;
}

}  // namespace

std::string device_id(const transport::PortInfo& p) {
    std::string id = std::string("MFG:") + kMake + ";MDL:" + kModel + ";CMD:TACTUS;CLS:PRINTER;DES:" +
                     id_value(info(p)) + ";";
    if (!p.serial_number.empty()) id += "SN:" + id_value(p.serial_number) + ";";
    return id;
}

std::string discovery_line(const transport::PortInfo& p) {
    const bool direct = p.kind == "usb-serial" || p.kind == "hid-uart" || p.kind == "lpt";
    return std::string(direct ? "direct " : "serial ") + uri_from_device(p.device) + " " +
           quoted(std::string(kMake) + " " + kModel) + " " + quoted(info(p)) + " " + quoted(device_id(p)) +
           " " + quoted("");
}

std::vector<transport::PortInfo> list_all_ports(std::vector<std::string>& warnings) {
    std::vector<transport::PortInfo> ports;
    for (auto lister : {transport::list_serial_ports, transport::list_hid_uarts, transport::list_parallel_ports}) {
        auto r = lister();
        if (r) ports.insert(ports.end(), r->begin(), r->end());
        else warnings.push_back(r.error().to_string());
    }
    return ports;
}

}  // namespace tactus::cups
