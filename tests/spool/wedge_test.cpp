// SPDX-License-Identifier: GPL-3.0-or-later
// A spool that cannot be wedged: a stored job with a wrong
// JSON type fails that job with a reason instead of aborting the process; a
// job longer than the controller can count is failed, not retried forever;
// `queue recover` moves aside only what is damaged, never a healthy spool
// that is read-only or from a newer Tactus.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sqlite3.h>

#include <fstream>

#include "common/file_io.hpp"
#include "process.hpp"
#include "profile/profile.hpp"
#include "profile/profile_json.hpp"
#include "spool/runner.hpp"
#include "spool/schema.hpp"
#include "spool/snapshot.hpp"
#include "sim_rig.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

using test::TempDir;

const std::string kCli = TACTUS_CLI;

TEST(Wedge, ASnapshotWithAWrongJsonTypeIsAnErrorNotAnAbort) {
    for (const char* text : {
             R"({"format":3,"geometry":{},"pages":[]})",
             R"({"format":["tactus-paged-1"],"geometry":{},"pages":[]})",
             R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27,"lines_per_page":24,"interpoint":true,"eight_dot":false},"pages":[7]})",
             R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27.5,"lines_per_page":24,"interpoint":true,"eight_dot":false},"pages":[]})",
             R"({"format":"tactus-paged-1","geometry":{"cells_per_line":27,"lines_per_page":24,"interpoint":true,"eight_dot":false},"pages":[{"number":1e300,"print_page":"","lines":[]}]})",
         }) {
        SCOPED_TRACE(text);
        const auto doc = from_snapshot(text);
        ASSERT_FALSE(doc);
        EXPECT_FALSE(doc.error().message.empty());
    }
}

TEST(Wedge, OneBadStoredJobFailsAloneAndTheNextJobRuns) {
    TempDir dir;
    const auto db = dir / "spool.db";
    auto spool = *Spool::open(db);
    ASSERT_TRUE(spool.add_printer("lab", "sim", profile::to_json(profile::default_profile()).dump()));
    auto bad = test::submission("lab", 2);
    bad.document = R"({"format":3,"geometry":{"cells_per_line":"27"},"pages":{}})";
    const auto bad_id = *spool.submit(bad);
    const auto good_id = *spool.submit(test::submission("lab", 2));
    test::SimPrinter printer;
    RunnerOptions o;
    o.retry_backoff = std::chrono::milliseconds(0);
    o.poll = std::chrono::milliseconds(5);
    Runner r(db, "lab", printer.connect(), o);
    ASSERT_TRUE(r.start());
    std::atomic<bool> stop{false};
    auto first = r.run_next(stop);
    ASSERT_TRUE(first) << first.error().to_string();
    EXPECT_EQ(*first, RunEnd::failed);
    const auto failed = *spool.job(bad_id);
    EXPECT_EQ(failed.state, JobState::failed);
    EXPECT_NE(failed.reason.find("unreadable"), std::string::npos) << failed.reason;
    auto second = r.run_next(stop);
    ASSERT_TRUE(second) << second.error().to_string();
    EXPECT_EQ(*second, RunEnd::completed);
    EXPECT_EQ(spool.job(good_id)->state, JobState::completed);
}

TEST(Wedge, AJobLongerThanTheControllerCanCountFailsInsteadOfRetryingForever) {
    TempDir dir;
    const auto db = dir / "spool.db";
    auto spool = *Spool::open(db);
    ASSERT_TRUE(spool.add_printer("lab", "sim", profile::to_json(profile::default_profile()).dump()));
    // 3 interpoint sheets x 6,000 copies: far more than 65,535 passes in one job.
    auto big = test::submission("lab", 5, 6000);
    const auto id = *spool.submit(big);
    test::SimPrinter printer;
    RunnerOptions o;
    o.retry_backoff = std::chrono::milliseconds(0);
    o.poll = std::chrono::milliseconds(5);
    o.max_retries = 1000;  // today's behaviour: retried as "transient" over and over
    Runner r(db, "lab", printer.connect(), o);
    ASSERT_TRUE(r.start());
    std::atomic<bool> stop{false};
    auto end = r.run_next(stop);
    ASSERT_TRUE(end) << end.error().to_string();
    EXPECT_EQ(*end, RunEnd::failed);
    const auto job = *spool.job(id);
    EXPECT_EQ(job.state, JobState::failed);
    EXPECT_NE(job.reason.find("65,535"), std::string::npos) << job.reason;
    EXPECT_TRUE(printer.controller->strike_log().empty());
}

std::pair<int, std::string> cli(const std::filesystem::path& db, std::vector<std::string> args,
                                const std::filesystem::path& err) {
    args.insert(args.begin() + 1, {"--db", db.string()});
    args.insert(args.begin(), kCli);
    std::filesystem::remove(err);
    test::Process p(args, err.string());
    auto out = p.read_all();
    return {p.wait(), out};
}

void set_user_version(const std::filesystem::path& db, int v) {
    sqlite3* h = nullptr;
    ASSERT_EQ(sqlite3_open(db.c_str(), &h), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(h, ("PRAGMA user_version=" + std::to_string(v)).c_str(), nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(h);
}

TEST(Wedge, RecoverLeavesAReadOnlyOrNewerSpoolWhereItIs) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
    std::ofstream(dir / "a.txt") << "Hello.\n";
    ASSERT_EQ(cli(db, {"emboss", "--queue", (dir / "a.txt").string()}, err).first, 0);
    auto no_broken_copy = [&] {
        for (const auto& f : std::filesystem::directory_iterator(dir.path()))
            EXPECT_EQ(f.path().filename().string().find(".broken-"), std::string::npos) << f.path();
    };

    // From a newer Tactus: refused by everything, but never moved aside.
    set_user_version(db, 99);
    const auto [ncode, nout] = cli(db, {"queue", "recover"}, err);
    EXPECT_EQ(ncode, 3) << nout;
    EXPECT_NE(test::read_text(err).find("newer Tactus"), std::string::npos) << test::read_text(err);
    EXPECT_TRUE(std::filesystem::exists(db));
    no_broken_copy();
    set_user_version(db, kSchemaVersion);

    if (geteuid() == 0) GTEST_SKIP() << "root writes read-only files: the read-only half needs another user";
    // Read-only file: healthy, kept, and the queue still lists.
    ASSERT_EQ(chmod(db.c_str(), 0444), 0);
    const auto [code, out] = cli(db, {"queue", "recover"}, err);
    EXPECT_EQ(code, 0) << out << test::read_text(err);
    EXPECT_NE(out.find("read-only"), std::string::npos) << out;
    EXPECT_NE(out.find("nothing moved"), std::string::npos) << out;
    EXPECT_TRUE(std::filesystem::exists(db));
    const auto [lcode, listed] = cli(db, {"queue", "list"}, err);
    EXPECT_EQ(lcode, 0) << test::read_text(err);
    EXPECT_NE(listed.find("a.txt"), std::string::npos) << listed;

    // A read-only database in a read-only folder is read-only, not "not usable".
    ASSERT_EQ(chmod(dir.path().c_str(), 0555), 0);
    const auto [rcode, rout] = cli(db, {"queue", "list"}, err);
    const auto rerr = test::read_text(err);
    ASSERT_EQ(chmod(dir.path().c_str(), 0755), 0);
    EXPECT_EQ(rcode, 0) << rerr;
    EXPECT_EQ(rerr.find("not a usable spool database"), std::string::npos) << rerr;
    ASSERT_EQ(chmod(db.c_str(), 0644), 0);
    no_broken_copy();
}

}  // namespace
}  // namespace tactus::spool
