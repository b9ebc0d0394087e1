// SPDX-License-Identifier: GPL-3.0-or-later
// `tactus-cli emboss --device ipp://.../printers/NAME` against a real cupsd
// (private, loopback only): the CLI sends the source document over IPP, the
// server's tactus-layout filter and tactus backend emboss it on the
// simulated controller, and the CLI follows the job there to its end. One
// cupsd serves the whole suite (a shared fixture); each test adds its own
// queue on its own simulator.
#include <gtest/gtest.h>

#include <csignal>
#include <regex>

#include "cups_rig.hpp"
#include "ipp/remote_queues.hpp"

namespace tactus::cups {
namespace {

using spool::JobState;
using test::CupsRig;
using test::PtySim;

int cups_job_id(const std::string& out) {
    std::smatch m;
    return std::regex_search(out, m, std::regex("as job ([0-9]+)")) ? std::stoi(m[1]) : 0;
}

class CupsIppE2E : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        if (test::have_cupsd()) rig_ = std::make_unique<CupsRig>();
    }
    static void TearDownTestSuite() { rig_.reset(); }
    void SetUp() override {
        if (!test::have_cupsd()) GTEST_SKIP() << "cupsd, lpadmin, lp, lpstat not installed";
        ASSERT_TRUE(rig_->started()) << rig_->error_log();
        before_ = rig().last_spool_job();
    }
    static CupsRig& rig() { return *rig_; }

    std::filesystem::path lesson_file(const std::string& name, int paragraphs) {
        return rig().lesson_file(name, paragraphs);
    }
    // tactus-cli emboss to queue `name`, as the teacher.
    std::vector<std::string> emboss(const std::string& queue, const std::filesystem::path& doc,
                                    std::vector<std::string> extra = {}, bool as_teacher = true) {
        std::vector<std::string> args{spool::test::kCli, "emboss", "--device",
                                      rig().queue_uri(queue)};
        args.insert(args.end(), extra.begin(), extra.end());
        args.push_back(doc.string());
        return rig().command(args, as_teacher);
    }
    // The CLI's job on the server, once the simulator has struck more than
    // `strikes` dots: its CUPS id (from the CLI's "as job N" line) and the
    // spool job the backend made for it.
    void wait_embossing(spool::test::Process& cli, const PtySim& sim, std::size_t strikes, int& cups_id,
                        spool::JobId& id) {
        const auto sent = cli.read_line(std::chrono::seconds(30));
        cups_id = cups_job_id(sent);
        ASSERT_GT(cups_id, 0) << sent;
        id = rig().newest_spool_job(before_);
        ASSERT_NE(id, 0) << rig().error_log();
        ASSERT_TRUE(rig().e.wait_for(
            [&](const spool::JobRecord&) { return sim.strikes().size() > strikes; }, id));
    }
    // The CLI's output and errors in one stream.
    static inline const spool::test::Process::Options merged{
        .stderr_file = {}, .merge_stderr = true, .stdin_text = {}};

    spool::JobId before_ = 0;  // the newest spool job before this test
    static inline std::unique_ptr<CupsRig> rig_;
};


