// SPDX-License-Identifier: GPL-3.0-or-later
// The reference firmware's C headers (firmware/src/fw.h, exec.h) keep their
// own copies of its sizes and of the wire format's codes: SDCC compiles them
// without the host's headers. The host has one place for each, the sizes in
// core/machine (reference_firmware.hpp, ram_budget.hpp) and the codes in
// core/encode, and every stage reads them from there: the encoder cuts DATA
// payloads to kMaxOps, the simulated controller reports kRingBytes, the dry
// run counts frames. Here each of the firmware's copies is held to the host's,
// so a change on one side without the other fails.
#include <gtest/gtest.h>

#include <cstddef>

extern "C" {
#include "exec.h"
#include "fw.h"
}

#include "encode/frame.hpp"
#include "encode/messages.hpp"
#include "encode/stream_v3.hpp"
#include "machine/ram_budget.hpp"
#include "machine/reference_firmware.hpp"

namespace tactus {
namespace {

namespace fw = machine::reference_firmware;

template <typename E>
constexpr int code(E e) {
    return static_cast<int>(e);
}

TEST(FirmwareConstants, TheBufferSizesAreTheHosts) {
    EXPECT_EQ(FW_PROTOCOL, fw::kProtocol);
    EXPECT_EQ(FW_VERSION_MAJOR, fw::kFirmwareMajor);
    EXPECT_EQ(FW_VERSION_MINOR, fw::kFirmwareMinor);
    EXPECT_EQ(std::size_t{FW_BUF_CAP}, fw::kBufferBytes);
    EXPECT_EQ(std::size_t{FW_SLACK}, fw::kSlack);
    EXPECT_EQ(std::size_t{FW_RING_BYTES}, fw::kRingBytes);
    EXPECT_EQ(std::size_t{FW_MAX_DATA}, fw::kMaxPayload);
    EXPECT_EQ(std::size_t{FW_MAX_DATA - 2}, fw::kMaxOps);  // the DATA check is the payload's last two bytes
    EXPECT_EQ(std::size_t{FW_WINDOW_FRAMES}, fw::kWindowFrames);
}

TEST(FirmwareConstants, TheFrameLayoutIsTheHosts) {
    EXPECT_EQ(FW_SYNC, encode::kSync);
    // What the firmware stores of a frame besides its payload: all but SYNC.
    EXPECT_EQ(std::size_t{FW_FRAME_OVERHEAD}, encode::kFrameOverhead - 1);
    // The largest LEN either side takes before it calls a frame a false start.
    EXPECT_EQ(std::size_t{FW_WIRE_MAX_PAYLOAD}, machine::ram::kMaxPayload);
    EXPECT_EQ(std::size_t{FW_WIRE_MAX_PAYLOAD}, encode::kMaxPayload);
}

TEST(FirmwareConstants, TheMessageCodesAreTheHosts) {
    using encode::FrameType;
    EXPECT_EQ(T_HELLO, code(FrameType::hello));
    EXPECT_EQ(T_CONFIGURE, code(FrameType::configure));
    EXPECT_EQ(T_DATA, code(FrameType::data));
    EXPECT_EQ(T_PAUSE, code(FrameType::pause));
    EXPECT_EQ(T_RESUME, code(FrameType::resume));
    EXPECT_EQ(T_ABORT, code(FrameType::abort));
    EXPECT_EQ(T_STATUS, code(FrameType::status));
    EXPECT_EQ(T_KEEPALIVE, code(FrameType::keepalive));
    EXPECT_EQ(T_HELLO_REPLY, code(FrameType::hello_reply));
    EXPECT_EQ(T_ACK, code(FrameType::ack));
    EXPECT_EQ(T_NAK, code(FrameType::nak));
    EXPECT_EQ(T_STATUS_REPLY, code(FrameType::status_reply));

    using encode::NakReason;
    EXPECT_EQ(NAK_OUT_OF_ORDER, code(NakReason::out_of_order));
    EXPECT_EQ(NAK_NO_SPACE, code(NakReason::no_space));
    EXPECT_EQ(NAK_NO_SESSION, code(NakReason::no_session));
    EXPECT_EQ(NAK_BAD_PAYLOAD, code(NakReason::bad_payload));
    EXPECT_EQ(NAK_UNKNOWN_TYPE, code(NakReason::unknown_type));

    using encode::ControllerState;
    EXPECT_EQ(ST_IDLE, code(ControllerState::idle));
    EXPECT_EQ(ST_RUNNING, code(ControllerState::running));
    EXPECT_EQ(ST_WAITING, code(ControllerState::waiting));
    EXPECT_EQ(ST_PAUSED, code(ControllerState::paused));
    EXPECT_EQ(ST_FAULT, code(ControllerState::fault));
    EXPECT_EQ(ST_HOMING, code(ControllerState::homing));

    namespace fault = encode::fault;
    EXPECT_EQ(F_PAPER_OUT, fault::paper_out);
    EXPECT_EQ(F_LIMIT, fault::limit_switch);
    EXPECT_EQ(F_HAMMER, fault::hammer);
    EXPECT_EQ(F_POWER_ON, fault::power_on_reset);
    EXPECT_EQ(F_WARM_RESET, fault::warm_reset);
    EXPECT_EQ(F_HOST_TIMEOUT, fault::host_timeout);
    EXPECT_EQ(F_UNDERRUN, fault::underrun);
    EXPECT_EQ(F_STREAM, fault::stream_error);

    namespace flag = encode::flag;
    EXPECT_EQ(FL_CONFIGURED, flag::configured);
    EXPECT_EQ(FL_HOMED, flag::homed);
    EXPECT_EQ(FL_PASS_ACTIVE, flag::pass_active);
    EXPECT_EQ(FL_PAPER, flag::paper_present);
    EXPECT_EQ(FL_JOB_ACTIVE, flag::job_active);
    EXPECT_EQ(FL_JOB_ENDED, flag::job_ended);

    namespace cap = encode::capability;
    EXPECT_EQ(CAP_INTERPOINT, cap::interpoint);
    EXPECT_EQ(CAP_LPT, cap::lpt);
    EXPECT_EQ(CAP_UART, cap::uart);
    EXPECT_EQ(CAP_WARM_RESTART, cap::warm_restart);
}

TEST(FirmwareConstants, TheJobStreamCodesAreTheHosts) {
    namespace v3 = encode::v3;
    EXPECT_EQ(OP_JOB_BEGIN, v3::op_job_begin);
    EXPECT_EQ(OP_JOB_END, v3::op_job_end);
    EXPECT_EQ(OP_SHEET_BEGIN, v3::op_sheet_begin);
    EXPECT_EQ(OP_SHEET_END, v3::op_sheet_end);
    EXPECT_EQ(OP_PASS, v3::op_pass);
    EXPECT_EQ(OP_HOME, v3::op_home);
    EXPECT_EQ(OP_SEEK_CARRIAGE, v3::op_seek_carriage);
    EXPECT_EQ(OP_SEEK_FEED, v3::op_seek_feed);

    namespace pf = v3::pass_flag;
    EXPECT_EQ(PF_BACK, pf::back_side);
    EXPECT_EQ(PF_NO_FEED, pf::no_feed);
    EXPECT_EQ(PF_SWEEP_NEG, pf::sweep_neg);
    EXPECT_EQ(PF_FIRST_NEG, pf::first_neg);
    EXPECT_EQ(PF_SKIP, pf::skip);
    EXPECT_EQ(PF_ALL, pf::all);

    EXPECT_EQ(E_CONCAVE, v3::entry::concave);
    EXPECT_EQ(E_EXT, v3::entry::ext);
    EXPECT_EQ(E_DIST, v3::entry::dist);
}

}  // namespace
}  // namespace tactus
