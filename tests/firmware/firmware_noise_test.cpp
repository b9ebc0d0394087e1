// SPDX-License-Identifier: GPL-3.0-or-later
// The noise campaign against the firmware itself: the reference firmware's own
// C (link.c, decoder.c, crc16.c, exec.c: native_firmware.hpp) at the far end
// of the host's real link over a noisy line, on virtual time. The same
// campaign as the C++ controller's (tests/common/noise_campaign.hpp): every
// run completes with exactly the plan's strikes or fails cleanly. 40 seeds a
// rate here; bench/firmware/bench_noise_native runs hundreds against both
// controllers (docs/protocol.md, "Noise campaign").
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "native_firmware.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../common/noise_campaign.hpp"
#include "../common/firmware_tables_fixture.hpp"

namespace tactus {
namespace {

const machine::FirmwareTables& tables() { return test::firmware_tables(); }

test::CampaignSetup firmware_setup() {
    test::CampaignSetup setup;
    setup.baud = 9600;  // the firmware's build rate
    setup.tables = tables();
    setup.timing = profile::strike_timing(profile::default_profile());
    setup.make = [] {
        test::NativeFirmwareOptions o;
        o.tables = tables();
        auto fw = std::make_shared<test::NativeFirmware>(o);
        return test::FarEnd{fw, [fw] { return fw->strike_log(); }};
    };
    return setup;
}

TEST(FirmwareNative, ACleanLineStrikesThePlanAtTheCppControllersTimes) {
    auto setup = firmware_setup();
    const auto plan = test::make_firmware_plan(tables(), setup.timing, 2, 4, 12, 5);
    const auto r = test::campaign_run(setup, plan, 0, 1);
    ASSERT_EQ(r.out.end, link::JobEnd::completed) << r.out.error.to_string();
    EXPECT_EQ(r.log, controller::planned_strikes(plan));
    // The C++ controller on protocol 3 follows the firmware rule for rule:
    // the same strikes at the same times, the same job time.
    test::CampaignSetup cpp = setup;
    controller::SimOptions so;
    so.firmware = tables();
    cpp.make = [so] {
        auto ctl = std::make_shared<controller::SimController>(so);
        return test::FarEnd{ctl, [ctl] { return ctl->strike_log(); }};
    };
    const auto c = test::campaign_run(cpp, plan, 0, 1);
    ASSERT_EQ(c.log.size(), r.log.size());
    for (std::size_t i = 0; i < r.log.size(); ++i)
        EXPECT_NEAR(r.log[i].time_s, c.log[i].time_s, 1e-3) << "strike " << i;
    EXPECT_NEAR(r.seconds, c.seconds, 0.05);
}

void campaign(double rate) {
    const char* more = std::getenv("TACTUS_NOISE_SEEDS");
    const std::uint64_t seeds = more ? std::strtoull(more, nullptr, 10) : 40;
    const auto t = test::campaign(firmware_setup(), rate, seeds);
    if (std::getenv("TACTUS_NOISE_VERBOSE"))
        for (const auto& f : t.failures) std::printf("failed cleanly, %s\n", f.c_str());
    EXPECT_EQ(t.wrong, 0U) << t.first_wrong;
    EXPECT_EQ(t.completed + t.failed_cleanly, seeds);
    if (rate <= 1e-3)
        EXPECT_EQ(t.completed, seeds);
    else
        EXPECT_GE(t.completed * 100, seeds * 90);
    std::printf("firmware (native), noise %g: %zu runs, %zu completed exactly, %zu failed cleanly, %zu wrong; "
                "%zu bytes corrupted; throughput %.1f %% of a clean line\n",
                rate, t.runs, t.completed, t.failed_cleanly, t.wrong, t.corrupted, 100.0 * t.throughput());
}

class FirmwareNoise : public ::testing::TestWithParam<double> {};
TEST_P(FirmwareNoise, EveryRunCompletesExactlyOrFailsCleanly) { campaign(GetParam()); }

std::string rate_name(const ::testing::TestParamInfo<double>& p) {
    return p.param == 1e-3 ? std::string("PerByte1e3")
           : p.param == 1e-2 ? std::string("PerByte1e2")
                              : std::string("PerByte2e2");
}
INSTANTIATE_TEST_SUITE_P(Rates, FirmwareNoise, ::testing::Values(1e-3, 1e-2, 2e-2), rate_name);

}  // namespace
}  // namespace tactus