TEST_F(CupsIppE2E, TheCliSendsTheDocumentAndFollowsTheJobToCompletion) {
    PtySim sim(rig().e.dir.path(), "sim-complete");
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserA")) << rig().error_log();
    const auto doc = lesson_file("complete.md", 3);
    const auto [code, out] =
        spool::test::run(emboss("EmbosserA", doc, {"-t", "en-ueb-g1", "--copies", "2"}));
    ASSERT_EQ(code, 0) << out << rig().error_log();
    const int cups_id = cups_job_id(out);
    ASSERT_GT(cups_id, 0) << out;
    // It followed the job: processing with sheets counted by the server,
    // then completed; the last line says so.
    const auto prefix = "job " + std::to_string(cups_id) + " ";
    EXPECT_NE(out.find(prefix + "processing"), std::string::npos) << out;
    EXPECT_NE(out.find(prefix + "completed"), std::string::npos) << out;
    EXPECT_NE(
        out.find("embossed job " + std::to_string(cups_id) + " on " + rig().queue_uri("EmbosserA")),
        std::string::npos)
        << out;
    // The server laid it out and embossed it through its spool, exactly as planned.
    const auto id = rig().newest_spool_job(before_);
    ASSERT_NE(id, 0) << rig().error_log();
    ASSERT_TRUE(rig().e.wait_state(id, JobState::completed)) << rig().e.history(id);
    const auto job = *rig().e.spool().job(id);
    EXPECT_EQ(job.copies, 2u);
    if (test::is_root()) {
        EXPECT_EQ(job.user, test::kTeacher);
    }
    const auto audit = rig().e.audit(id, sim);
    EXPECT_EQ(audit.problems, "");
    EXPECT_EQ(audit.sheets_checked, job.total_sheets());
    // The sheet count the CLI printed last is the server's page count.
    std::smatch m;
    std::string last_count;
    for (auto it = out.cbegin();
         std::regex_search(it, out.cend(), m, std::regex("sheets embossed: ([0-9]+)"));
         it = m[0].second)
        last_count = m[1];
    EXPECT_EQ(last_count, std::to_string(job.total_sheets())) << out;
}

TEST_F(CupsIppE2E, ACancelOnTheServerEndsTheCliWithExit1) {
    PtySim sim(rig().e.dir.path(), "sim-cancel", {}, 100);  // slow: still running when cancelled
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserB"));
    const auto doc = lesson_file("cancel.md", 6);
    spool::test::Process cli(emboss("EmbosserB", doc, {"--copies", "5"}), merged);
    int cups_id = 0;
    spool::JobId id = 0;
    ASSERT_NO_FATAL_FAILURE(wait_embossing(cli, sim, 20, cups_id, id));
    const auto [code, msg] = rig().client({"cancel", "EmbosserB-" + std::to_string(cups_id)});
    ASSERT_EQ(code, 0) << msg;
    const auto rest = cli.read_all();
    EXPECT_EQ(cli.wait(), 1) << rest;
    EXPECT_NE(rest.find("job " + std::to_string(cups_id) + " was cancelled on " +
                        rig().queue_uri("EmbosserB")),
              std::string::npos)
        << rest;
    ASSERT_TRUE(rig().e.wait_state(id, JobState::cancelled)) << rig().e.history(id);
    EXPECT_LT(sim.strikes().size(), rig().e.plan_of(id).strikes);
}

TEST_F(CupsIppE2E, CtrlCInTheCliCancelsTheJobOnTheServer) {
    PtySim sim(rig().e.dir.path(), "sim-interrupt", {}, 100);
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserC"));
    const auto doc = lesson_file("interrupt.md", 6);
    // Not through runuser: the signal goes to tactus-cli itself.
    spool::test::Process cli(emboss("EmbosserC", doc, {"--copies", "5"}, /*as_teacher=*/false),
                             merged);
    int cups_id = 0;
    spool::JobId id = 0;
    ASSERT_NO_FATAL_FAILURE(wait_embossing(cli, sim, 20, cups_id, id));
    cli.signal(SIGINT);
    const auto rest = cli.read_all();
    EXPECT_EQ(cli.wait(), 1) << rest;
    EXPECT_NE(rest.find("was cancelled on"), std::string::npos) << rest;
    ASSERT_TRUE(rig().e.wait_state(id, JobState::cancelled)) << rig().e.history(id);
    EXPECT_FALSE(rig().cups_job_active(cups_id));
}

TEST_F(CupsIppE2E, TheCliWaitsThroughACupsdRestartAndSeesTheJobComplete) {
    PtySim sim(rig().e.dir.path(), "sim-restart", {}, 300);
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserR"));
    const auto doc = lesson_file("restart.md", 4);
    spool::test::Process cli(emboss("EmbosserR", doc, {"--copies", "3"}), merged);
    int cups_id = 0;
    spool::JobId id = 0;
    ASSERT_NO_FATAL_FAILURE(wait_embossing(cli, sim, 100, cups_id, id));
    rig().kill_cupsd();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ASSERT_TRUE(rig().restart_cupsd()) << rig().error_log();
    const auto rest = cli.read_all();
    EXPECT_EQ(cli.wait(), 0) << rest << rig().error_log();
    EXPECT_NE(rest.find("embossed job " + std::to_string(cups_id)), std::string::npos) << rest;
    ASSERT_TRUE(rig().e.wait_state(id, JobState::completed)) << rig().e.history(id);
    const auto audit = rig().e.audit(id, sim);
    EXPECT_EQ(audit.problems, "") << rig().e.history(id);
}

