// SPDX-License-Identifier: GPL-3.0-or-later
// The hidapi backend of HidDevice: the real CP2110/FT260 on USB.
#include <hidapi.h>

#include <cwchar>
#include <mutex>

#include "transport/hid_uart.hpp"
#include "common/try.hpp"

namespace tactus::transport {
namespace {

std::string narrow(const wchar_t* w) {
    std::string s;
    if (!w) return s;
    for (; *w; ++w) s.push_back(*w < 128 ? static_cast<char>(*w) : '?');
    return s;
}

std::wstring widen(const std::string& s) { return std::wstring(s.begin(), s.end()); }

Result<void> ensure_init() {
    static std::once_flag once;
    static int rc = 0;
    std::call_once(once, [] { rc = hid_init(); });
    if (rc != 0) return fail(ErrorKind::device, "hidapi could not start", "hid");
    return {};
}

class HidapiDevice final : public HidDevice {
public:
    explicit HidapiDevice(hid_device* d) : d_(d) {}
    ~HidapiDevice() override { hid_close(d_); }
    HidapiDevice(const HidapiDevice&) = delete;
    HidapiDevice& operator=(const HidapiDevice&) = delete;

    Result<void> write_report(std::span<const std::uint8_t> report) override {
        if (hid_write(d_, report.data(), report.size()) < 0) return fail(ErrorKind::device, narrow(hid_error(d_)), "hid");
        return {};
    }
    Result<std::size_t> read_report(std::span<std::uint8_t> buffer, int timeout_ms) override {
        const int n = hid_read_timeout(d_, buffer.data(), buffer.size(), timeout_ms);
        if (n < 0) return fail(ErrorKind::device, narrow(hid_error(d_)), "hid");
        return static_cast<std::size_t>(n);
    }
    Result<void> send_feature(std::span<const std::uint8_t> report) override {
        if (hid_send_feature_report(d_, report.data(), report.size()) < 0)
            return fail(ErrorKind::device, narrow(hid_error(d_)), "hid");
        return {};
    }

private:
    hid_device* d_;
};

}  // namespace

Result<std::unique_ptr<ByteStream>> open_hid(const DeviceSpec& spec) {
    const std::string where = "hid:" + spec.path;
    // path = VID:PID[:serial], hexadecimal ids
    unsigned vid = 0, pid = 0;
    std::string serial;
    const auto c1 = spec.path.find(':');
    const auto c2 = c1 == std::string::npos ? std::string::npos : spec.path.find(':', c1 + 1);
    try {
        if (c1 == std::string::npos) throw std::invalid_argument("");
        std::size_t used = 0;
        vid = static_cast<unsigned>(std::stoul(spec.path.substr(0, c1), &used, 16));
        if (used != c1) throw std::invalid_argument("");
        const auto pid_text = spec.path.substr(c1 + 1, c2 == std::string::npos ? std::string::npos : c2 - c1 - 1);
        pid = static_cast<unsigned>(std::stoul(pid_text, &used, 16));
        if (used != pid_text.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
        // A malformed device string is the user's to fix (usage), not a device that is missing.
        return fail(ErrorKind::usage, "expected hid:VID:PID[:serial] with hexadecimal ids", where);
    }
    if (vid > 0xFFFF || pid > 0xFFFF) return fail(ErrorKind::usage, "USB ids are 16-bit", where);
    if (c2 != std::string::npos) serial = spec.path.substr(c2 + 1);
    const auto bridge = bridge_for(static_cast<std::uint16_t>(vid), static_cast<std::uint16_t>(pid));
    if (!bridge)
        return fail(ErrorKind::device, "not a supported HID-UART bridge (CP2110 10c4:ea80, CP2114 10c4:eab0, FT260 "
                    "0403:6030)",
                    where);
    TACTUS_TRY(uart, uart_settings(spec));
    TACTUS_TRY_VOID(ensure_init());
    auto opener = [vid, pid, serial, where]() -> Result<std::unique_ptr<HidDevice>> {
        const std::wstring wserial = widen(serial);
        hid_device* d = hid_open(static_cast<unsigned short>(vid), static_cast<unsigned short>(pid),
                                 serial.empty() ? nullptr : wserial.c_str());
        if (!d) {
            // Tell "absent" from "present but not ours to open".
            hid_device_info* list = hid_enumerate(static_cast<unsigned short>(vid),
                                                  static_cast<unsigned short>(pid));
            const bool present = list != nullptr;
            hid_free_enumeration(list);
            return fail(ErrorKind::device, present ? "busy or permission denied (check the udev rules for hidraw)"
                                : "no such device",
                        where);
        }
        return std::unique_ptr<HidDevice>(std::make_unique<HidapiDevice>(d));
    };
    TACTUS_TRY(h, HidUart::open(opener, *bridge, uart, where));
    return std::unique_ptr<ByteStream>(std::move(h));
}

Result<std::vector<PortInfo>> list_hid_uarts() {
    std::vector<PortInfo> out;
    TACTUS_TRY_VOID(ensure_init());
    hid_device_info* list = hid_enumerate(0, 0);
    for (auto* d = list; d; d = d->next) {
        const auto bridge = bridge_for(d->vendor_id, d->product_id);
        if (!bridge) continue;
        PortInfo p;
        char ids[16];
        std::snprintf(ids, sizeof ids, "%04x:%04x", d->vendor_id, d->product_id);
        p.serial_number = narrow(d->serial_number);
        p.device = std::string("hid:") + ids + (p.serial_number.empty() ? "" : ":" + p.serial_number);
        p.kind = "hid-uart";
        p.vid = d->vendor_id;
        p.pid = d->product_id;
        p.manufacturer = narrow(d->manufacturer_string);
        p.product = narrow(d->product_string);
        p.description = std::string(bridge_name(*bridge)) + " HID-UART bridge";
        out.push_back(std::move(p));
    }
    hid_free_enumeration(list);
    return out;
}

}  // namespace tactus::transport
