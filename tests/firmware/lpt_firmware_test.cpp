// SPDX-License-Identifier: GPL-3.0-or-later
// One behaviour, two implementations: the parallel port's controller side as
// the C++ model runs it (controller::LptPeripheral) and as the firmware runs
// it (firmware/src/lpt.c, compiled natively: its pins are variables,
// firmware/native/8052.h), each driven by the host's own LptPort through
// the same cable. Compatibility-mode bytes in (strobe, Busy, nAck), the
// condition on PError/nFault/Select, and IEEE 1284 nibble-mode replies
// (negotiation, HostBusy, the four status lines, termination) must give the
// host the same bytes from both.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <memory>
#include <vector>

#include "controller/lpt_peripheral.hpp"
#include "transport/lpt_port.hpp"

extern "C" {
#include "board.h"
#include "fw.h"
#include "lpt.h"
#include "uart.h"
void strobe_isr(void);
// What lpt.c takes from the rest of the firmware, here: the receive queue
// (uart.c), the controller's state (link.c) and its reply bytes.
FW_IDATA uint8_t rxq[RXQ];
volatile uint8_t rx_w, rx_r;
uint8_t fw_faults, fw_state;
volatile uint8_t P3_2, P3_3, P3_4, P3_5, P3_6, P3_7;
volatile union native_port native_p2;
volatile uint8_t P0;
}

namespace {

std::deque<std::uint8_t> g_replies;  // what link.c would build next

}  // namespace

extern "C" int16_t fw_reply_byte(void) {
    if (g_replies.empty()) return -1;
    const auto b = g_replies.front();
    g_replies.pop_front();
    return b;
}

namespace tactus {
namespace {

using transport::LptControl;
using transport::LptPort;
using transport::LptStatus;
using transport::ParallelPortLines;

// The controller's side of the cable, whichever implementation.
class Side {
public:
    virtual ~Side() = default;
    virtual void set_data(std::uint8_t d) = 0;
    virtual void set_control(const LptControl& c) = 0;
    virtual void tick() = 0;
    [[nodiscard]] virtual LptStatus status() const = 0;
    virtual std::vector<std::uint8_t> take_received() = 0;
    virtual void send(const std::vector<std::uint8_t>& bytes) = 0;
    virtual void set_condition(bool paper_out, bool fault) = 0;
};

class ModelSide final : public Side {
public:
    void set_data(std::uint8_t d) override { p_.set_data(d); }
    void set_control(const LptControl& c) override { p_.set_control(c); }
    void tick() override { p_.tick(); }
    [[nodiscard]] LptStatus status() const override { return p_.status(); }
    std::vector<std::uint8_t> take_received() override { return p_.take_received(); }
    void send(const std::vector<std::uint8_t>& b) override { p_.send(b); }
    void set_condition(bool paper_out, bool fault) override { p_.set_condition(paper_out, fault, true); }

private:
    controller::LptPeripheral p_;
};

// The firmware's lpt.c: the host's control lines on its input pins, the
// strobe's falling edge runs the INT0 handler, tick() is one main-loop pass
// (the receive queue drained as io_rx does, then lpt_poll).
class FirmwareSide final : public Side {
public:
    FirmwareSide() {
        g_replies.clear();
        rx_w = 0;
        rx_r = 0;
        fw_faults = 0;
        fw_state = ST_IDLE;
        native_p2.byte = 0xFF;  // the port's reset state
        P3_5 = 1;
        P3_2 = 1;
        lpt_init();
        LPT_BUSY = 0;  // io_init
    }
    void set_data(std::uint8_t d) override { P0 = d; }
    void set_control(const LptControl& c) override {
        const bool fell = P3_2 && !c.n_strobe;
        P3_2 = c.n_strobe ? 1 : 0;
        P2_4 = c.n_auto_fd ? 1 : 0;
        P2_5 = c.n_select_in ? 1 : 0;
        if (fell) strobe_isr();
    }
    void tick() override {
        if (rx_r == rx_w) {
            if (LPT_BUSY && lpt_mode == LM_COMPAT) LPT_BUSY = 0;  // io_rx: room again
        } else {
            received_.push_back(rxq[rx_r & (RXQ - 1)]);
            rx_r = static_cast<std::uint8_t>(rx_r + 1);
        }
        lpt_poll();
    }
    [[nodiscard]] LptStatus status() const override {
        return LptStatus{P3_5 != 0, P2_3 != 0, P2_2 != 0, P2_1 != 0, P2_0 != 0};
    }
    std::vector<std::uint8_t> take_received() override { return std::exchange(received_, {}); }
    void send(const std::vector<std::uint8_t>& b) override {
        g_replies.insert(g_replies.end(), b.begin(), b.end());
        fw_via_lpt = 1;  // the host spoke over this port last
    }
    void set_condition(bool paper_out, bool fault) override {
        fw_faults = paper_out ? F_PAPER_OUT : 0;
        fw_state = fault ? ST_FAULT : ST_IDLE;
        tick();
    }

private:
    std::vector<std::uint8_t> received_;
};

class Cable final : public ParallelPortLines {
public:
    explicit Cable(Side& s) : s_(s) {}
    Result<void> write_data(std::uint8_t v) override {
        s_.set_data(v);
        return {};
    }
    Result<void> write_control(const LptControl& c) override {
        s_.set_control(c);
        return {};
    }
    Result<LptStatus> read_status() override { return s_.status(); }
    void settle() override { s_.tick(); }

private:
    Side& s_;
};

enum class Impl { model, firmware };

class LptBothSides : public ::testing::TestWithParam<Impl> {
protected:
    void SetUp() override {
        if (GetParam() == Impl::model) side_ = std::make_unique<ModelSide>();
        else side_ = std::make_unique<FirmwareSide>();
        auto p = LptPort::open(
            [this]() -> Result<std::unique_ptr<ParallelPortLines>> {
                return std::unique_ptr<ParallelPortLines>(std::make_unique<Cable>(*side_));
            },
            "lpt:test");
        ASSERT_TRUE(p) << p.error().to_string();
        port_ = std::move(*p);
    }
    std::vector<std::uint8_t> read_all(std::size_t want) {
        std::vector<std::uint8_t> got;
        std::array<std::uint8_t, 64> buf{};
        for (int tries = 0; tries < 50 && got.size() < want; ++tries) {
            auto n = port_->read(buf, std::chrono::milliseconds(5));
            EXPECT_TRUE(n) << n.error().to_string();
            if (!n) break;
            got.insert(got.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(*n));
        }
        return got;
    }
    std::unique_ptr<Side> side_;
    std::unique_ptr<LptPort> port_;
};

TEST_P(LptBothSides, CompatibilityModeDeliversEveryByteInOrder) {
    std::vector<std::uint8_t> data(300);
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7);
    ASSERT_TRUE(port_->write(data));
    side_->tick();
    EXPECT_EQ(side_->take_received(), data);
}

TEST_P(LptBothSides, NibbleModeReadsTheControllersBytesAndReturnsToCompatibilityMode) {
    const std::vector<std::uint8_t> hello{0x7E, 0x03, 0x00, 0x01, 0x12, 0x34, 0x03, 0xAB, 0xCD};
    ASSERT_TRUE(port_->write(hello));
    side_->tick();
    EXPECT_EQ(side_->take_received(), hello);
    // Every nibble value both ways, and a byte with all status lines low.
    const std::vector<std::uint8_t> reply{0x7E, 0x00, 0xFF, 0xA5, 0x5A, 0x01, 0x10, 0x0F, 0xF0};
    side_->send(reply);
    EXPECT_EQ(read_all(reply.size()), reply);
    // Back in compatibility mode: forward bytes go through again.
    const std::vector<std::uint8_t> more{1, 2, 3};
    ASSERT_TRUE(port_->write(more));
    side_->tick();
    EXPECT_EQ(side_->take_received(), more);
    // Nothing to send: the read ends with no bytes.
    std::array<std::uint8_t, 8> buf{};
    auto n = port_->read(buf, std::chrono::milliseconds(2));
    ASSERT_TRUE(n) << n.error().to_string();
    EXPECT_EQ(*n, 0U);
    // A reply that comes while the host is away is read at its next poll,
    // which negotiates again at once after the last termination (the
    // controller must not wait for HostBusy high there).
    side_->send({0x42, 0x43});
    EXPECT_EQ(read_all(2), (std::vector<std::uint8_t>{0x42, 0x43}));
}

TEST_P(LptBothSides, StatusLinesCarryTheCondition) {
    side_->set_condition(true, false);
    auto c = port_->condition();
    ASSERT_TRUE(c);
    EXPECT_TRUE(c->paper_out);
    EXPECT_FALSE(c->fault);
    EXPECT_TRUE(c->online);
    side_->set_condition(false, true);
    c = port_->condition();
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->paper_out);
    EXPECT_TRUE(c->fault);
    // The condition is shown again after a nibble-mode read (once the
    // controller has seen the end of it: one poll).
    side_->send({0x00});
    EXPECT_EQ(read_all(1), (std::vector<std::uint8_t>{0x00}));
    side_->tick();
    c = port_->condition();
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->paper_out);
    EXPECT_TRUE(c->fault);
    EXPECT_TRUE(c->online);
}