TEST_F(CupsIppE2E, AnUnknownTableEndsTheCliWithTheFiltersErrorAndEmbossesNothing) {
    PtySim sim(rig().e.dir.path(), "sim-badtable");
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserD"));
    const auto doc = lesson_file("badtable.md", 1);
    spool::test::Process cli(
        emboss("EmbosserD", doc, {"-t", "no-such-table"}),
        merged);
    const auto out = cli.read_all();
    EXPECT_EQ(cli.wait(), 1) << out;
    // CUPS ends a job its filter refused as cancelled, with the filter's ERROR: line.
    EXPECT_NE(out.find("was cancelled on " + rig().queue_uri("EmbosserD") +
                       ": option braille-table: 'no-such-table' is not an installed braille table"),
              std::string::npos)
        << out;
    EXPECT_TRUE(sim.strikes().empty());
}

TEST_F(CupsIppE2E, AQueueThatIsNotThereIsExit4AndOptionsTheServerDecidesAreExit2) {
    const auto doc = lesson_file("nowhere.md", 1);
    const auto full = rig().client(
        {spool::test::kCli, "emboss", "--device", rig().queue_uri("NoSuchQueue"), doc.string()});
    EXPECT_EQ(full.first, 4);
    EXPECT_NE(full.second.find("cannot send the job"), std::string::npos) << full.second;
    const auto preset = rig().client({spool::test::kCli, "emboss", "--preset", "letter", "--device",
                                      rig().queue_uri("NoSuchQueue"), doc.string()});
    EXPECT_EQ(preset.first, 2);
    EXPECT_NE(preset.second.find("--preset cannot go to a CUPS queue"), std::string::npos)
        << preset.second;
}

TEST_F(CupsIppE2E, TheServersTactusQueuesAreListedAndOtherQueuesAreNot) {
    PtySim sim(rig().e.dir.path(), "sim-list");
    ASSERT_TRUE(rig().add_queue(sim, "EmbosserList"));
    // A queue that is not a Tactus one: CUPS's own ipp backend to a printer
    // nobody answers (never printed to). cupsd takes a device URI only for a
    // backend in its ServerBin.
    std::error_code ec;
    std::filesystem::create_symlink("/usr/lib/cups/backend/ipp", rig().cups_dir / "bin/backend/ipp",
                                    ec);
    const auto [code, msg] = rig().client(
        {"lpadmin", "-p", "Laser", "-E", "-v", "ipp://127.0.0.1:9/ipp/print", "-m", "raw"});
    ASSERT_EQ(code, 0) << msg;
    ASSERT_EQ(rig().client({"lpstat", "-p", "Laser"}).first, 0);  // it is there, and left out
    const auto server = rig().server();
    const auto host = server.substr(0, server.rfind(':'));
    const int port = std::stoi(server.substr(server.rfind(':') + 1));
    const auto queues = ipp::tactus_queues(host, port);
    ASSERT_TRUE(queues) << queues.error().to_string();
    std::vector<std::string> names;
    for (const auto& q : *queues) names.push_back(q.name);
    EXPECT_NE(std::find(names.begin(), names.end(), "EmbosserList"), names.end());
    EXPECT_EQ(std::find(names.begin(), names.end(), "Laser"), names.end());
    for (const auto& q : *queues) {
        if (q.name != "EmbosserList") continue;
        EXPECT_EQ(q.uri, rig().queue_uri("EmbosserList"));
        EXPECT_EQ(q.make_and_model, "Tactus Braille Embosser");
        EXPECT_TRUE(q.accepting);
        EXPECT_TRUE(q.state.starts_with("idle")) << q.state;
    }
}

}  // namespace
}  // namespace tactus::cups
