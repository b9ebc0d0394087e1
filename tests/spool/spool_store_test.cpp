// SPDX-License-Identifier: GPL-3.0-or-later
// The spool database on a real file: persistence across reopen, queue order,
// operator actions, progress bookkeeping, runner take-over, concurrency and
// every way the file can be unusable.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <thread>
#include <vector>

#include "common/file_io.hpp"
#include "spool/runner_token.hpp"
#include "spool/schema.hpp"
#include "spool/spool.hpp"
#include "spool/sqlite.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

using test::submission;
using test::TempDir;

constexpr const char* kProfile = R"({"name":"test"})";

Spool open_with_printer(const std::filesystem::path& db) {
    auto s = Spool::open(db);
    EXPECT_TRUE(s) << s.error().to_string();
    EXPECT_TRUE(s->add_printer("lab", "pty:/dev/null", kProfile));
    return std::move(*s);
}

std::string file_bytes(const std::filesystem::path& p) {
    auto r = read_file(p);
    return r ? *r : std::string();
}

TEST(SpoolStore, CreatesItsFolderAndKeepsJobsAcrossReopen) {
    TempDir dir;
    const auto db = dir / "deep/er/spool.db";
    JobId id = 0;
    {
        Spool s = open_with_printer(db);
        auto r = s.submit(submission("lab", 9, 2));
        ASSERT_TRUE(r) << r.error().to_string();
        id = *r;
    }
    auto s = Spool::open(db, {.create = false});
    ASSERT_TRUE(s) << s.error().to_string();
    auto j = s->job(id);
    ASSERT_TRUE(j);
    EXPECT_EQ(j->state, JobState::queued);
    EXPECT_EQ(j->sheets_per_copy, 5u);
    EXPECT_EQ(j->total_sheets(), 10u);
    EXPECT_EQ(j->user, "teacher");
    EXPECT_EQ(*s->profile_snapshot(id), kProfile);
    auto doc = from_snapshot(*s->document_snapshot(id));
    ASSERT_TRUE(doc);
    EXPECT_EQ(doc->pages, test::make_document(9, true).pages);
    auto events = s->events(id);
    ASSERT_TRUE(events);
    ASSERT_EQ(events->size(), 1u);
    EXPECT_EQ(events->front().kind, "submitted");
}

// A folder that cannot be made is an I/O failure (exit 1 in the CLI), not bad
// input (exit 3, which said the user's file was at fault).
TEST(SpoolStore, AFolderThatCannotBeMadeIsAnIoFailure) {
    TempDir dir;
    std::ofstream(dir / "plain-file").flush();
    const auto s = Spool::open(dir / "plain-file/spool/spool.db");
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().kind, ErrorKind::io) << s.error().to_string();
    EXPECT_NE(s.error().message.find("cannot create the spool folder"), std::string::npos) << s.error().to_string();
}

// The CUPS backend (user lp) creates the shared spool; SQLite makes the empty
// file before the schema. A reader that may not create (a root `queue list`,
// the CUPS test rig polling) used to write the schema into that empty file
// itself, racing its creator: CupsIppE2E saw the backend fail with "attempt
// to write a readonly database". Now such a reader finds nothing there yet and
// writes nothing; the creator then opens it as usual, and diagnose calls it
// missing, never foreign (recover would have moved it aside).
TEST(SpoolStore, AReaderLeavesAnEmptySpoolFileToItsCreator) {
    TempDir dir;
    const auto db = dir / "spool.db";
    std::ofstream(db).flush();  // the file as sqlite3_open leaves it, before the schema
    const auto s = Spool::open(db, {.create = false});
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("no spool database here yet"), std::string::npos) << s.error().to_string();
    EXPECT_EQ(std::filesystem::file_size(db), 0U) << "the reader wrote into the creator's file";
    EXPECT_FALSE(std::filesystem::exists(dir / "spool.db-wal"));
    EXPECT_EQ(diagnose(db).health, SpoolHealth::missing);
    auto created = Spool::open(db);
    ASSERT_TRUE(created) << created.error().to_string();
    EXPECT_TRUE(created->add_printer("lab", "pty:/dev/null", kProfile));
}

