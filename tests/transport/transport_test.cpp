// SPDX-License-Identifier: GPL-3.0-or-later
// Transports on both sides of the hardware boundary: HID-UART report framing
// against fake CP2110 and FT260 chips written from their datasheets, the LPT
// handshakes against the controller's peripheral model, a real pty, device
// strings, and absent devices.
#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <random>

#include "controller/lpt_peripheral.hpp"
#include "controller/sim_controller.hpp"
#include "link/link.hpp"
#include "../common/test_plans.hpp"
#include "transport/device.hpp"
#include "transport/hid_uart.hpp"
#include "transport/lpt_port.hpp"
#include "transport/tty_port.hpp"

namespace tactus::transport {
namespace {

double wall() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// ---------------------------------------------------------------- HID

// The bridge chip as the datasheets describe it, wired to the simulated
// controller's UART. Written independently of hid_report so the two sides
// check each other.
class FakeBridge final : public HidDevice {
public:
    FakeBridge(HidBridge chip, std::shared_ptr<controller::SimController> ctl) : chip_(chip), ctl_(std::move(ctl)) {}

    Result<void> write_report(std::span<const std::uint8_t> r) override {
        if (!uart_enabled_) return fail(ErrorKind::device, "UART not enabled", "fake");
        std::vector<std::uint8_t> data;
        if (chip_ == HidBridge::cp2110) {
            if (r.empty() || r[0] < 1 || r[0] > 63 || r.size() != 1U + r[0]) return fail(ErrorKind::protocol, "bad CP2110 report", "fake");
            data.assign(r.begin() + 1, r.end());
        } else {
            if (r.size() < 2 || r[0] < 0xF0 || r[0] > 0xFE) return fail(ErrorKind::protocol, "bad FT260 report id", "fake");
            const std::size_t cap = 4U * (r[0] - 0xF0U + 1U);
            if (r[1] == 0 || r[1] > cap || r.size() != 2 + cap) return fail(ErrorKind::protocol, "bad FT260 report size", "fake");
            data.assign(r.begin() + 2, r.begin() + 2 + r[1]);
        }
        reports_out_.push_back(std::vector<std::uint8_t>(r.begin(), r.end()));
        ctl_->receive(data, wall() - t0_);
        return {};
    }
    Result<std::size_t> read_report(std::span<std::uint8_t> buf, int timeout_ms) override {
        const double until = wall() + timeout_ms / 1000.0;
        do {
            ctl_->advance(wall() - t0_);
            for (auto b : ctl_->take_output()) pending_.push_back(b);
            if (!pending_.empty()) break;
        } while (wall() < until);
        if (pending_.empty()) return std::size_t{0};
        const std::size_t max = chip_ == HidBridge::cp2110 ? 63 : 60;
        const std::size_t n = std::min(max, pending_.size());
        std::size_t at = 0;
        if (chip_ == HidBridge::cp2110) {
            buf[at++] = static_cast<std::uint8_t>(n);
        } else {
            buf[at++] = static_cast<std::uint8_t>(0xF0 + (n - 1) / 4);
            buf[at++] = static_cast<std::uint8_t>(n);
        }
        for (std::size_t i = 0; i < n; ++i) {
            buf[at++] = pending_.front();
            pending_.pop_front();
        }
        return at;
    }
    Result<void> send_feature(std::span<const std::uint8_t> r) override {
        features_.push_back(std::vector<std::uint8_t>(r.begin(), r.end()));
        if (chip_ == HidBridge::cp2110) {
            if (r[0] == 0x41 && r.size() == 2) uart_enabled_ = r[1] == 1;
            if (r[0] == 0x50 && r.size() == 9) baud_ = (r[1] << 24) | (r[2] << 16) | (r[3] << 8) | r[4];
        } else if (r[0] == 0xA1 && r.size() >= 2) {
            if (r[1] == 0x03) uart_enabled_ = true;
            if (r[1] == 0x41 && r.size() == 11) baud_ = r[3] | (r[4] << 8) | (r[5] << 16) | (r[6] << 24);
        }
        return {};
    }

