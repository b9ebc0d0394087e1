// SPDX-License-Identifier: GPL-3.0-or-later
// The full noise campaign against both controllers on the
// same line: the C++ controller speaking protocol 3 and the reference
// firmware's own C compiled natively (tests/firmware/native_firmware.hpp),
// each at the far end of the host's real link, bytes dropped, flipped and
// duplicated each at the rate, both ways, on virtual time. Per rate and
// controller: runs completed exactly, failed cleanly, wrong or missing
// strikes (must be 0), and the throughput (a clean line's job time over the
// noisy line's). The campaign's rule is tests/common/noise_campaign.hpp.
//
//   bench_noise_native [SEEDS=300] [BAUD=9600]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "native_firmware.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile.hpp"
#include "../../tests/common/noise_campaign.hpp"

using namespace tactus;

int main(int argc, char** argv) {
    const std::uint64_t seeds = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 300;
    const double baud = argc > 2 ? std::strtod(argv[2], nullptr) : 9600;
    auto loaded = profile::load_firmware_tables(TACTUS_FIRMWARE_TABLES);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.error().to_string().c_str());
        return 1;
    }
    const machine::FirmwareTables tables = *loaded;
    test::CampaignSetup fw;
    fw.baud = baud;
    fw.tables = tables;
    fw.timing = profile::strike_timing(profile::default_profile());
    fw.make = [tables, baud] {
        test::NativeFirmwareOptions o;
        o.tables = tables;
        o.baud = baud;
        auto f = std::make_shared<test::NativeFirmware>(o);
        return test::FarEnd{f, [f] { return f->strike_log(); }};
    };
    test::CampaignSetup cpp = fw;
    controller::SimOptions so;
    so.firmware = tables;
    cpp.make = [so] {
        auto c = std::make_shared<controller::SimController>(so);
        return test::FarEnd{c, [c] { return c->strike_log(); }, [c] { return c->data_check_errors(); }};
    };
    std::printf("noise campaign, %llu seeds a rate, %.0f baud, plans of 2 sheets x 4 passes x up to 12 strikes\n",
                static_cast<unsigned long long>(seeds), baud);
    std::printf("| Controller | Per-byte rate | Runs | Completed exactly | Failed cleanly | Wrong or missing | Throughput |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    int wrong = 0;
    for (const double rate : {1e-3, 1e-2, 2e-2}) {
        for (const auto& [name, setup] : {std::pair<std::string, const test::CampaignSetup*>{"firmware (its C, native)", &fw},
                                          {"C++ controller, v3", &cpp}}) {
            const auto t = test::campaign(*setup, rate, seeds);
            std::printf("| %s | %g | %zu | %zu | %zu | %zu | %.1f %% |\n", name.c_str(), rate, t.runs, t.completed,
                        t.failed_cleanly, t.wrong, 100.0 * t.throughput());
            if (t.wrong) std::printf("  first wrong: %s\n", t.first_wrong.c_str());
            if (std::getenv("TACTUS_NOISE_VERBOSE"))
                for (const auto& f : t.failures) std::printf("  failed cleanly, %s\n", f.c_str());
            wrong += t.wrong > 0;
        }
    }
    return wrong ? 1 : 0;
}