// A host that gives a negotiation up (its handshake timed out, it reopened
// the port) drops 1284 Active without the strobe of event 3: the controller
// goes back to compatibility mode, nAck high, takes bytes and answers the
// next negotiation. Both sides waited for that strobe for good before: the
// host's bytes still came in, but no later read was answered (a warm reset
// while the host read a reply over lpt:emu, FirmwareOverLpt).
TEST_P(LptBothSides, ANegotiationTheHostGivesUpLeavesTheNextOneAnswered) {
    side_->set_data(0x00);  // event 0: nibble mode requested, 1284 Active, HostBusy low
    side_->set_control(LptControl{.n_strobe = true, .n_auto_fd = false, .n_init = true, .n_select_in = true});
    side_->tick();
    EXPECT_FALSE(side_->status().n_ack);  // event 2
    ASSERT_TRUE(port_->reopen());        // the idle lines: 1284 inactive, no strobe
    side_->tick();
    EXPECT_TRUE(side_->status().n_ack);
    const std::vector<std::uint8_t> bytes{0x7E, 0x01, 0x02};
    ASSERT_TRUE(port_->write(bytes));
    side_->tick();
    EXPECT_EQ(side_->take_received(), bytes);
    side_->send({0x55, 0xAA});
    EXPECT_EQ(read_all(2), (std::vector<std::uint8_t>{0x55, 0xAA}));
}

INSTANTIATE_TEST_SUITE_P(Sides, LptBothSides, ::testing::Values(Impl::model, Impl::firmware),
                         [](const auto& p) { return std::string(p.param == Impl::model ? "Model" : "Firmware"); });

}  // namespace
}  // namespace tactus