    HidBridge chip_;
    std::shared_ptr<controller::SimController> ctl_;
    double t0_ = wall();
    bool uart_enabled_ = false;
    int baud_ = 0;
    std::deque<std::uint8_t> pending_;
    std::vector<std::vector<std::uint8_t>> reports_out_, features_;
};

TEST(HidReports, Cp2110FramingAtTheLengthBoundaries) {
    std::vector<std::uint8_t> data(130);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i);
    const auto reports = hid_report::uart_out(HidBridge::cp2110, data);
    ASSERT_EQ(reports.size(), 3U);
    EXPECT_EQ(reports[0][0], 63);
    EXPECT_EQ(reports[2][0], 4);
    EXPECT_EQ(reports[2].size(), 5U);
    std::vector<std::uint8_t> back;
    for (const auto& r : reports) {
        auto d = hid_report::uart_in(HidBridge::cp2110, r);
        ASSERT_TRUE(d);
        back.insert(back.end(), d->begin(), d->end());
    }
    EXPECT_EQ(back, data);
    EXPECT_FALSE(hid_report::uart_in(HidBridge::cp2110, std::vector<std::uint8_t>{10, 1, 2}));  // short
    EXPECT_TRUE(hid_report::uart_in(HidBridge::cp2110, std::vector<std::uint8_t>{0x42, 0})->empty());
}

TEST(HidReports, Ft260SizeClasses) {
    for (std::size_t n : {1U, 4U, 5U, 59U, 60U, 61U}) {
        std::vector<std::uint8_t> data(n, 0xAB);
        const auto reports = hid_report::uart_out(HidBridge::ft260, data);
        const auto& r = reports[0];
        const std::size_t first = std::min<std::size_t>(n, 60);
        EXPECT_EQ(r[0], 0xF0 + (first - 1) / 4) << n;
        EXPECT_EQ(r[1], first);
        EXPECT_EQ(r.size(), 2 + 4 * ((first - 1) / 4 + 1));
    }
    EXPECT_FALSE(hid_report::uart_in(HidBridge::ft260, std::vector<std::uint8_t>{0xF0, 9, 1, 2, 3, 4, 5}));
}

TEST(HidReports, UartSetupReports) {
    UartSettings u;
    u.baud = 57600;
    u.parity = 'e';
    const auto cp = hid_report::uart_setup(HidBridge::cp2110, u);
    ASSERT_EQ(cp.size(), 3U);
    EXPECT_EQ(cp[1], (std::vector<std::uint8_t>{0x50, 0x00, 0x00, 0xE1, 0x00, 2, 0, 3, 0}));
    const auto ft = hid_report::uart_setup(HidBridge::ft260, u);
    EXPECT_EQ(ft[1], (std::vector<std::uint8_t>{0xA1, 0x41, 4, 0x00, 0xE1, 0x00, 0x00, 8, 2, 0, 0}));
    EXPECT_EQ(bridge_for(0x10C4, 0xEA80), HidBridge::cp2110);
    EXPECT_EQ(bridge_for(0x0403, 0x6030), HidBridge::ft260);
    EXPECT_FALSE(bridge_for(0x0403, 0x6001));
}

class HidEndToEnd : public ::testing::TestWithParam<HidBridge> {};

TEST_P(HidEndToEnd, JobThroughTheBridge) {
    controller::SimOptions so;
    so.instant_motion = true;
    auto ctl = std::make_shared<controller::SimController>(so);
    FakeBridge* chip = nullptr;
    UartSettings u;
    u.baud = 115200;
    auto uart = HidUart::open(
        [&]() -> Result<std::unique_ptr<HidDevice>> {
            auto d = std::make_unique<FakeBridge>(GetParam(), ctl);
            chip = d.get();
            return std::unique_ptr<HidDevice>(std::move(d));
        },
        GetParam(), u, "hid:test");
    ASSERT_TRUE(uart) << uart.error().to_string();
    EXPECT_EQ(chip->baud_, 115200);
    EXPECT_TRUE(chip->uart_enabled_);
    auto link = link::Link::over(std::move(*uart));
    ASSERT_TRUE(link.hello());
    const auto plan = test::make_plan(1, 4, 12);
    link::CancelToken cancel;
    auto out = link.send_job(plan, 1, {}, cancel);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->end, link::JobEnd::completed) << out->error.to_string();
    EXPECT_EQ(ctl->strike_log(), controller::planned_strikes(plan));
    EXPECT_GT(chip->reports_out_.size(), 4U);
}
INSTANTIATE_TEST_SUITE_P(Chips, HidEndToEnd, ::testing::Values(HidBridge::cp2110, HidBridge::ft260),
                         [](const auto& p) { return std::string(p.param == HidBridge::cp2110 ? "CP2110" : "FT260"); });

