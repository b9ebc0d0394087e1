// SPDX-License-Identifier: GPL-3.0-or-later
// "Never a wrong dot, whatever the line does": hundreds of
// seeds at three per-byte noise rates (bytes dropped, bit-flipped and
// duplicated, each at the rate, both ways, 57,600 baud), the host link
// against the C++ controller on virtual time (tests/common/noise_campaign.hpp
// has the rule). Every run must either complete with exactly the plan's
// strikes or fail cleanly: 0 wrong or missing strikes. Throughput is printed,
// not asserted (docs/protocol.md has the figures).
//
// Both protocols: NoiseCampaign runs the C++ controller speaking protocol 2,
// NoiseCampaignV3 speaking protocol 3 as the reference firmware does (its
// ramp tables, ring, window and DATA check), on plans made of the firmware's
// table moves. The firmware's own C runs the same campaign in
// tests/firmware/firmware_noise_test.cpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../common/noise_campaign.hpp"
#include "../common/firmware_tables_fixture.hpp"

namespace tactus {
namespace {

const machine::FirmwareTables& tables() { return test::firmware_tables(); }

void campaign(double rate, bool v3) {
    // 200 seeds a rate; TACTUS_NOISE_SEEDS=N runs more (the figures in docs/protocol.md).
    const char* more = std::getenv("TACTUS_NOISE_SEEDS");
    const std::uint64_t kSeeds = more ? std::strtoull(more, nullptr, 10) : 200;
    // TACTUS_NOISE_FIRST_SEED=N starts there (to run one seed again).
    const char* from = std::getenv("TACTUS_NOISE_FIRST_SEED");
    const std::uint64_t first = from ? std::strtoull(from, nullptr, 10) : 1;
    test::CampaignSetup setup;
    controller::SimOptions so;
    if (v3) {
        so.firmware = tables();
        setup.tables = tables();
        setup.timing = profile::strike_timing(profile::default_profile());
    }
    setup.make = [so] {
        auto ctl = std::make_shared<controller::SimController>(so);
        return test::FarEnd{ctl, [ctl] { return ctl->strike_log(); }, [ctl] { return ctl->data_check_errors(); }};
    };
    const auto t = test::campaign(setup, rate, kSeeds, first);
    if (std::getenv("TACTUS_NOISE_VERBOSE"))
        for (const auto& f : t.failures) std::printf("failed cleanly, %s\n", f.c_str());
    EXPECT_EQ(t.wrong, 0U) << t.first_wrong;
    EXPECT_EQ(t.completed + t.failed_cleanly, kSeeds);
    // At 1e-3 every job gets through; on the noisier lines most do (the frame
    // size follows the line), the others end cleanly at the give-up. At 2e-2
    // a quarter of the v3 runs (a third of v2's) once failed at the session's
    // open, 3 s into a line that garbled the controller's answers
    // (link_session.cpp silent_too_long): 151 of 200 v3 runs and 138 of
    // v2's completed then, 198 and 182 now.
    if (rate <= 1e-3)
        EXPECT_EQ(t.completed, kSeeds);
    else if (rate <= 1e-2)
        EXPECT_GE(t.completed * 100, kSeeds * 97);
    else
        EXPECT_GE(t.completed * 100, kSeeds * (v3 ? 95 : 80));
    std::printf("protocol %d, noise %g: %zu runs, %zu completed exactly, %zu failed cleanly, %zu wrong; %zu bytes corrupted, %zu DATA frames passed the CRC and failed the DATA check; "
                "throughput %.1f %% of a clean line\n",
                v3 ? 3 : 2, rate, t.runs, t.completed, t.failed_cleanly, t.wrong, t.corrupted, t.check_drops,
                100.0 * t.throughput());
}

class NoiseCampaign : public ::testing::TestWithParam<double> {};
TEST_P(NoiseCampaign, EveryRunCompletesExactlyOrFailsCleanly) { campaign(GetParam(), false); }

class NoiseCampaignV3 : public ::testing::TestWithParam<double> {};
TEST_P(NoiseCampaignV3, EveryRunCompletesExactlyOrFailsCleanly) { campaign(GetParam(), true); }

std::string rate_name(const ::testing::TestParamInfo<double>& p) {
    return p.param == 1e-3 ? std::string("PerByte1e3")
           : p.param == 1e-2 ? std::string("PerByte1e2")
                              : std::string("PerByte2e2");
}
INSTANTIATE_TEST_SUITE_P(Rates, NoiseCampaign, ::testing::Values(1e-3, 1e-2, 2e-2), rate_name);
INSTANTIATE_TEST_SUITE_P(Rates, NoiseCampaignV3, ::testing::Values(1e-3, 1e-2, 2e-2), rate_name);

}  // namespace
}  // namespace tactus
