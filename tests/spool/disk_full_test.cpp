// SPDX-License-Identifier: GPL-3.0-or-later
// A disk that fills mid-job, for real: the spool lives on a small tmpfs
// mounted in a mount namespace of this test's own (ctest runs the binary
// under `unshare -rm`, so no root is needed and the machine's mounts are never
// touched). The runner must say so, exit 1 and leave the job paused with the
// reason, and the job must then finish exactly once after room is made.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "e2e_rig.hpp"

namespace tactus::spool {
namespace {

using test::E2E;
using test::PtySim;

// True in a mount namespace other than the machine's (PID 1's): only there
// may the test mount.
bool own_mount_namespace() {
    std::error_code a, b;
    const auto self = std::filesystem::read_symlink("/proc/self/ns/mnt", a);
    const auto init = std::filesystem::read_symlink("/proc/1/ns/mnt", b);
    return !a && (b || self != init);
}

// Fills the disk holding `dir` to the last byte.
void fill(const std::filesystem::path& file) {
    std::ofstream out(file, std::ios::binary);
    const std::string block(64 * 1024, '\0');
    while (out.write(block.data(), static_cast<std::streamsize>(block.size()))) {
    }
    out.close();
    const std::string byte(1, '\0');
    std::ofstream(file, std::ios::binary | std::ios::app).write(byte.data(), 1);
}

TEST(DiskFull, MidJobServeExitsOneTheJobIsPausedThenFinishesExactlyOnce) {
    if (!own_mount_namespace()) GTEST_SKIP() << "run under `unshare -rm` (ctest does): the test mounts a tmpfs";
    E2E e;
    const auto disk = e.dir / "disk";
    std::filesystem::create_directory(disk);
    const auto mount = "mount -t tmpfs -o size=4m tactus-test " + disk.string();
    ASSERT_EQ(std::system(mount.c_str()), 0) << mount;
    e.db = disk / "spool.db";
    // The simulator's strike log stays outside the full disk, for the audit.
    PtySim sim(e.dir.path(), "sim", {}, 40);
    ASSERT_FALSE(sim.path().empty());
    ASSERT_EQ(e.cli({"queue", "printer", "add", "lab", "--device", sim.device()}).first, 0);
    const JobId id = e.queue_text(test::kText, {"--copies", "4"});

    auto serve = e.serve({"--write-retry-ms", "500"});
    ASSERT_TRUE(e.wait_for(
        [&](const JobRecord&) {
            auto s = Spool::open(e.db, {.create = false});
            if (!s) return false;
            const auto p = s->progress(id);
            return p && !p->empty() && p->front().passes_done > 0;
        },
        id))
        << e.history(id);
    fill(disk / "fill");
    EXPECT_EQ(serve->wait(), 1);
    const auto said = test::read_text((e.dir / "serve.log").string());
    EXPECT_NE(said.find("disk is full"), std::string::npos) << said;
    EXPECT_NE(said.find("job " + std::to_string(id) + " is paused"), std::string::npos) << said;
    {
        auto s = e.spool();
        const auto job = s.job(id);
        ASSERT_TRUE(job);
        EXPECT_EQ(job->state, JobState::paused) << e.history(id);
        EXPECT_NE(job->reason.find("disk is full"), std::string::npos) << job->reason;
        EXPECT_TRUE(job->runner.empty()) << job->runner;
    }

    std::filesystem::remove(disk / "fill");
    ASSERT_EQ(e.cli({"queue", "resume", std::to_string(id)}).first, 0);
    auto again = e.serve();
    ASSERT_TRUE(e.wait_state(id, JobState::completed)) << e.history(id);
    again->signal(SIGTERM);
    EXPECT_EQ(again->wait(), 0);
    const auto audit = e.audit(id, sim);
    EXPECT_EQ(audit.problems, "") << e.history(id);
    EXPECT_EQ(audit.sheets_checked, e.spool().job(id)->total_sheets());
    const auto umount = "umount " + disk.string();
    EXPECT_EQ(std::system(umount.c_str()), 0);
}

}  // namespace
}  // namespace tactus::spool
