// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Never a wrong dot, whatever the line does": the noise
// campaign, one rule for every controller at the far end of the in-process
// line. Per seed, a plan, the host's real link against a fresh controller
// over a line that drops, bit-flips and duplicates bytes (each at the rate,
// both ways) on virtual time. A run must either complete with exactly the
// plan's strikes or fail cleanly (what was struck is the plan's beginning,
// nothing past the sheet the outcome names to resume from, and an error
// that says why). Throughput: the clean line's job time over the noisy
// line's, motion included.
//
// Used by tests/link/noise_campaign_test.cpp (the C++ controller, protocol 2
// and 3), tests/firmware/firmware_noise_test.cpp (the firmware's own C) and
// bench/firmware/bench_noise_native.cpp (hundreds of seeds, both). No
// GoogleTest here: the callers assert on the tally.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "controller/line_end.hpp"
#include "controller/sim_controller.hpp"
#include "controller/sim_transport.hpp"
#include "link/link.hpp"
#include "machine/firmware_tables.hpp"
#include "test_plans.hpp"

namespace tactus::test {

// A fresh controller for one run, and how to read what it struck.
struct FarEnd {
    std::shared_ptr<controller::LineEnd> end;
    std::function<std::vector<controller::LoggedStrike>()> strikes;
    // v3 DATA frames whose CRC passed and whose DATA check failed (0 when unknown).
    std::function<std::size_t()> check_drops = [] { return std::size_t{0}; };
};
using MakeFarEnd = std::function<FarEnd()>;

struct CampaignSetup {
    MakeFarEnd make;
    double baud = 57600;
    // Protocol 3: the firmware's tables and strike timing (plans of its table
    // moves); nullopt: protocol 2.
    std::optional<machine::FirmwareTables> tables;
    machine::StrikeTiming timing;
    std::size_t sheets = 2, passes = 4, strikes = 12;
};

struct CampaignRun {
    link::JobOutcome out;
    std::vector<controller::LoggedStrike> log;
    double seconds = 0;  // virtual: HELLO to the job's end
    std::size_t corrupted = 0;
    std::size_t check_drops = 0;
};

inline CampaignRun campaign_run(const CampaignSetup& setup, const plan::JobPlan& plan, double rate,
                                std::uint64_t seed) {
    auto far = setup.make();
    controller::SimLineOptions line;
    line.baud = setup.baud;
    line.noise = {rate, rate, rate, seed};
    auto t = std::make_unique<controller::SimTransport>(far.end, line);
    auto* raw = t.get();
    auto l = link::Link::over(std::move(t));
    CampaignRun r;
    const double start = raw->now();
    // HELLO and CONFIGURE are bounded by their own timeouts; a run that
    // cannot open its session fails cleanly (nothing sent).
    auto h = l.hello();
    Result<void> c = h ? Result<void>{} : Result<void>(std::unexpected(h.error()));
    if (c && setup.tables) {
        if (l.protocol() != encode::kProtocolV3)
            c = fail(ErrorKind::protocol, "the controller did not speak protocol 3", "campaign");
        else
            c = l.use_firmware_tables(*setup.tables, setup.timing);
    }
    if (c) c = l.configure({});
    if (c) {
        link::CancelToken cancel;
        auto out = l.send_job(plan, 1, {}, cancel);
        if (out) {
            r.out = *out;
        } else {
            r.out.end = link::JobEnd::failed;
            r.out.error = out.error();
        }
    } else {
        r.out.end = link::JobEnd::failed;
        r.out.resume_sheet = 1;
        r.out.error = c.error();
    }
    r.seconds = raw->now() - start;
    r.log = far.strikes();
    r.corrupted = raw->bytes_corrupted();
    r.check_drops = far.check_drops();
    return r;
}

struct CampaignTally {
    std::size_t runs = 0, completed = 0, failed_cleanly = 0, wrong = 0, corrupted = 0, check_drops = 0;
    double seconds = 0, clean_seconds = 0;
    std::string first_wrong;
    std::vector<std::string> failures;  // why each clean failure failed ("seed N: message")
    [[nodiscard]] double throughput() const { return seconds > 0 ? clean_seconds / seconds : 0.0; }
};

// Seeds first..first + seeds - 1 at `rate` (each seed its own plan and line).
inline CampaignTally campaign(const CampaignSetup& setup, double rate, std::uint64_t seeds, std::uint64_t first = 1) {
    CampaignTally t;
    for (std::uint64_t seed = first; seed < first + seeds; ++seed) {
        const auto plan = setup.tables ? make_firmware_plan(*setup.tables, setup.timing, setup.sheets, setup.passes,
                                                            setup.strikes, static_cast<unsigned>(seed))
                                       : make_plan(setup.sheets, setup.passes, setup.strikes, static_cast<unsigned>(seed));
        const auto planned = controller::planned_strikes(plan);
        const auto r = campaign_run(setup, plan, rate, seed * 7919 + static_cast<std::uint64_t>(rate * 1e6));
        ++t.runs;
        t.corrupted += r.corrupted;
        t.check_drops += r.check_drops;
        const bool prefix = r.log.size() <= planned.size() && std::equal(r.log.begin(), r.log.end(), planned.begin());
        const bool nothing_past_resume = std::all_of(r.log.begin(), r.log.end(), [&](const auto& s) {
            return s.sheet <= r.out.resume_sheet;
        });
        if (r.out.end == link::JobEnd::completed && r.log == planned) {
            ++t.completed;
            t.seconds += r.seconds;
            t.clean_seconds += campaign_run(setup, plan, 0, 1).seconds;
        } else if (r.out.end != link::JobEnd::completed && prefix && r.out.resume_sheet >= 1 &&
                   nothing_past_resume && !r.out.error.message.empty()) {
            ++t.failed_cleanly;
            t.failures.push_back("seed " + std::to_string(seed) + ": " + r.out.error.message);
        } else {
            ++t.wrong;
            if (t.first_wrong.empty()) {
                t.first_wrong = "seed " + std::to_string(seed) + ": " + std::to_string(r.log.size()) + " of " +
                                std::to_string(planned.size()) + " strikes, end " +
                                std::to_string(static_cast<int>(r.out.end)) + " " + r.out.error.message;
                const auto at = std::mismatch(r.log.begin(), r.log.end(), planned.begin(), planned.end());
                if (at.first != r.log.end() && at.second != planned.end())
                    t.first_wrong += "; strike " + std::to_string(at.first - r.log.begin()) + " struck at carriage step " +
                                     std::to_string(at.first->carriage_step) + ", feed step " +
                                     std::to_string(at.first->feed_step) + ", sheet " + std::to_string(at.first->sheet) +
                                     " where the plan has " + std::to_string(at.second->carriage_step) + ", " +
                                     std::to_string(at.second->feed_step) + ", " + std::to_string(at.second->sheet);
            }
        }
    }
    return t;
}

}  // namespace tactus::test