// cupsd starts a server's first job's filter and backend together, and both
// create the spool: the loser once met a half-made file and failed ("unable
// to open database file"), which stops the CUPS queue. Creators racing on a
// fresh path must all open the one spool, whoever wins.
TEST(SpoolStore, CreatorsRacingOnANewPathAllOpenTheSameSpool) {
    TempDir dir;
    for (int round = 0; round < 30; ++round) {
        const auto db = dir / ("spool-" + std::to_string(round) + ".db");
        constexpr int kCreators = 4;
        std::vector<std::string> errors(kCreators);
        std::vector<std::thread> creators;
        for (int i = 0; i < kCreators; ++i)
            creators.emplace_back([&, i] {
                auto s = Spool::open(db);
                if (!s) errors[static_cast<std::size_t>(i)] = s.error().to_string();
                else if (auto p = s->printers(); !p) errors[static_cast<std::size_t>(i)] = p.error().to_string();
            });
        for (auto& t : creators) t.join();
        for (int i = 0; i < kCreators; ++i) EXPECT_EQ(errors[static_cast<std::size_t>(i)], "") << "round " << round;
        auto s = Spool::open(db, {.create = false});
        ASSERT_TRUE(s) << s.error().to_string();
        EXPECT_TRUE(s->add_printer("lab", "pty:/dev/null", kProfile));
    }
    // Nothing of the making is left beside the spools.
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(entry.path().filename().string().find(".new-"), std::string::npos) << entry.path();
}

TEST(SpoolStore, ProfileSnapshotIsTakenAtSubmission) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const JobId id = *s.submit(submission("lab", 2));
    ASSERT_TRUE(s.update_printer("lab", {}, std::string(R"({"name":"recalibrated"})")));
    EXPECT_EQ(*s.profile_snapshot(id), kProfile);
    EXPECT_EQ(s.printer("lab")->profile_json, R"({"name":"recalibrated"})");
}

TEST(SpoolStore, UnknownPrinterIsAClearErrorAndQueuesNothing) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    auto r = s.submit(submission("nope", 2));
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("unknown printer 'nope' (known: lab)"), std::string::npos)
        << r.error().message;
    EXPECT_TRUE(s.jobs(true)->empty());
    EXPECT_FALSE(s.add_printer("lab", "pty:/dev/x", kProfile));
}

TEST(SpoolStore, ClaimsByPriorityThenAgeAndSkipsBackOff) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const auto pid = s.printer("lab")->id;
    const JobId low = *s.submit(submission("lab", 2, 1, 0));
    const JobId high = *s.submit(submission("lab", 2, 1, 5));
    const JobId low2 = *s.submit(submission("lab", 2, 1, 0));
    const auto token = this_runner_token();
    ASSERT_TRUE(s.claim_printer(pid, token));
    auto first = s.claim_next(pid, token, now_seconds());
    ASSERT_TRUE(first && *first);
    EXPECT_EQ((*first)->id, high);
    EXPECT_EQ((*first)->state, JobState::running);
    EXPECT_EQ((*first)->runner, token);
    // `low` fails transiently and backs off: `low2` goes first.
    auto second = s.claim_next(pid, token, now_seconds());
    EXPECT_EQ((*second)->id, low);
    ASSERT_TRUE(s.requeue(low, "device gone", now_seconds() + 3600, true));
    auto third = s.claim_next(pid, token, now_seconds());
    EXPECT_EQ((*third)->id, low2);
    EXPECT_FALSE(*s.claim_next(pid, token, now_seconds()));
    auto later = s.claim_next(pid, token, now_seconds() + 7200);
    ASSERT_TRUE(later && *later);
    EXPECT_EQ((*later)->id, low);
    EXPECT_EQ((*later)->retries, 1);
}