// ---------------------------------------------------------------- LPT

// The cable: the host's lines on one side, the controller's port firmware on the other.
class Cable final : public ParallelPortLines {
public:
    explicit Cable(controller::LptPeripheral& p) : p_(p) {}
    Result<void> write_data(std::uint8_t v) override {
        p_.set_data(v);
        return {};
    }
    Result<void> write_control(const LptControl& c) override {
        p_.set_control(c);
        return {};
    }
    Result<LptStatus> read_status() override { return p_.status(); }
    void settle() override {
        p_.tick();
        if (on_tick) on_tick();
    }
    std::function<void()> on_tick;

private:
    controller::LptPeripheral& p_;
};

Result<std::unique_ptr<LptPort>> open_cable(controller::LptPeripheral& p, std::function<void()> on_tick = {}) {
    return LptPort::open(
        [&p, on_tick]() -> Result<std::unique_ptr<ParallelPortLines>> {
            auto c = std::make_unique<Cable>(p);
            c->on_tick = on_tick;
            return std::unique_ptr<ParallelPortLines>(std::move(c));
        },
        "lpt:test");
}

TEST(Lpt, CompatibilityModeDeliversEveryByteInOrder) {
    controller::LptPeripheral per;
    auto port = open_cable(per);
    ASSERT_TRUE(port);
    std::vector<std::uint8_t> data(300);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7);
    ASSERT_TRUE((*port)->write(data));
    EXPECT_EQ(per.take_received(), data);
}

TEST(Lpt, NibbleModeReadsTheControllersBytes) {
    controller::LptPeripheral per;
    auto port = open_cable(per);
    ASSERT_TRUE(port);
    const std::vector<std::uint8_t> reply{0x7E, 0x00, 0xFF, 0xA5, 0x5A, 0x01};
    per.send(reply);
    std::array<std::uint8_t, 64> buf{};
    auto n = (*port)->read(buf, std::chrono::milliseconds(10));
    ASSERT_TRUE(n) << n.error().to_string();
    EXPECT_EQ(std::vector<std::uint8_t>(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(*n)), reply);
    // Back in compatibility mode afterwards: forward bytes still go through.
    const std::vector<std::uint8_t> more{1, 2, 3};
    ASSERT_TRUE((*port)->write(more));
    EXPECT_EQ(per.take_received(), more);
    // Nothing to send: the read times out with no bytes.
    n = (*port)->read(buf, std::chrono::milliseconds(2));
    ASSERT_TRUE(n);
    EXPECT_EQ(*n, 0U);
}

TEST(Lpt, StatusLinesCarryTheCondition) {
    controller::LptPeripheral per;
    auto port = open_cable(per);
    ASSERT_TRUE(port);
    per.set_condition(true, false, true);
    auto c = (*port)->condition();
    ASSERT_TRUE(c);
    EXPECT_TRUE(c->paper_out);
    EXPECT_FALSE(c->fault);
    per.set_condition(false, true, false);
    c = (*port)->condition();
    EXPECT_FALSE(c->paper_out);
    EXPECT_TRUE(c->fault);
    EXPECT_FALSE(c->online);
}

// A peripheral that never answers: Busy stuck high (from the first data
// byte on, when `after_data`; else from the start, as a pulled cable).
class DeadLines final : public ParallelPortLines {
public:
    explicit DeadLines(bool after_data) : busy_(!after_data) {}
    Result<void> write_data(std::uint8_t) override {
        busy_ = true;
        return {};
    }
    Result<void> write_control(const LptControl&) override { return {}; }
    Result<LptStatus> read_status() override { return LptStatus{true, busy_, false, false, true}; }
    void settle() override {}

private:
    bool busy_;
};

Result<std::unique_ptr<LptPort>> open_dead(bool after_data) {
    return LptPort::open([after_data]() -> Result<std::unique_ptr<ParallelPortLines>> {
        return std::unique_ptr<ParallelPortLines>(std::make_unique<DeadLines>(after_data));
    }, "lpt:dead", LptTimings{std::chrono::milliseconds(20)});
}

