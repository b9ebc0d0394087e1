// SPDX-License-Identifier: GPL-3.0-or-later
// The queue commands' answers to bad input: exit codes, messages naming what
// is wrong, and files left untouched.
#include <gtest/gtest.h>

#include <fstream>
#include <tuple>

#include "common/file_io.hpp"
#include "process.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

using test::run;
using test::TempDir;

const std::string kCli = TACTUS_CLI;

// tactus-cli <command> --db DB <rest>; stderr (this call's only) goes to `err`.
std::pair<int, std::string> cli(const std::filesystem::path& db, const std::vector<std::string>& args,
                                const std::filesystem::path& err) {
    std::vector<std::string> full{kCli, args.front(), "--db", db.string()};
    full.insert(full.end(), args.begin() + 1, args.end());
    std::filesystem::remove(err);
    test::Process p(full, err.string());
    auto out = p.read_all();
    return {p.wait(), out};
}

TEST(QueueCli, UnknownPrinterUnknownJobAndRefusedActionsAreBadInput) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
    std::ofstream(dir / "a.txt") << "Hello.\n";
    EXPECT_EQ(cli(db, {"emboss", "--queue", "--printer", "nope", (dir / "a.txt").string()}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("unknown printer 'nope' (known: lab)"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(cli(db, {"queue", "show", "42"}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("job 42: no such job"), std::string::npos);
    const auto [code, out] = cli(db, {"emboss", "--queue", (dir / "a.txt").string()}, err);
    ASSERT_EQ(code, 0) << test::read_text(err);
    EXPECT_EQ(out.rfind("queued job 1:", 0), 0u) << out;
    EXPECT_EQ(cli(db, {"queue", "cancel", "1"}, err).first, 0);
    EXPECT_EQ(cli(db, {"queue", "pause", "1"}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("job 1: job is cancelled: nothing to pause"), std::string::npos);
    EXPECT_EQ(cli(db, {"queue", "retry", "1", "--from-sheet", "9"}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("outside the job's 1 sheets"), std::string::npos);
    const auto [lcode, listed] = cli(db, {"queue", "list", "--all"}, err);
    EXPECT_EQ(lcode, 0);
    EXPECT_NE(listed.find("cancelled"), std::string::npos) << listed;
}

TEST(QueueCli, ADamagedDatabaseIsReportedKeptAndOnlyMovedAsideOnRequest) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    const std::string junk(10000, 'z');
    ASSERT_TRUE(write_file_atomic(db, junk));
    EXPECT_EQ(cli(db, {"queue", "list"}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("left untouched"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 3);
    EXPECT_EQ(*read_file(db), junk);
    const auto [code, out] = cli(db, {"queue", "recover"}, err);
    ASSERT_EQ(code, 0) << test::read_text(err);
    const auto pos = out.find("moved the damaged spool to ");
    ASSERT_NE(pos, std::string::npos) << out;
    const auto aside = out.substr(pos + 27, out.find(' ', pos + 27) - pos - 27);
    EXPECT_EQ(*read_file(aside), junk);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
}

TEST(QueueCli, ANewcomersFirstQueuedJobSetsUpTheSpoolAndAPrinterForTheDevice) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    std::ofstream(dir / "a.txt") << "Hello.\n";
    // Before anything was queued, a read-only command says what to do.
    EXPECT_EQ(cli(db, {"queue", "list"}, err).first, 3);
    EXPECT_NE(test::read_text(err).find("emboss --queue --device"), std::string::npos) << test::read_text(err);
    EXPECT_FALSE(std::filesystem::exists(db));
    // The README's example on a fresh machine.
    const auto [code, out] = cli(db, {"emboss", "--queue", "--device", "pty:/dev/null", (dir / "a.txt").string()}, err);
    ASSERT_EQ(code, 0) << test::read_text(err);
    EXPECT_EQ(out.rfind("queued job 1:", 0), 0u) << out;
    EXPECT_NE(test::read_text(err).find("set up queue printer 'null' on pty:/dev/null"), std::string::npos)
        << test::read_text(err);
    // The same device again: the same printer.
    ASSERT_EQ(cli(db, {"emboss", "--queue", "--device", "pty:/dev/null", (dir / "a.txt").string()}, err).first, 0);
    const auto [lcode, printers] = cli(db, {"queue", "printer", "list"}, err);
    EXPECT_EQ(lcode, 0);
    EXPECT_EQ(printers, "null  pty:/dev/null\n");
}

// --pages names braille pages as they are numbered, a book's preliminary
// pages too (Jekyll and Hyde in two volumes: t1 the title page, p1 the contents).
TEST(QueueCli, PagesAreNamedAsTheBookNumbersThem) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    const auto book = (std::filesystem::path(TACTUS_TEST_DATA) / "import" / "books" / "jekyll-and-hyde.epub").string();
    const auto queue = [&](const std::string& pages) {
        return cli(db, {"emboss", "--queue", "--device", "pty:/dev/null", "--volumes", "--pages", pages, book}, err);
    };
    auto [code, out] = queue("3-10");
    ASSERT_EQ(code, 0) << test::read_text(err);
    EXPECT_NE(out.find("4 sheet(s)"), std::string::npos) << out;
    std::tie(code, out) = queue("t1-p1");  // the title page, its blank back, the contents page
    ASSERT_EQ(code, 0) << test::read_text(err);
    EXPECT_NE(out.find("2 sheet(s)"), std::string::npos) << out;
    EXPECT_EQ(queue("999").first, 3);
    EXPECT_NE(test::read_text(err).find("page 999 is not in the document"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(queue("10-3").first, 3);
    EXPECT_NE(test::read_text(err).find("comes before"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(queue("x-1").first, 2);
    EXPECT_NE(test::read_text(err).find("expected FIRST-LAST"), std::string::npos) << test::read_text(err);
}

TEST(QueueCli, SeveralPrintersAndNoneChosenAreNamed) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    std::ofstream(dir / "a.txt") << "Hello.\n";
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "office", "--device", "sim"}, err).first, 0);
    EXPECT_EQ(cli(db, {"emboss", "--queue", (dir / "a.txt").string()}, err).first, 2);
    const auto e = test::read_text(err);
    EXPECT_NE(e.find("lab (pty:/dev/null)"), std::string::npos) << e;
    EXPECT_NE(e.find("office (sim)"), std::string::npos) << e;
    EXPECT_NE(e.find("--printer"), std::string::npos) << e;
}

TEST(QueueCli, AMalformedDeviceIsRefusedWhenThePrinterIsAdded) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "bogus:/dev/x"}, err).first, 2);  // exit_usage: a device string that cannot be used
    EXPECT_NE(test::read_text(err).find("unknown device type"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "serial:/dev/ttyUSB0?baud=12"}, err).first, 2);
    EXPECT_NE(test::read_text(err).find("baud rate"), std::string::npos) << test::read_text(err);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:"}, err).first, 2);
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
    EXPECT_EQ(cli(db, {"queue", "printer", "set", "lab", "--device", "serial:/dev/ttyUSB0?parity=q"}, err).first, 2);
    const auto [code, printers] = cli(db, {"queue", "printer", "list"}, err);
    EXPECT_EQ(printers, "lab  pty:/dev/null\n");
}