TEST(SpoolStore, OperatorActionsFollowTheStateMachineAndAreLogged) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const auto pid = s.printer("lab")->id;
    const JobId id = *s.submit(submission("lab", 4));
    EXPECT_EQ(s.act(id, Action::pause)->state, JobState::paused);
    EXPECT_FALSE(s.claim_next(pid, "h:1", now_seconds()).value());  // paused jobs wait
    auto resumed = s.act(id, Action::resume);
    ASSERT_TRUE(resumed) << resumed.error().to_string();
    EXPECT_EQ(resumed->state, JobState::queued) << resumed->runner << "|" << to_string(resumed->control);
    const auto token = this_runner_token();
    ASSERT_TRUE(s.claim_printer(pid, token));
    ASSERT_TRUE(s.claim_next(pid, token, now_seconds()).value());
    // Running: the request is left for the runner.
    auto paused = s.act(id, Action::pause);
    ASSERT_TRUE(paused);
    EXPECT_EQ(paused->state, JobState::running);
    EXPECT_EQ(paused->control, Control::pause);
    EXPECT_EQ(*s.take_control(id), Control::pause);
    EXPECT_EQ(*s.take_control(id), Control::none);  // taken once
    ASSERT_TRUE(s.set_state(id, JobState::paused, "paused by the operator", "paused", "stopped", /*held=*/true));
    EXPECT_EQ(s.act(id, Action::resume)->control, Control::resume);
    EXPECT_EQ(s.act(id, Action::cancel)->control, Control::cancel);
    ASSERT_TRUE(s.set_state(id, JobState::cancelled, "cancelled by the operator", "cancelled", "aborted"));
    auto done = s.job(id);
    EXPECT_EQ(done->state, JobState::cancelled);
    EXPECT_TRUE(done->runner.empty());
    EXPECT_TRUE(done->finished_at);
    auto again = s.act(id, Action::cancel);
    ASSERT_FALSE(again);
    EXPECT_EQ(again.error().where, "job " + std::to_string(id));
    auto retried = s.act(id, Action::retry, 2);
    ASSERT_TRUE(retried) << retried.error().to_string();
    EXPECT_EQ(retried->state, JobState::queued);
    EXPECT_EQ(retried->resume_sheet, 2u);
    EXPECT_FALSE(s.act(id, Action::retry, 99));  // job has 2 sheets
    std::vector<std::string> kinds;
    const auto events = *s.events(id);
    for (const auto& e : events) kinds.push_back(e.kind);
    EXPECT_EQ(kinds, (std::vector<std::string>{"submitted", "pause", "resume", "started", "pause",
                                               "paused", "resume", "cancel", "cancelled", "retry"}));
}

TEST(SpoolStore, AnOppositeRequestWithdrawsOneTheRunnerHasNotTaken) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const auto pid = s.printer("lab")->id;
    const JobId id = *s.submit(submission("lab", 4));
    const auto token = this_runner_token();
    ASSERT_TRUE(s.claim_printer(pid, token));
    ASSERT_TRUE(s.claim_next(pid, token, now_seconds()).value());
    // Pause, then Resume before the runner looked: nothing is left for it.
    EXPECT_EQ(s.act(id, Action::pause)->control, Control::pause);
    auto resumed = s.act(id, Action::resume);
    ASSERT_TRUE(resumed) << resumed.error().to_string();
    EXPECT_EQ(resumed->state, JobState::running);
    EXPECT_EQ(resumed->control, Control::none);
    EXPECT_EQ(*s.take_control(id), Control::none);
    // Paused on the printer: Resume, then Pause before the runner looked.
    ASSERT_TRUE(s.set_state(id, JobState::paused, "paused by the operator", "paused", "stopped", /*held=*/true));
    EXPECT_EQ(s.act(id, Action::resume)->control, Control::resume);
    auto paused = s.act(id, Action::pause);
    ASSERT_TRUE(paused) << paused.error().to_string();
    EXPECT_EQ(paused->state, JobState::paused);
    EXPECT_EQ(paused->control, Control::none);
    const auto events = *s.events(id);
    EXPECT_NE(events.back().message.find("had not reached the runner and is withdrawn"), std::string::npos);
}

TEST(SpoolStore, ProgressOnlyGrowsAndSpoilingRestartsASheet) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const JobId id = *s.submit(submission("lab", 4));
    ASSERT_TRUE(s.set_sheet_passes(id, {30, 28}));
    ASSERT_TRUE(s.record_passes(id, 1, 30));
    ASSERT_TRUE(s.record_passes(id, 2, 11));
    ASSERT_TRUE(s.record_passes(id, 2, 7));  // late duplicate: ignored
    EXPECT_FALSE(s.record_passes(id, 2, 29));  // beyond the plan
    EXPECT_FALSE(s.record_passes(id, 3, 1));   // no such sheet
    auto p = *s.progress(id);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(p[0].done());
    EXPECT_EQ(p[1].passes_done, 11u);
    ASSERT_TRUE(s.spoil_sheet(id, 2, "sheet 2 ejected at pass 11 of 28"));
    p = *s.progress(id);
    EXPECT_EQ(p[1].passes_done, 0u);
    EXPECT_EQ(p[1].spoiled, 1u);
    // Re-planning keeps what was done.
    ASSERT_TRUE(s.set_sheet_passes(id, {30, 28}));
    EXPECT_TRUE((*s.progress(id))[0].done());
}

