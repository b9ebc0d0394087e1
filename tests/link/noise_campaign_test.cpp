// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 12 item 8, "never a wrong dot, whatever the line does": hundreds of
// seeds at three per-byte noise rates (bytes dropped, bit-flipped and
// duplicated, each at the rate, both ways, 57,600 baud), the host link
// against the C++ controller on virtual time. Every run must either complete
// with exactly the plan's strikes or fail cleanly (what was struck is the
// plan's beginning, and the outcome names the sheet to resume from): 0 wrong
// or missing strikes. Throughput is the job's: the time a clean line takes
// over the time the noisy one does, motion included (the ring keeps the
// carriage busy while frames are resent), printed, not asserted
// (docs/protocol.md has the figures).
//
// Both protocols: NoiseCampaign runs the C++ controller speaking protocol 2,
// NoiseCampaignV3 speaking protocol 3 as the reference firmware does (its
// ramp tables, ring, window and DATA check), on plans made of the firmware's
// table moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "link/link.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../common/test_plans.hpp"

namespace tactus {
namespace {

struct RunResult {
    link::JobOutcome out;
    std::vector<controller::LoggedStrike> log;
    double seconds = 0;  // virtual: HELLO to the job's end
    std::size_t corrupted = 0;
    std::size_t check_drops = 0;  // v3: DATA frames whose CRC passed and DATA check failed
};

const machine::FirmwareTables& tables() {
    static const machine::FirmwareTables t = [] {
        auto r = profile::load_firmware_tables(TACTUS_FIRMWARE_TABLES);
        EXPECT_TRUE(r) << r.error().to_string();
        return r ? *r : machine::FirmwareTables{};
    }();
    return t;
}
const machine::StrikeTiming& timing() {
    static const machine::StrikeTiming t = profile::strike_timing(profile::default_profile());
    return t;
}

RunResult run_once(const plan::JobPlan& plan, double rate, std::uint64_t seed, bool v3) {
    controller::SimOptions so;
    if (v3) so.firmware = tables();
    auto ctl = std::make_shared<controller::SimController>(so);
    controller::SimLineOptions line;
    line.baud = 57600;
    line.noise = {rate, rate, rate, seed};
    auto t = std::make_unique<controller::SimTransport>(ctl, line);
    auto* raw = t.get();
    auto l = link::Link::over(std::move(t));
    RunResult r;
    const double start = raw->now();
    // HELLO and CONFIGURE are bounded by their own timeouts; a run that
    // cannot open its session fails cleanly (nothing sent).
    auto h = l.hello();
    Result<void> c = h ? Result<void>{} : Result<void>(std::unexpected(h.error()));
    if (c && v3) {
        EXPECT_EQ(l.protocol(), encode::kProtocolV3);
        c = l.use_firmware_tables(tables(), timing());
        EXPECT_TRUE(c) << c.error().to_string();
    }
    if (c) c = l.configure({});
    if (c) {
        link::CancelToken cancel;
        auto out = l.send_job(plan, 1, {}, cancel);
        EXPECT_TRUE(out) << out.error().to_string();
        if (out) r.out = *out;
    } else {
        r.out.end = link::JobEnd::failed;
        r.out.resume_sheet = 1;
        r.out.error = c.error();
    }
    r.seconds = raw->now() - start;
    r.log = ctl->strike_log();
    r.corrupted = raw->bytes_corrupted();
    r.check_drops = ctl->data_check_errors();
    return r;
}

struct Tally {
    std::size_t completed = 0, failed_cleanly = 0, wrong = 0, corrupted = 0, check_drops = 0;
    double seconds = 0, clean_seconds = 0;
    std::string first_wrong;
};

void campaign(double rate, bool v3) {
    // 200 seeds a rate; TACTUS_NOISE_SEEDS=N runs more (the figures in docs/protocol.md).
    const char* more = std::getenv("TACTUS_NOISE_SEEDS");
    const std::uint64_t kSeeds = more ? std::strtoull(more, nullptr, 10) : 200;
    Tally t;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const auto plan = v3 ? test::make_firmware_plan(tables(), timing(), 2, 4, 12, static_cast<unsigned>(seed))
                             : test::make_plan(2, 4, 12, static_cast<unsigned>(seed));
        const auto planned = controller::planned_strikes(plan);
        const auto r = run_once(plan, rate, seed * 7919 + static_cast<std::uint64_t>(rate * 1e6), v3);
        t.corrupted += r.corrupted;
        t.check_drops += r.check_drops;
        const bool prefix = r.log.size() <= planned.size() && std::equal(r.log.begin(), r.log.end(), planned.begin());
        if (r.out.end == link::JobEnd::completed && r.log == planned) {
            ++t.completed;
            t.seconds += r.seconds;
            t.clean_seconds += run_once(plan, 0, 1, v3).seconds;
        } else if (r.out.end != link::JobEnd::completed && prefix && r.out.resume_sheet >= 1 &&
                   !r.out.error.message.empty()) {
            ++t.failed_cleanly;
            if (std::getenv("TACTUS_NOISE_VERBOSE"))
                std::printf("seed %llu failed cleanly: %s\n", static_cast<unsigned long long>(seed),
                            r.out.error.message.c_str());
            // Nothing after the sheet to resume from was struck.
            for (const auto& s : r.log) EXPECT_LE(s.sheet, r.out.resume_sheet) << "seed " << seed;
        } else {
            ++t.wrong;
            if (t.first_wrong.empty())
                t.first_wrong = "seed " + std::to_string(seed) + ": " + std::to_string(r.log.size()) + " of " +
                                std::to_string(planned.size()) + " strikes, end " +
                                std::to_string(static_cast<int>(r.out.end)) + " " + r.out.error.message;
        }
    }
    EXPECT_EQ(t.wrong, 0U) << t.first_wrong;
    EXPECT_EQ(t.completed + t.failed_cleanly, kSeeds);
    // At 1e-3 every job gets through; on the noisier lines most do (the frame
    // size follows the line), the others end cleanly at the give-up. At 2e-2
    // a quarter of the v3 runs (a third of v2's) once failed at the session's
    // open, 3 s into a line that garbled the controller's answers (issue 12
    // item 8; link_impl.hpp silent_too_long): 151 of 200 v3 runs and 138 of
    // v2's completed then, 198 and 182 now.
    if (rate <= 1e-3)
        EXPECT_EQ(t.completed, kSeeds);
    else if (rate <= 1e-2)
        EXPECT_GE(t.completed * 100, kSeeds * 97);
    else
        EXPECT_GE(t.completed * 100, kSeeds * (v3 ? 95 : 80));
    std::printf("protocol %d, noise %g: %zu runs, %zu completed exactly, %zu failed cleanly, %zu wrong; %zu bytes corrupted, %zu DATA frames passed the CRC and failed the DATA check; "
                "throughput %.1f %% of a clean line\n",
                v3 ? 3 : 2, rate, static_cast<std::size_t>(kSeeds), t.completed, t.failed_cleanly, t.wrong, t.corrupted, t.check_drops,
                t.seconds > 0 ? 100.0 * t.clean_seconds / t.seconds : 0.0);
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
