// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/serial_port.hpp"
#include "common/try.hpp"

#include <libserialport.h>

#include <cstring>

namespace tactus::transport {
namespace {

std::string sp_error(sp_return r) {
    if (r == SP_ERR_FAIL) {
        char* msg = sp_last_error_message();
        std::string s = msg ? msg : "unknown failure";
        sp_free_error_message(msg);
        const int code = sp_last_error_code();
        if (code == ENOENT || code == ENODEV || code == ENXIO) return "no such device";
        if (code == EACCES || code == EPERM)
            return "permission denied (is your user in the dialout group?)";
        if (code == EBUSY) return "busy (in use by another program)";
        return s;
    }
    if (r == SP_ERR_ARG) return "invalid argument (no such port?)";
    if (r == SP_ERR_SUPP) return "not supported by this port";
    if (r == SP_ERR_MEM) return "out of memory";
    return "error " + std::to_string(static_cast<int>(r));
}

std::string str(const char* s) { return s ? s : ""; }

}  // namespace

Result<std::unique_ptr<SerialPort>> SerialPort::open(const std::string& path,
                                                     const UartSettings& uart) {
    std::unique_ptr<SerialPort> p(new SerialPort(path, uart));
    TACTUS_TRY_VOID(p->open_port());
    return p;
}

SerialPort::~SerialPort() { close_port(); }

void SerialPort::close_port() {
    if (!port_) return;
    sp_close(port_);
    sp_free_port(port_);
    port_ = nullptr;
}

Result<void> SerialPort::open_port() {
    const std::string where = "serial:" + path_;
    if (auto r = sp_get_port_by_name(path_.c_str(), &port_); r != SP_OK) {
        port_ = nullptr;
        return fail(ErrorKind::device, r == SP_ERR_ARG ? "no such device" : sp_error(r), where);
    }
    if (auto r = sp_open(port_, SP_MODE_READ_WRITE); r != SP_OK) {
        const auto msg = sp_error(r);
        sp_free_port(port_);
        port_ = nullptr;
        return fail(ErrorKind::device, msg, where);
    }
    const sp_parity parity = uart_.parity == 'o'   ? SP_PARITY_ODD
                             : uart_.parity == 'e' ? SP_PARITY_EVEN
                                                   : SP_PARITY_NONE;
    const sp_flowcontrol flow = uart_.flow == UartSettings::Flow::rtscts    ? SP_FLOWCONTROL_RTSCTS
                                : uart_.flow == UartSettings::Flow::xonxoff ? SP_FLOWCONTROL_XONXOFF
                                                                            : SP_FLOWCONTROL_NONE;
    sp_return r = sp_set_baudrate(port_, uart_.baud);
    if (r == SP_OK) r = sp_set_bits(port_, 8);
    if (r == SP_OK) r = sp_set_parity(port_, parity);
    if (r == SP_OK) r = sp_set_stopbits(port_, uart_.stop_bits);
    if (r == SP_OK) r = sp_set_flowcontrol(port_, flow);
    if (r != SP_OK) {
        const auto msg = sp_error(r);
        close_port();
        return fail(ErrorKind::device, "cannot configure the line: " + msg, where);
    }
    return {};
}

Result<void> SerialPort::reopen() {
    close_port();
    return open_port();
}

double SerialPort::bytes_per_second() const {
    return uart_.bytes_per_second();
}

Result<void> SerialPort::write(std::span<const std::uint8_t> bytes) {
    const std::string where = "serial:" + path_;
    if (!port_) return fail(ErrorKind::device, "device not open", where);
    const auto n = sp_blocking_write(port_, bytes.data(), bytes.size(), 2000);
    if (n < 0) return fail(ErrorKind::device, "device disconnected: " + sp_error(n), where);
    if (static_cast<std::size_t>(n) != bytes.size()) return fail(ErrorKind::device, "write timed out (flow control?)", where);
    return {};
}

Result<std::size_t> SerialPort::read(std::span<std::uint8_t> buffer,
                                     std::chrono::microseconds timeout) {
    const std::string where = "serial:" + path_;
    if (!port_) return fail(ErrorKind::device, "device not open", where);
    const auto ms = static_cast<unsigned>((timeout.count() + 999) / 1000);
    // Wait for the first byte, then take whatever else is already there.
    auto n = sp_blocking_read_next(port_, buffer.data(), buffer.size(), ms == 0 ? 1 : ms);
    if (n < 0) return fail(ErrorKind::device, "device disconnected: " + sp_error(n), where);
    return static_cast<std::size_t>(n);
}

Result<std::vector<PortInfo>> list_serial_ports() {
    sp_port** ports = nullptr;
    if (auto r = sp_list_ports(&ports); r != SP_OK) return fail(ErrorKind::device, sp_error(r), "serial ports");
    std::vector<PortInfo> out;
    for (sp_port** p = ports; *p; ++p) {
        PortInfo info;
        const std::string name = str(sp_get_port_name(*p));
        info.device = "serial:" + name;
        info.description = str(sp_get_port_description(*p));
        switch (sp_get_port_transport(*p)) {
            case SP_TRANSPORT_USB: {
                info.kind = "usb-serial";
                int vid = 0, pid = 0;
                if (sp_get_port_usb_vid_pid(*p, &vid, &pid) == SP_OK) {
                    info.vid = vid;
                    info.pid = pid;
                }
                info.serial_number = str(sp_get_port_usb_serial(*p));
                info.manufacturer = str(sp_get_port_usb_manufacturer(*p));
                info.product = str(sp_get_port_usb_product(*p));
                break;
            }
            case SP_TRANSPORT_BLUETOOTH: info.kind = "bluetooth"; break;
            default: info.kind = "native"; break;
        }
        out.push_back(std::move(info));
    }
    sp_free_port_list(ports);
    return out;
}

}  // namespace tactus::transport
