// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli end to end: the real binary, its exit codes and messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>

#include "../common/process.hpp"

using tactus::test::cli;
using tactus::test::run_captured;

namespace fs = std::filesystem;

namespace {

const std::string kWelcome = TACTUS_RESOURCES_DIR "/samples/welcome.md";

const std::string kText =
    "The quick brown fox.\n"
    "Braille, 42 times; \"quoted\" and (bracketed).\n"
    "\n"
    "Knowledge is power!\n";

fs::path temp_file(const std::string& name, const std::string& content) {
    const auto p = fs::temp_directory_path() / ("tactus-cli-test-" + name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

}  // namespace

// The fixed contract: one output line per input line, exactly what liblouis's own
// lou_translate gives with the same display table.
TEST(CliTranslate, MatchesLouTranslateLineByLine) {
    const auto input = temp_file("in.txt", kText);
    for (const auto& [to, display] : {std::pair{"unicode", "unicode.dis"}, std::pair{"brf", "en-us-brf.dis"}}) {
        const auto ours = run_captured(cli({"translate", "--table", "en-ueb-g2.ctb", "--to", to, input.string()}));
        ASSERT_EQ(ours.exit_code, 0) << ours.err;
        const auto peer = run_captured({"lou_translate", std::string(display) + ",en-ueb-g2.ctb"}, kText);
        ASSERT_EQ(peer.exit_code, 0) << peer.err;
        EXPECT_EQ(ours.out, peer.out) << to;
    }
    const auto from_stdin = run_captured(cli({"translate", "--to", "brf", "-"}), "Hello\n");
    EXPECT_EQ(from_stdin.out, ",HELLO\n");
}

TEST(CliTranslate, InvalidUtf8IsBadInputWithFileAndLine) {
    const auto input = temp_file("bad.txt", "fine\nbroken \xFF here\n");
    const auto r = run_captured(cli({"translate", input.string()}));
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find(input.string() + ":2:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("invalid UTF-8"), std::string::npos) << r.err;
}

TEST(CliTranslate, UnknownTableIsBadInput) {
    const auto r = run_captured(cli({"translate", "--table", "xx-nonexistent.ctb", "-"}), "a\n");
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find("xx-nonexistent.ctb"), std::string::npos) << r.err;
}

// A line with a Chinese word: the word in zh-tw.ctb's braille with UEB's
// non-UEB word indicator (^( in BRF); --one-table gives liblouis's own line,
// escape codes and all; a second table that does not exist is bad input
// naming the option.
TEST(CliTranslate, PassagesInAnotherLanguageGetTheirTable) {
    const std::string line = "The word \xE4\xB8\xAD\xE6\x96\x87 means Chinese.\n";
    const auto mixed = run_captured(cli({"translate", "--to", "brf", "-"}), line);
    ASSERT_EQ(mixed.exit_code, 0) << mixed.err;
    EXPECT_EQ(mixed.out, ",! ^W ^(A&'=1 M1NS ,*9ESE4\n");
    const auto one = run_captured(cli({"translate", "--to", "brf", "--one-table", "-"}), line);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const auto peer = run_captured({"lou_translate", "en-us-brf.dis,en-ueb-g2.ctb"}, line);
    EXPECT_EQ(one.out, peer.out);
    EXPECT_NE(one.out, mixed.out);
    const auto bad = run_captured(cli({"translate", "--second-table", "xx-nonexistent.ctb", "-"}), line);
    EXPECT_EQ(bad.exit_code, 3);
    EXPECT_NE(bad.err.find("--second-table"), std::string::npos) << bad.err;
}

TEST(Cli, UsageErrorsExitTwo) {
    EXPECT_EQ(run_captured(cli({})).exit_code, 2);
    EXPECT_EQ(run_captured(cli({"layout", "--cells", "1", "x.md", "--to", "brf"})).exit_code, 2);
    EXPECT_EQ(run_captured(cli({"translate", "--to", "docx", "-"})).exit_code, 2);
    EXPECT_EQ(run_captured(cli({"layout", "--preset", "nope", "--to", "brf", kWelcome})).exit_code, 2);
}

// An encoding the user named that cannot be used is a usage error (2); the
// file itself is not at fault.
TEST(CliLayout, AnEncodingThatCannotBeUsedIsAUsageError) {
    const auto input = temp_file("encoding.txt", kText);
    const auto unknown = run_captured(cli({"layout", "--to", "brf", "--encoding", "klingon-42", input.string()}));
    EXPECT_EQ(unknown.exit_code, 2) << unknown.err;
    EXPECT_NE(unknown.err.find("unknown encoding 'klingon-42'"), std::string::npos) << unknown.err;
    const auto not_text = run_captured(
        cli({"layout", "--to", "brf", "--format", "html", "--encoding", "windows-1252", input.string()}));
    EXPECT_EQ(not_text.exit_code, 2) << not_text.err;
    EXPECT_NE(not_text.err.find("an encoding can only be given for text and Markdown input"), std::string::npos)
        << not_text.err;
}

// A file that cannot be written is the machine's storage failing (exit 1),
// never bad input.
TEST(CliSim, AStrikeLogThatCannotBeWrittenIsAStorageError) {
    const auto log = fs::temp_directory_path() / "tactus-cli-test-no-such-folder" / "strikes.jsonl";
    fs::remove_all(log.parent_path());
    const auto r = run_captured({TACTUS_CLI, "sim", "--pty", "--strike-log", log.string()});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(log.string() + ": cannot write the strike log"), std::string::npos) << r.err;
}

// A document BRF cannot hold (8-dot cells) is refused as bad input (3): the
// write did not fail, there is nothing to retry.
TEST(CliLayout, EightDotCellsForBrfAreBadInputNotAFailedWrite) {
    const auto input = temp_file("eight-dot.txt", "\u28FF\u2841\n");
    const auto out = fs::temp_directory_path() / "tactus-cli-test-eight-dot.brf";
    fs::remove(out);
    const auto r = run_captured(cli({"layout", "--to", "brf", "--eight-dot", "-o", out.string(), input.string()}));
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find("8-dot cell cannot be written as BRF"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, EveryCommandHasHelp) {
    for (const char* c : {"", "translate", "layout", "tables"}) {
        const auto r = run_captured(*c ? cli({c, "--help"}) : cli({"--help"}));
        EXPECT_EQ(r.exit_code, 0) << c;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << c;
    }
}

TEST(CliLayout, WritesAtomicallyAndSummarises) {
    const auto out = fs::temp_directory_path() / "tactus-cli-test-out.brf";
    fs::remove(out);
    const auto r = run_captured(cli({"layout", "--interpoint", "--to", "brf", "-o", out.string(), kWelcome}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_NE(r.err.find("interpoint"), std::string::npos);
    const auto s = run_captured(cli({"layout", "--summary", kWelcome}));
    EXPECT_EQ(s.exit_code, 0);
    EXPECT_NE(s.out.find("27 cells x 24 lines"), std::string::npos) << s.out;
}

TEST(CliLayout, CustomGeometryIsHonoured) {
    const auto r = run_captured(cli({"layout", "--cells", "40", "--lines", "25", "--to", "unicode", kWelcome}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::size_t longest = 0;
    std::istringstream lines(r.out);
    std::string line;
    bool wider_than_27 = false;
    while (std::getline(lines, line)) {
        if (!line.empty() && line[0] == '\f') line.erase(0, 1);
        const auto cells = line.size() / 3;  // every braille code point is 3 UTF-8 bytes
        longest = std::max(longest, cells);
        wider_than_27 = wider_than_27 || cells > 27;
    }
    EXPECT_LE(longest, 40u);
    EXPECT_TRUE(wider_than_27);
}

TEST(CliLayout, BadInputNamesTheFile) {
    const auto junk = temp_file("junk.docx", std::string("PK\x03\x04\x14\x00 truncated zip", 20));
    const auto r = run_captured(cli({"layout", "--to", "brf", junk.string()}));
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find(junk.string()), std::string::npos) << r.err;
    const auto missing = run_captured(cli({"layout", "--to", "brf", "/nonexistent/file.txt"}));
    EXPECT_EQ(missing.exit_code, 3);
    EXPECT_NE(missing.err.find("/nonexistent/file.txt"), std::string::npos) << missing.err;
}
