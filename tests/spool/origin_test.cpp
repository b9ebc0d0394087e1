// SPDX-License-Identifier: GPL-3.0-or-later
// Jobs sent from another system (CUPS) carry an origin; submitting the same
// origin again gives the same job, so a CUPS job run twice is queued once.
#include <gtest/gtest.h>

#include <thread>

#include "spool/spool.hpp"
#include "spool/sqlite.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

using test::submission;
using test::TempDir;

TEST(SpoolOrigin, TheSameOriginGivesTheSameJobAcrossReopen) {
    TempDir dir;
    const auto db = dir / "spool.db";
    JobId first = 0;
    {
        auto s = Spool::open(db);
        ASSERT_TRUE(s) << s.error().to_string();
        ASSERT_TRUE(s->add_printer("lab", "pty:/dev/null", R"({"name":"test"})"));
        auto job = submission("lab", 3);
        job.origin = "cups:urn:uuid:1";
        first = *s->submit(job);
        EXPECT_EQ(*s->submit(job), first);
        auto other = submission("lab", 3);
        other.origin = "cups:urn:uuid:2";
        EXPECT_NE(*s->submit(other), first);
        EXPECT_NE(*s->submit(submission("lab", 3)), first);  // no origin: always a new job
    }
    auto s = Spool::open(db, {.create = false});
    ASSERT_TRUE(s);
    auto job = submission("lab", 3);
    job.origin = "cups:urn:uuid:1";
    EXPECT_EQ(*s->submit(job), first);
    EXPECT_EQ(s->jobs(true)->size(), 3u);
    const auto found = s->job_by_origin("cups:urn:uuid:1");
    ASSERT_TRUE(found && *found);
    EXPECT_EQ((*found)->id, first);
    EXPECT_FALSE(*s->job_by_origin("cups:urn:uuid:unknown"));
}

TEST(SpoolOrigin, FourSubmittersOfOneOriginMakeOneJob) {
    TempDir dir;
    const auto db = dir / "spool.db";
    {
        auto s = Spool::open(db);
        ASSERT_TRUE(s->add_printer("lab", "pty:/dev/null", R"({"name":"test"})"));
    }
    std::vector<JobId> ids(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < ids.size(); ++t)
        threads.emplace_back([&, t] {
            auto s = Spool::open(db, {.create = false});
            auto job = submission("lab", 2);
            job.origin = "cups:same";
            if (s) ids[t] = s->submit(job).value_or(0);
        });
    for (auto& t : threads) t.join();
    for (const auto id : ids) EXPECT_EQ(id, ids[0]);
    EXPECT_NE(ids[0], 0);
    EXPECT_EQ(Spool::open(db, {.create = false})->jobs(true)->size(), 1u);
}

TEST(SpoolOrigin, ASpoolWrittenBeforeOriginsGainsTheTable) {
    TempDir dir;
    const auto db = dir / "spool.db";
    {
        auto s = Spool::open(db);
        ASSERT_TRUE(s->add_printer("lab", "pty:/dev/null", R"({"name":"test"})"));
        ASSERT_TRUE(s->submit(submission("lab", 2)));
    }
    {
        // As an older Tactus left it: no job_origins table.
        auto raw = sql::Database::open(db, false, 1000);
        ASSERT_TRUE(raw);
        ASSERT_TRUE(raw->exec("DROP TABLE job_origins"));
    }
    auto s = Spool::open(db, {.create = false});
    ASSERT_TRUE(s) << s.error().to_string();
    auto job = submission("lab", 2);
    job.origin = "cups:x";
    const auto id = s->submit(job);
    ASSERT_TRUE(id) << id.error().to_string();
    EXPECT_EQ(*s->submit(job), *id);
    EXPECT_EQ(s->jobs(true)->size(), 2u);
}

}  // namespace
}  // namespace tactus::spool