TEST(Lpt, StuckBusyIsABoundedError) {
    // Busy from the start: no controller is found on the port (a reconnect
    // keeps trying rather than failing on its first byte).
    auto none = open_dead(false);
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().message.find("no controller ready on the port (Busy stays high"), std::string::npos)
        << none.error().message;
    // Ready at first, then Busy stuck: the byte fails within the handshake time.
    auto port = open_dead(true);
    ASSERT_TRUE(port) << port.error().to_string();
    const std::vector<std::uint8_t> b{1, 2};
    auto r = (*port)->write(b);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("Busy"), std::string::npos);
}

TEST(Lpt, JobOverTheParallelPort) {
    controller::SimOptions so;
    so.instant_motion = true;
    controller::SimController ctl(so);
    controller::LptPeripheral per;
    const double t0 = wall();
    // The firmware's main loop: port bytes to the protocol, replies to the port.
    auto firmware = [&] {
        const auto in = per.take_received();
        if (!in.empty()) ctl.receive(in, wall() - t0);
        ctl.advance(wall() - t0);
        const auto out = ctl.take_output();
        if (!out.empty()) per.send(out);
    };
    auto port = open_cable(per, firmware);
    ASSERT_TRUE(port);
    auto link = link::Link::over(std::move(*port));
    ASSERT_TRUE(link.hello());
    const auto plan = test::make_plan(1, 3, 8);
    link::CancelToken cancel;
    auto out = link.send_job(plan, 1, {}, cancel);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->end, link::JobEnd::completed) << out->error.to_string();
    EXPECT_EQ(ctl.strike_log(), controller::planned_strikes(plan));
}

// ---------------------------------------------------------------- pty and device strings

TEST(Pty, RawBytesBothWays) {
    int master = -1, slave = -1;
    char name[128];
    ASSERT_EQ(openpty(&master, &slave, name, nullptr, nullptr), 0);
    auto port = TtyPort::open(name, UartSettings{});
    ASSERT_TRUE(port) << port.error().to_string();
    // Every byte value passes untouched (raw mode: no CR/LF mapping, no signals).
    std::vector<std::uint8_t> all(256);
    for (int i = 0; i < 256; ++i) all[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
    ASSERT_TRUE((*port)->write(all));
    std::vector<std::uint8_t> got;
    std::array<std::uint8_t, 512> buf{};
    while (got.size() < all.size()) {
        const auto n = ::read(master, buf.data(), buf.size());
        ASSERT_GT(n, 0);
        got.insert(got.end(), buf.begin(), buf.begin() + n);
    }
    EXPECT_EQ(got, all);
    ASSERT_EQ(::write(master, all.data(), all.size()), 256);
    got.clear();
    while (got.size() < all.size()) {
        auto n = (*port)->read(buf, std::chrono::milliseconds(500));
        ASSERT_TRUE(n);
        ASSERT_GT(*n, 0U);
        got.insert(got.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(*n));
    }
    EXPECT_EQ(got, all);
    // A second opener is refused: the line is ours.
    auto second = TtyPort::open(name, UartSettings{});
    ASSERT_FALSE(second);
    EXPECT_NE(second.error().message.find("busy"), std::string::npos);
    // The other end goes away: a clear error, not a hang.
    ::close(master);
    ::close(slave);
    auto n = (*port)->read(buf, std::chrono::milliseconds(200));
    ASSERT_FALSE(n);
    EXPECT_NE(n.error().message.find("disconnected"), std::string::npos);
}

TEST(Device, ParsesDeviceStrings) {
    auto s = parse_device("serial:/dev/ttyUSB0?baud=57600&parity=none&flow=rtscts");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->scheme, "serial");
    EXPECT_EQ(s->path, "/dev/ttyUSB0");
    auto u = uart_settings(*s);
    ASSERT_TRUE(u);
    EXPECT_EQ(u->baud, 57600);
    EXPECT_EQ(u->flow, UartSettings::Flow::rtscts);
    s = parse_device("hid:10c4:ea80:ABC123");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->path, "10c4:ea80:ABC123");
    EXPECT_TRUE(parse_device("sim"));
}