// A printer name the user typed that is taken or empty is theirs to change:
// a usage error (2), not a bad database or document (3).
TEST(QueueCli, APrinterNameTakenOrMissingIsAUsageError) {
    TempDir dir;
    const auto db = dir / "spool.db", err = dir / "err";
    ASSERT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "pty:/dev/null"}, err).first, 0);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "lab", "--device", "sim"}, err).first, 2);
    EXPECT_NE(test::read_text(err).find("--printer: printer 'lab' already exists"), std::string::npos)
        << test::read_text(err);
    EXPECT_EQ(cli(db, {"queue", "printer", "add", "", "--device", "sim"}, err).first, 2);
    EXPECT_NE(test::read_text(err).find("a printer needs a name"), std::string::npos) << test::read_text(err);
    const auto [code, printers] = cli(db, {"queue", "printer", "list"}, err);
    EXPECT_EQ(printers, "lab  pty:/dev/null\n");
}

// The machine's storage, not the document: a spool folder that cannot be
// made (here a file stands where the folder would be) is exit 1.
TEST(QueueCli, ASpoolFolderThatCannotBeCreatedIsAStorageError) {
    TempDir dir;
    const auto err = dir / "err";
    std::ofstream(dir / "a.txt") << "Hello.\n";
    std::ofstream(dir / "taken") << "a file, not a folder\n";
    const auto db = dir / "taken" / "tactus" / "spool.db";
    EXPECT_EQ(cli(db, {"emboss", "--queue", "--device", "sim", (dir / "a.txt").string()}, err).first, 1);
    EXPECT_NE(test::read_text(err).find("cannot create the spool folder"), std::string::npos) << test::read_text(err);
    EXPECT_FALSE(std::filesystem::exists(db));
}

TEST(QueueCli, TheDefaultDatabaseFollowsTheEnvironment) {
    TempDir dir;
    const auto err = dir / "err";
    const std::string env = "TACTUS_SPOOL_DB=" + (dir / "from-env.db").string();
    test::Process p({"/usr/bin/env", env, kCli, "queue", "printer", "add", "lab", "--device", "pty:/dev/null"},
                    err.string());
    EXPECT_EQ(p.wait(), 0) << test::read_text(err);
    EXPECT_TRUE(std::filesystem::exists(dir / "from-env.db"));
    const std::string xdg = "XDG_DATA_HOME=" + (dir / "xdg").string();
    test::Process q({"/usr/bin/env", "-u", "TACTUS_SPOOL_DB", xdg, kCli, "queue", "printer", "add", "lab", "--device",
                     "pty:/dev/null"},
                    err.string());
    EXPECT_EQ(q.wait(), 0) << test::read_text(err);
    EXPECT_TRUE(std::filesystem::exists(dir / "xdg" / "tactus" / "spool.db"));
}

}  // namespace
}  // namespace tactus::spool
