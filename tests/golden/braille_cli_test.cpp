// SPDX-License-Identifier: GPL-3.0-or-later
// Through the real tactus-cli: ready-made braille page for page, a
// page that does not fit is refused before anything happens, the defaults say
// what the help says, an empty document is an error, and a table that does not
// suit the text is named.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "../common/process.hpp"

namespace {
// tactus-cli with a command line written as one string: words split at spaces,
// '...' quoting a word (no shell involved).
tactus::test::RunResult run_cli(const std::string& line) {
    std::vector<std::string> args;
    std::string word;
    bool quoted = false, have = false;
    for (const char c : line) {
        if (c == '\'') {
            quoted = !quoted;
            have = true;
        } else if (c == ' ' && !quoted) {
            if (have) args.push_back(word);
            word.clear();
            have = false;
        } else {
            word += c;
            have = true;
        }
    }
    if (have) args.push_back(word);
    return tactus::test::run_captured(tactus::test::cli(args));
}
}  // namespace

namespace fs = std::filesystem;

namespace {

const std::string kPef = TACTUS_TEST_DATA "/pef/";

fs::path temp_file(const std::string& name, const std::string& content) {
    const auto p = fs::temp_directory_path() / ("tactus-braille-cli-" + name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

std::size_t count(const std::string& s, char c) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), c)); }

}  // namespace

// `layout --to brf` of a document, fed back in, gives the same pages (it gave
// twice as many: the old page-number lines kept and new numbers added).
TEST(BrailleCli, BrfBackInIsPageForPage) {
    const auto first = run_cli(("layout --to brf " TACTUS_RESOURCES_DIR "/samples/welcome.md"));
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const auto brf = temp_file("welcome.brf", first.out);
    const auto again = run_cli(("layout --to brf '" + brf.string() + "'"));
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(count(again.out, '\f'), count(first.out, '\f'));
    EXPECT_EQ(again.out, first.out);
}