// format_device is parse_device's inverse: over random device strings built
// from the characters they use, every string that parses is written back to
// one that parses to the same spec (and is itself if its options came in key
// order without repeats).
TEST(Device, FormatIsTheInverseOfParse) {
    std::mt19937 rng(11);
    const std::string schemes[] = {"serial", "pty", "hid", "lpt", "sim", "usb", ""};
    const std::string alphabet = "ab09/:.=&?-_";
    const auto word = [&](std::size_t most) {
        std::string w;
        for (std::size_t n = rng() % (most + 1); n > 0; --n) w += alphabet[rng() % alphabet.size()];
        return w;
    };
    int parsed = 0;
    for (int i = 0; i < 5000; ++i) {
        std::string text = schemes[rng() % std::size(schemes)];
        if (rng() % 4 != 0) text += ":" + word(12);
        if (rng() % 2 == 0) text += "?" + word(3) + "=" + word(4) + (rng() % 2 ? "&" + word(3) + "=" + word(3) : "");
        const auto spec = parse_device(text);
        if (!spec) continue;
        ++parsed;
        const auto written = format_device(*spec);
        const auto again = parse_device(written);
        ASSERT_TRUE(again) << text << " -> " << written << ": " << again.error().to_string();
        EXPECT_EQ(again->scheme, spec->scheme) << text;
        EXPECT_EQ(again->path, spec->path) << text;
        EXPECT_EQ(again->options, spec->options) << text << " -> " << written;
        EXPECT_EQ(format_device(*again), written) << text;
    }
    EXPECT_GT(parsed, 1000);
    EXPECT_EQ(format_device(*parse_device("sim?speed=10&baud=9600")), "sim?baud=9600&speed=10");
    EXPECT_EQ(format_device(*parse_device("hid:10c4:ea80:ABC123")), "hid:10c4:ea80:ABC123");
    EXPECT_EQ(format_device(*parse_device("sim")), "sim");
}

// Each device type, with and without options, on the paths and values users
// have: by-id serial paths with spaces, percent signs, '#' and non-ASCII
// names, option values holding '=', ':' or '?', options out of key order.
// parse -> format -> parse keeps the spec; format writes the options in key
// order and the rest of the string as typed.
TEST(Device, FormatKeepsEveryTypesPathAndOptions) {
    struct Case {
        std::string text, written;
    };
    const Case cases[] = {
        {"sim", "sim"},
        {"sim?speed=max", "sim?speed=max"},
        {"sim?speed=10&baud=9600&seed=7", "sim?baud=9600&seed=7&speed=10"},
        {"sim?noise=1e-3&paper-reload=5&protocol=2", "sim?noise=1e-3&paper-reload=5&protocol=2"},
        {"serial:/dev/ttyUSB0", "serial:/dev/ttyUSB0"},
        {"serial:/dev/ttyUSB0?parity=none&flow=rtscts&baud=57600",
         "serial:/dev/ttyUSB0?baud=57600&flow=rtscts&parity=none"},
        {"serial:/dev/serial/by-id/usb-FTDI_FT232R USB UART_A50285BI-if00-port0?baud=9600",
         "serial:/dev/serial/by-id/usb-FTDI_FT232R USB UART_A50285BI-if00-port0?baud=9600"},
        {"serial:/dev/serial/by-id/usb-Pr\xc3\xa4gemaschine_#2_100%-if00", "serial:/dev/serial/by-id/usb-Pr\xc3\xa4gemaschine_#2_100%-if00"},
        {"serial:COM3?stop=2", "serial:COM3?stop=2"},
        {"pty:/dev/pts/3", "pty:/dev/pts/3"},
        {"pty:/dev/pts/3?baud=115200", "pty:/dev/pts/3?baud=115200"},
        {"hid:10c4:ea80", "hid:10c4:ea80"},
        {"hid:10c4:ea80:ABC123?baud=115200&parity=even", "hid:10c4:ea80:ABC123?baud=115200&parity=even"},
        {"lpt:/dev/parport0", "lpt:/dev/parport0"},
        {"lpt:emu?fw=/tmp/a b/fw=1.ihx&log=x:y?z", "lpt:emu?fw=/tmp/a b/fw=1.ihx&log=x:y?z"},
        {"lpt:emu?log=&fw=f.ihx", "lpt:emu?fw=f.ihx&log="},
    };
    for (const auto& c : cases) {
        const auto spec = parse_device(c.text);
        ASSERT_TRUE(spec) << c.text << ": " << spec.error().to_string();
        const auto written = format_device(*spec);
        EXPECT_EQ(written, c.written);
        const auto again = parse_device(written);
        ASSERT_TRUE(again) << written << ": " << again.error().to_string();
        EXPECT_EQ(again->scheme, spec->scheme) << c.text;
        EXPECT_EQ(again->path, spec->path) << c.text;
        EXPECT_EQ(again->options, spec->options) << c.text;
    }
    // The parts come back as typed, '=' in a value included.
    const auto emu = parse_device("lpt:emu?fw=/tmp/a b/fw=1.ihx&log=x:y?z");
    ASSERT_TRUE(emu);
    EXPECT_EQ(emu->path, "emu");
    EXPECT_EQ(emu->options.at("fw"), "/tmp/a b/fw=1.ihx");
    EXPECT_EQ(emu->options.at("log"), "x:y?z");
}

