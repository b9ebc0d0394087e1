// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool_binding.hpp"

#include <chrono>
#include <thread>

#include <cstdlib>

#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "transport/device.hpp"

namespace tactus::cups {
namespace {

bool same_cable(std::string_view a, std::string_view b) {
    if (a == b) return true;
    const auto sa = transport::parse_device(a);
    const auto sb = transport::parse_device(b);
    return sa && sb && sa->scheme == sb->scheme && sa->path == sb->path;
}

Result<std::optional<spool::PrinterRecord>> find(spool::Spool& s, std::string_view device) {
    auto all = s.printers();
    if (!all) return std::unexpected(all.error());
    for (const auto& p : *all)
        if (same_cable(p.device, device)) return std::optional<spool::PrinterRecord>(p);
    return std::optional<spool::PrinterRecord>{};
}

}  // namespace

std::filesystem::path cups_spool_path() {
    if (const char* v = std::getenv("TACTUS_SPOOL_DB"); v && *v) return v;
    return kSystemSpool;
}

Result<spool::Spool> open_cups_spool() {
    const auto path = cups_spool_path();
    auto opened = spool::Spool::open(path, {.create = true});
    for (int attempt = 1; !opened && attempt < 20; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        opened = spool::Spool::open(path, {.create = true});
    }
    return opened;
}

Result<spool::PrinterRecord> bind_printer(spool::Spool& s, std::string_view device, std::string_view queue_name) {
    auto found = find(s, device);
    if (!found) return std::unexpected(found.error());
    if (*found) return **found;
    const std::string name = queue_name.empty() ? std::string("Embosser") : std::string(queue_name);
    if (auto same_name = s.printer(name); same_name)
        return fail(ErrorKind::usage, "the spool's printer '" + name + "' is on " + same_name->device + ", but this CUPS queue is on " +
                        std::string(device) + "; change one of them (tactus-cli queue printer set " + name +
                        " --device ...) so they name the same cable",
                    s.path().string());
    auto added = s.add_printer(name, device, profile::to_json(profile::default_profile()).dump(2));
    if (added) return added;
    // The filter and the backend of one job may both add it at once: the
    // loser finds the winner's printer.
    if (auto again = find(s, device); again && *again) return **again;
    return added;
}

}  // namespace tactus::cups