TEST(BrailleCli, PefThatDoesNotFitStopsWithExitFiveAndOffersReflow) {
    const auto r = run_cli(("layout --to brf " + kPef + "us_braille_40x25.pef"));
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find("us_braille_40x25.pef"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--reflow"), std::string::npos) << r.err;
    const auto reflowed = run_cli(("layout --reflow --to brf " + kPef + "us_braille_40x25.pef"));
    EXPECT_EQ(reflowed.exit_code, 0) << reflowed.err;
    const auto us = run_cli(("layout --preset us-braille --single-sided --to brf " + kPef +
                                    "us_braille_40x25.pef"));
    EXPECT_EQ(us.exit_code, 0) << us.err;
    EXPECT_EQ(count(us.out, '\f'), 2u);
    // On interpoint paper each page of the single-sided PEF gets a blank back.
    const auto both = run_cli(("layout --preset us-braille --to brf " + kPef + "us_braille_40x25.pef"));
    EXPECT_EQ(count(both.out, '\f'), 4u);
}

TEST(BrailleCli, PefRoundTripThroughTheCommandLineKeepsMetadata) {
    const auto out = fs::temp_directory_path() / "tactus-braille-cli-sections.pef";
    const auto r = run_cli(("layout --to pef -o '" + out.string() + "' " + kPef + "sections.pef"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream f(out);
    const std::string pef((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    for (const char* kept : {"<dc:title>Two sections, interpoint</dc:title>", "<dc:creator>Tactus test suite</dc:creator>",
                             "<dc:identifier>org.example.tactus.sections-2024</dc:identifier>",
                             "<dc:date>2024-05-01</dc:date>", "cols=\"20\"", "rows=\"6\""})
        EXPECT_NE(pef.find(kept), std::string::npos) << kept << "\n" << pef;
    std::size_t sections = 0;
    for (std::size_t at = pef.find("<section"); at != std::string::npos; at = pef.find("<section", at + 1)) ++sections;
    EXPECT_EQ(sections, 2u);
}

TEST(BrailleCli, ImpossiblePefAttributeIsBadInputWithItsLine) {
    const auto r = run_cli(("layout --to brf " + kPef + "bad_duplex.pef"));
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find("bad_duplex.pef:11"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("maybe"), std::string::npos) << r.err;
}

// The help says a4 (the default) is interpoint: `layout` now lays it out so.
TEST(BrailleCli, DefaultPresetIsInterpointAsTheHelpSays) {
    const auto help = run_cli(("layout --help"));
    EXPECT_NE(help.out.find("a4: A4, 27 cells x 24 lines, interpoint"), std::string::npos) << help.out;
    const auto s = run_cli(("layout --summary " TACTUS_RESOURCES_DIR "/samples/welcome.md"));
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_NE(s.out.find("interpoint"), std::string::npos) << s.out;
    const auto single = run_cli(("layout --summary --single-sided " TACTUS_RESOURCES_DIR "/samples/welcome.md"));
    EXPECT_NE(single.out.find("single-sided"), std::string::npos) << single.out;
    const auto preset = run_cli(("layout --summary --preset a4-single " TACTUS_RESOURCES_DIR "/samples/welcome.md"));
    EXPECT_NE(preset.out.find("single-sided"), std::string::npos) << preset.out;
}

TEST(BrailleCli, EmptyDocumentIsAnErrorUnlessABlankPageIsAskedFor) {
    const auto empty = temp_file("empty.txt", "");
    const auto r = run_cli(("layout --to brf '" + empty.string() + "'"));
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
    const auto blank = run_cli(("layout --blank-page --to brf '" + empty.string() + "'"));
    EXPECT_EQ(blank.exit_code, 0) << blank.err;
    EXPECT_EQ(count(blank.out, '\f'), 1u);
}

TEST(BrailleCli, TableThatDoesNotSuitTheScriptIsNamed) {
    const auto zh = run_cli(("layout --to brf " TACTUS_RESOURCES_DIR "/samples/chinese-tw.txt"));
    EXPECT_NE(zh.err.find("warning"), std::string::npos) << zh.err;
    EXPECT_NE(zh.err.find("zh-tw.ctb"), std::string::npos) << zh.err;
    const auto cn = run_cli(("layout --to unicode " TACTUS_RESOURCES_DIR "/samples/chinese-cn.txt"));
    EXPECT_NE(cn.err.find("zhcn-g2.ctb"), std::string::npos) << cn.err;
    const auto en = run_cli(("layout --table zh-tw.ctb --to unicode " TACTUS_RESOURCES_DIR "/samples/welcome.md"));
    EXPECT_NE(en.err.find("en-ueb-g2.ctb"), std::string::npos) << en.err;
    const auto fine = run_cli(("layout --table zh-tw.ctb --to brf " TACTUS_RESOURCES_DIR "/samples/chinese-tw.txt"));
    EXPECT_EQ(fine.err.find("warning"), std::string::npos) << fine.err;
}

// Bold text in a script the table does not know crashed the CLI (heap
// corruption: liblouis wrote the typeform for every output cell into a buffer
// sized for the input); the same with Arabic and with the Chinese table.
TEST(BrailleCli, EmphasisInAnUnknownScriptIsTranslatedWhole) {
    for (const auto& [text, table] : {std::pair{"**Привет**\n", "en-ueb-g2.ctb"}, std::pair{"*مرحبا بالعالم*\n", "en-ueb-g2.ctb"},
                                      std::pair{"**Привет**\n", "zh-tw.ctb"}}) {
        const auto md = temp_file("foreign.md", text);
        const auto r = run_cli("layout --to brf -t " + std::string(table) + " '" + md.string() + "'");
        EXPECT_EQ(r.exit_code, 0) << table << ": " << r.err;
        EXPECT_GE(count(r.out, '\\'), 6u) << table << ": one escape per letter\n" << r.out;
    }
}

// Text cut short with exit 0: liblouis drops escape codes that do not fit and
// still reports the whole input read.
TEST(BrailleCli, TranslateGivesEveryWord) {
    const auto r = tactus::test::run_captured(tactus::test::cli({"translate", "--to", "brf", "-"}), "Привет мир\n");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(count(r.out, '\\'), 9u) << r.out;  // nine letters, nine escape codes
    EXPECT_EQ(count(r.out, ' '), 1u) << r.out;
}

// Tactus's own multi-page BRF and PEF back-translate page after page, line for
// line, a form feed between pages (it stopped at the first form feed).
TEST(BrailleCli, BackTranslationGoesAcrossPages) {
    std::string text;
    for (int i = 1; i <= 60; ++i) text += "Line number " + std::to_string(i) + " of the lesson.\n\n";
    const auto md = temp_file("pages.md", text);
    for (const char* to : {"brf", "pef"}) {
        const auto out = fs::temp_directory_path() / (std::string("tactus-braille-cli-pages.") + to);
        const auto made = run_cli("layout -t en-ueb-g1.ctb --to " + std::string(to) + " -o '" + out.string() + "' '" +
                                  md.string() + "'");
        ASSERT_EQ(made.exit_code, 0) << made.err;
        const auto back = run_cli("translate --back -t en-ueb-g1.ctb '" + out.string() + "'");
        ASSERT_EQ(back.exit_code, 0) << to << ": " << back.err;
        EXPECT_GE(count(back.out, '\f'), 2u) << to;
        EXPECT_NE(back.out.find("Line number 1 of the"), std::string::npos) << to << "\n" << back.out;
        EXPECT_NE(back.out.find("Line number 60 of the"), std::string::npos) << to << "\n" << back.out;
    }
}

// A named pipe nobody writes to is refused at once, by every command that reads a file.
TEST(BrailleCli, NamedPipeIsRefusedNotWaitedOn) {
    const auto fifo = fs::temp_directory_path() / "tactus-braille-cli-fifo.md";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const char* command : {"layout --to brf ", "translate "}) {
        const auto r = run_cli(command + ("'" + fifo.string() + "'"));
        EXPECT_EQ(r.exit_code, 3) << command;
        EXPECT_NE(r.err.find("named pipe"), std::string::npos) << command << r.err;
    }
    fs::remove(fifo);
}

TEST(BrailleCli, HelpListsEveryExitStatus) {
    const auto r = run_cli("--help");
    EXPECT_NE(r.out.find("6 internal error"), std::string::npos) << r.out;
}