TEST(Device, BadStringsSayWhatIsWrong) {
    EXPECT_NE(parse_device("usb:/dev/x").error().message.find("unknown device type"), std::string::npos);
    EXPECT_NE(parse_device("serial:").error().message.find("missing the device path"), std::string::npos);
    EXPECT_NE(parse_device("serial:/dev/x?baud").error().message.find("key=value"), std::string::npos);
    auto s = parse_device("serial:/dev/x?baud=12");
    ASSERT_TRUE(s);
    EXPECT_FALSE(uart_settings(*s));
    s = parse_device("serial:/dev/x?speed=9600");
    ASSERT_TRUE(s);
    EXPECT_EQ(uart_settings(*s).error().where, "serial option speed");
    EXPECT_FALSE(open_device("hid:zz:ea80"));
    EXPECT_FALSE(open_device("sim?noise=-1"));
}

// The simulator's options are read once (sim_settings) for tactus-cli, the
// app and the spool's check of a printer's device: `sim?speed=max` was
// refused by the check ("unknown option") though tactus-cli ran it.
TEST(Device, SimulatorOptionsAreCheckedAsTheyAreRead) {
    for (const char* ok : {"sim", "sim?speed=max", "sim?speed=10", "sim?speed=0.5&noise=1e-3&seed=7&paper-reload=5"})
        EXPECT_TRUE(check_device(ok)) << ok;
    auto spec = parse_device("sim?speed=10&paper-reload=2");
    ASSERT_TRUE(spec);
    auto s = sim_settings(*spec);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->speed, 10.0);
    EXPECT_EQ(s->paper_reload_s, 2.0);
    spec = parse_device("sim");
    EXPECT_EQ(sim_settings(*spec)->speed, 1.0);  // the plan's own speed
    spec = parse_device("sim?speed=max");
    EXPECT_EQ(sim_settings(*spec)->speed, 0.0);  // as fast as the computer can
    // NaN and infinity are no speed or rate, and the noise stops where `sim
    // --noise` stops (they were accepted, and `noise=2` ran a line no frame crosses).
    for (const char* bad : {"sim?speed=0", "sim?speed=fast", "sim?volume=3", "sim?baud=100", "sim?speed=nan",
                            "sim?speed=inf", "sim?noise=nan", "sim?noise=2", "sim?baud=inf"}) {
        auto c = check_device(bad);
        ASSERT_FALSE(c) << bad;
        EXPECT_EQ(c.error().kind, ErrorKind::usage) << bad;
    }
}

TEST(Device, AbsentDevicesGiveTheDocumentedErrors) {
    for (const char* dev : {"serial:/dev/ttyTACTUS-NONE", "pty:/dev/pts/999999", "hid:10c4:ea80",
                            "hid:0403:6030:NOPE", "lpt:/dev/parport9"}) {
        auto s = open_device(dev);
        ASSERT_FALSE(s) << dev;
        EXPECT_NE(s.error().message.find("no such device"), std::string::npos) << dev << ": " << s.error().message;
        EXPECT_FALSE(s.error().where.empty());
    }
    // A malformed HID string is a usage error (exit 2), not a missing device (4).
    for (const char* dev : {"hid:zz:yy", "hid:10c4", "hid:10000:ea80"}) {
        auto s = open_device(dev);
        ASSERT_FALSE(s) << dev;
        EXPECT_EQ(s.error().kind, ErrorKind::usage) << dev << ": " << s.error().message;
    }
    auto notty = open_device("pty:/dev/null");
    ASSERT_FALSE(notty);
    EXPECT_NE(notty.error().message.find("not a terminal"), std::string::npos);
}

}  // namespace
}  // namespace tactus::transport
