// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/printer_setup.hpp"

#include "common/try.hpp"

namespace tactus::spool {

std::string printer_name_for_device(std::string_view device) {
    const std::string head(device.substr(0, device.find('?')));
    const auto colon = head.find(':');
    const std::string scheme = head.substr(0, colon);
    std::string path = colon == std::string::npos ? "" : head.substr(colon + 1);
    if (path.rfind("/dev/", 0) == 0) path.erase(0, 5);
    while (!path.empty() && path.front() == '/') path.erase(0, 1);
    std::string name = path.empty() ? scheme : (scheme == "hid" ? "hid-" + path : path);
    for (char& c : name)
        if (c == ':' || c == '/' || c == ' ') c = '-';
    return name;
}

Result<PrinterRecord> printer_for_device(Spool& spool, std::string_view device, std::string_view profile_json,
                                         bool* created) {
    if (created) *created = false;
    TACTUS_TRY(all, spool.printers());
    for (const auto& p : all)
        if (p.device == device) return p;
    const std::string base = printer_name_for_device(device);
    std::string name = base;
    for (int n = 2; spool.printer(name); ++n) name = base + "-" + std::to_string(n);
    TACTUS_TRY(added, spool.add_printer(name, device, profile_json));
    if (created) *created = true;
    return added;
}

}  // namespace tactus::spool