TEST(SpoolStore, ADeadRunnersJobsAreReleasedWithTheirWriteAheadRecord) {
    TempDir dir;
    Spool s = open_with_printer(dir / "spool.db");
    const auto pid = s.printer("lab")->id;
    const JobId id = *s.submit(submission("lab", 6));
    // A process that has exited: its pid is free, so the token is dead.
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    const std::string dead = std::string(host) + ":" + std::to_string(child);
    ASSERT_FALSE(runner_alive(dead));
    ASSERT_TRUE(s.claim_printer(pid, dead));
    ASSERT_TRUE(s.claim_next(pid, dead, now_seconds()).value());
    ASSERT_TRUE(s.set_sheet_passes(id, {4, 5, 6}));
    const auto link_job = s.begin_run(id, 2, 4, 0);
    ASSERT_TRUE(link_job);
    EXPECT_GE(*link_job, kFirstLinkJob);

    const auto me = this_runner_token();
    ASSERT_TRUE(s.claim_printer(pid, me)) << "a dead holder must not block the printer";
    auto j = *s.job(id);
    EXPECT_EQ(j.state, JobState::queued);
    EXPECT_TRUE(j.runner.empty());
    EXPECT_TRUE(j.run_open);
    EXPECT_EQ(j.link_job, *link_job);
    EXPECT_EQ(j.run_start_sheet, 2u);
    EXPECT_EQ(j.run_first_pass, 4u);
    EXPECT_EQ(s.events(id)->back().kind, "interrupted");

    // A live holder (this process, another token) is respected.
    auto other = s.claim_printer(pid, std::string(host) + ":1");  // pid 1 is alive
    ASSERT_FALSE(other);
    EXPECT_NE(other.error().message.find("already served by"), std::string::npos);
}

TEST(SpoolStore, EachRunGetsTheNextControllerJobIdNeverTheOneTheControllerHolds) {
    TempDir dir;
    auto s = *Spool::open(dir / "spool.db");
    ASSERT_TRUE(s.add_printer("lab", "sim", "{}"));
    const JobId id = *s.submit(submission("lab", 2));
    ASSERT_TRUE(s.set_sheet_passes(id, {4}));
    const auto a = *s.begin_run(id, 1, 0, 0);
    const auto b = *s.begin_run(id, 1, 0, static_cast<std::uint16_t>(a + 1));  // the controller holds a+1
    EXPECT_EQ(a, kFirstLinkJob);
    EXPECT_EQ(b, a + 2);
    // Settling closes the run in the same transaction as its records.
    RunSettlement settlement;
    settlement.record = {{1, 3}};
    settlement.discard = 1;
    settlement.discard_message = "sheet 1 was interrupted after pass 3 of 4 (the controller's count)";
    settlement.message = "settled";
    ASSERT_TRUE(s.settle_run(id, settlement));
    EXPECT_FALSE(s.job(id)->run_open);
    EXPECT_EQ((*s.progress(id))[0].passes_done, 0u);
    EXPECT_EQ((*s.progress(id))[0].spoiled, 1u);
    EXPECT_TRUE(s.open_runs(s.printer("lab")->id)->empty());
}

TEST(SpoolStore, AVersion1SpoolIsUpgradedInPlace) {
    TempDir dir;
    const auto db = dir / "spool.db";
    {
        auto s = *Spool::open(db);
        ASSERT_TRUE(s.add_printer("lab", "sim", "{}"));
        ASSERT_TRUE(s.submit(submission("lab", 2)));
    }
    // Back to the version 1 layout: without the two columns version 2 added.
    {
        sqlite3* h = nullptr;
        ASSERT_EQ(sqlite3_open(db.c_str(), &h), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(h,
                               "ALTER TABLE printers DROP COLUMN next_link_job; "
                               "ALTER TABLE jobs DROP COLUMN run_first_pass; PRAGMA user_version=1;",
                               nullptr, nullptr, nullptr),
                  SQLITE_OK)
            << sqlite3_errmsg(h);
        sqlite3_close(h);
    }
    auto s = Spool::open(db);
    ASSERT_TRUE(s) << s.error().to_string();
    EXPECT_EQ(s->jobs(false)->size(), 1u);
    EXPECT_TRUE(s->begin_run(1, 1, 0, 0));
}

