// SPDX-License-Identifier: GPL-3.0-or-later
// The libieee1284 backend of ParallelPortLines: the real port via ppdev or
// direct I/O, whichever libieee1284 finds. Without libieee1284
// (TACTUS_WITH_PARALLEL off) only the registered cables remain.
#if TACTUS_HAVE_PARALLEL
#include <ieee1284.h>
#else
#include "common/unavailable.hpp"
#endif

#include <thread>

#include "transport/lpt_port.hpp"
#include "common/try.hpp"

namespace tactus::transport {
#if TACTUS_HAVE_PARALLEL
namespace {

std::string error_text(int rc) {
    switch (rc) {
        case E1284_NOTAVAIL: return "not available on this port";
        case E1284_INIT: return "cannot open the port (permission denied? add yourself to the lp group)";
        case E1284_NOMEM: return "out of memory";
        case E1284_SYS: return "system error";
        case E1284_TIMEDOUT: return "timed out";
        case E1284_REJECTED: return "rejected by the peripheral";
        case E1284_NEGFAILED: return "negotiation failed";
        case E1284_NOID: return "no device id";
        case E1284_INVALIDPORT: return "invalid port";
        default: return "error " + std::to_string(rc);
    }
}

class Ieee1284Lines final : public ParallelPortLines {
public:
    explicit Ieee1284Lines(parport* p) : p_(p) {}
    ~Ieee1284Lines() override {
        ieee1284_release(p_);
        ieee1284_close(p_);
        ieee1284_unref(p_);
    }
    Ieee1284Lines(const Ieee1284Lines&) = delete;
    Ieee1284Lines& operator=(const Ieee1284Lines&) = delete;

    Result<void> write_data(std::uint8_t v) override {
        ieee1284_write_data(p_, v);
        return {};
    }
    Result<void> write_control(const LptControl& c) override {
        // Logical line levels to register bits; the inverted ones are flipped here.
        int v = (c.n_strobe ? C1284_NSTROBE : 0) | (c.n_auto_fd ? C1284_NAUTOFD : 0) |
                (c.n_init ? C1284_NINIT : 0) | (c.n_select_in ? C1284_NSELECTIN : 0);
        ieee1284_write_control(p_, static_cast<unsigned char>(v ^ C1284_INVERTED));
        return {};
    }
    Result<LptStatus> read_status() override {
        const int raw = ieee1284_read_status(p_);
        if (raw < 0) return fail(ErrorKind::device, error_text(raw), "lpt");
        const int v = raw ^ S1284_INVERTED;
        return LptStatus{(v & S1284_NACK) != 0, (v & S1284_BUSY) != 0, (v & S1284_PERROR) != 0,
                         (v & S1284_SELECT) != 0, (v & S1284_NFAULT) != 0};
    }
    void settle() override { std::this_thread::sleep_for(std::chrono::microseconds(1)); }

private:
    parport* p_;
};

// How a port is named in a device string: its ppdev node (/dev/parport0), or
// for a port libieee1284 drives by direct I/O (through /dev/port) its address.
std::string port_name(const parport* p) {
    const std::string file = p->filename ? p->filename : "";
    if (!file.empty() && file != "/dev/port") return file;
    return p->name ? p->name : "?";
}

std::string port_list(const parport_list& list) {
    std::string s;
    for (int i = 0; i < list.portc; ++i) {
        if (!s.empty()) s += ", ";
        s += port_name(list.portv[i]);
    }
    return s.empty() ? "none found" : s;
}

}  // namespace
#endif

Result<std::unique_ptr<ByteStream>> open_lpt(const DeviceSpec& spec) {
    const std::string where = "lpt:" + spec.path;
    if (const LptCable* cable = registered_lpt_cable(spec)) {
        auto opener = [open = cable->open, spec] { return open(spec); };
        auto p = LptPort::open(opener, where, cable->timings);
        if (!p) return std::unexpected(p.error());
        return std::unique_ptr<ByteStream>(std::move(*p));
    }
    if (!spec.options.empty()) return fail(ErrorKind::usage, "lpt takes no options", where);
#if !TACTUS_HAVE_PARALLEL
    return unavailable("the parallel port (lpt:)", "libieee1284", where);
#else
    const std::string wanted = spec.path;
    auto opener = [wanted, where]() -> Result<std::unique_ptr<ParallelPortLines>> {
        parport_list list{};
        if (ieee1284_find_ports(&list, 0) != E1284_OK) return fail(ErrorKind::device, "cannot list parallel ports", where);
        parport* found = nullptr;
        for (int i = 0; i < list.portc; ++i) {
            const std::string name = list.portv[i]->name ? list.portv[i]->name : "";
            if (wanted == name || wanted == port_name(list.portv[i]) || "/dev/" + name == wanted)
                found = list.portv[i];
        }
        if (!found) {
            const auto ports = port_list(list);
            ieee1284_free_ports(&list);
            return fail(ErrorKind::device, "no such device (parallel ports: " + ports + ")", where);
        }
        ieee1284_ref(found);
        ieee1284_free_ports(&list);
        int caps = 0;
        if (const int rc = ieee1284_open(found, F1284_EXCL, &caps); rc != E1284_OK) {
            ieee1284_unref(found);
            return fail(ErrorKind::device, error_text(rc), where);
        }
        if (const int rc = ieee1284_claim(found); rc != E1284_OK) {
            ieee1284_close(found);
            ieee1284_unref(found);
            return fail(ErrorKind::device, "busy (claimed by another driver or program): " + error_text(rc), where);
        }
        return std::unique_ptr<ParallelPortLines>(std::make_unique<Ieee1284Lines>(found));
    };
    TACTUS_TRY(p, LptPort::open(opener, where));
    return std::unique_ptr<ByteStream>(std::move(p));
#endif
}

Result<std::vector<PortInfo>> list_parallel_ports() {
#if !TACTUS_HAVE_PARALLEL
    return unavailable("listing parallel ports", "libieee1284");
#else
    parport_list list{};
    if (ieee1284_find_ports(&list, 0) != E1284_OK) return std::vector<PortInfo>{};
    std::vector<PortInfo> out;
    for (int i = 0; i < list.portc; ++i) {
        PortInfo p;
        p.device = "lpt:" + port_name(list.portv[i]);
        p.kind = "lpt";
        p.description = std::string("parallel port ") + list.portv[i]->name;
        out.push_back(std::move(p));
    }
    ieee1284_free_ports(&list);
    return out;
#endif
}

}  // namespace tactus::transport