TEST(SpoolStore, ConcurrentClientsAddAndCancelWithoutLosingAnything) {
    TempDir dir;
    const auto db = dir / "spool.db";
    { Spool s = open_with_printer(db); }
    constexpr int kClients = 4, kJobs = 40;
    std::vector<std::thread> clients;
    std::atomic<int> failures{0};
    for (int c = 0; c < kClients; ++c)
        clients.emplace_back([&, c] {
            auto s = Spool::open(db);
            if (!s) { ++failures; return; }
            for (int i = 0; i < kJobs; ++i) {
                auto id = s->submit(submission("lab", 2, 1, c));
                if (!id) { ++failures; continue; }
                // Every other job is cancelled straight away by its client.
                if (i % 2 && !s->act(*id, Action::cancel)) ++failures;
            }
        });
    for (auto& t : clients) t.join();
    EXPECT_EQ(failures.load(), 0);
    auto s = Spool::open(db);
    auto all = *s->jobs(true);
    ASSERT_EQ(all.size(), std::size_t{kClients * kJobs});
    int cancelled = 0;
    for (const auto& j : all) cancelled += j.state == JobState::cancelled;
    EXPECT_EQ(cancelled, kClients * kJobs / 2);
    EXPECT_EQ(s->events({}, 100000)->size(), std::size_t{1 + kClients * kJobs * 3 / 2});
    EXPECT_TRUE(s->check());
}

TEST(SpoolStore, ADamagedFileIsRefusedAndLeftUntouched) {
    TempDir dir;
    const auto db = dir / "spool.db";
    const std::string garbage(8192, 'x');
    ASSERT_TRUE(write_file_atomic(db, garbage));
    auto s = Spool::open(db);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().where, db.string());
    EXPECT_NE(s.error().message.find("not a usable spool database"), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().message.find("left untouched"), std::string::npos);
    EXPECT_EQ(file_bytes(db), garbage);
    auto aside = set_aside(db);
    ASSERT_TRUE(aside) << aside.error().to_string();
    EXPECT_EQ(file_bytes(*aside), garbage);
    EXPECT_FALSE(std::filesystem::exists(db));
    EXPECT_TRUE(Spool::open(db));
}

TEST(SpoolStore, AnotherProgramsDatabaseIsRefused) {
    TempDir dir;
    const auto db = dir / "other.db";
    {
        auto raw = sql::Database::open(db, true, 1000);
        ASSERT_TRUE(raw);
        ASSERT_TRUE(raw->exec("CREATE TABLE t(x); INSERT INTO t VALUES(1)"));
    }
    auto s = Spool::open(db);
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("not a Tactus spool"), std::string::npos);
}

TEST(SpoolStore, ALockedDatabaseIsAClearErrorNotAHang) {
    TempDir dir;
    const auto db = dir / "spool.db";
    { Spool s = open_with_printer(db); }
    auto holder = sql::Database::open(db, false, 1000);
    ASSERT_TRUE(holder);
    ASSERT_TRUE(holder->exec("BEGIN EXCLUSIVE"));
    auto s = Spool::open(db, {.busy_timeout_ms = 200});
    Result<JobId> r = s ? s->submit(submission("lab", 2)) : std::unexpected(s.error());
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().to_string().find("another process holds the spool database"), std::string::npos)
        << r.error().to_string();
    ASSERT_TRUE(holder->exec("ROLLBACK"));
}

TEST(SpoolStore, AFullDiskFailsTheSubmissionAndKeepsEarlierJobs) {
    TempDir dir;
    const auto db = dir / "spool.db";
    JobId kept = 0;
    {
        Spool s = open_with_printer(db);
        kept = *s.submit(submission("lab", 2));
    }
    // In a child: cap the file size so the next write cannot fit (the disk is "full").
    const pid_t child = fork();
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        // Three WAL frames' worth: the open succeeds, the 400-page document does not fit.
        constexpr rlim_t kLimit = 12 * 1024;
        rlimit lim{kLimit, kLimit};
        auto s = Spool::open(db);
        if (!s) _exit(2);
        setrlimit(RLIMIT_FSIZE, &lim);
        auto r = s->submit(submission("lab", 400));
        _exit(r ? 1 : 0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the oversized submission must fail, not half-succeed";
    auto s = Spool::open(db);
    ASSERT_TRUE(s);
    auto all = *s->jobs(true);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].id, kept);
    EXPECT_TRUE(s->check());
}

}  // namespace
}  // namespace tactus::spool
