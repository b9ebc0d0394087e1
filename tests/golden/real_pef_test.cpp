// SPDX-License-Identifier: GPL-3.0-or-later
// Ready-made braille on real PEF files (tests/data/pef/real, see its README):
// files published with the PEF specification's examples and by Dotify, each
// read and written again by the real tactus-cli, compared structurally with
// the input (both parsed with pugixml): the same rows on the same pages, the
// same page count, cols/rows, each section's duplex, every dc: element kept;
// and as BRF, a new section starts on a new sheet on interpoint paper.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "../common/process.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kReal = TACTUS_TEST_DATA "/pef/real/";
constexpr std::string_view kBlankCell = "\u2800";

struct Section {
    bool duplex = true;
    std::size_t volume = 0;  // 0-based: the <volume> it is in
    std::vector<std::vector<std::string>> pages;  // rows, trailing blank cells and rows dropped
};

struct Pef {
    int cols = 0, rows = 0;
    std::size_t longest_row = 0;  // in cells, as written
    bool eight_dot = false;       // a cell with dot 7 or 8 (U+2840..U+28FF)
    std::vector<Section> sections;
    std::multimap<std::string, std::string> dc;  // dc:name -> text
    std::size_t page_count() const {
        std::size_t n = 0;
        for (const auto& s : sections) n += s.pages.size();
        return n;
    }
};

std::string local(const char* name) {
    const std::string n = name;
    const auto colon = n.find(':');
    return colon == std::string::npos ? n : n.substr(colon + 1);
}

// A row as its cells mean it: the blank cells at its end are paper, not content.
std::string trimmed_row(std::string row) {
    while (row.size() >= kBlankCell.size() && row.ends_with(kBlankCell)) row.resize(row.size() - kBlankCell.size());
    return row;
}

Pef parse(const std::string& xml) {
    pugi::xml_document doc;
    const auto ok = doc.load_string(xml.c_str());
    EXPECT_TRUE(ok) << ok.description();
    Pef pef;
    const auto root = doc.document_element();
    for (const auto& m : root.child("head").child("meta").children())
        if (std::string(m.name()).starts_with("dc:")) pef.dc.emplace(m.name(), m.text().get());
    std::size_t volume = 0;
    for (const auto& v : root.child("body").children()) {
        if (local(v.name()) != "volume") continue;
        ++volume;
        pef.cols = std::max(pef.cols, v.attribute("cols").as_int());
        pef.rows = std::max(pef.rows, v.attribute("rows").as_int());
        const bool volume_duplex = std::string(v.attribute("duplex").value()) == "true";
        for (const auto& s : v.children()) {
            if (local(s.name()) != "section") continue;
            Section section;
            section.volume = volume - 1;
            section.duplex = s.attribute("duplex") ? std::string(s.attribute("duplex").value()) == "true" : volume_duplex;
            for (const auto& p : s.children()) {
                if (local(p.name()) != "page") continue;
                std::vector<std::string> rows;
                for (const auto& r : p.children()) {
                    if (local(r.name()) != "row") continue;
                    const std::string text = r.text().get();
                    // Braille cells are 3 UTF-8 bytes: E2 A0..A3 xx; A1..A3 carry dot 7 or 8.
                    pef.longest_row = std::max(pef.longest_row, text.size() / 3);
                    for (std::size_t i = 0; i + 1 < text.size(); i += 3)
                        pef.eight_dot = pef.eight_dot || static_cast<unsigned char>(text[i + 1]) > 0xA0;
                    rows.push_back(trimmed_row(text));
                }
                while (!rows.empty() && rows.back().empty()) rows.pop_back();
                section.pages.push_back(std::move(rows));
            }
            pef.sections.push_back(std::move(section));
        }
    }
    return pef;
}

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Large enough for every file here: the files' own pages are kept, not this one.
const std::vector<std::string> kPage = {"--cells", "40", "--lines", "30"};

tactus::test::RunResult layout(const std::string& file, const std::string& to, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"layout", "--to", to};
    args.insert(args.end(), kPage.begin(), kPage.end());
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(kReal + file);
    return tactus::test::run_captured(tactus::test::cli(args));
}

class RealPef : public ::testing::TestWithParam<const char*> {};

TEST_P(RealPef, IsValidInputWithPages) {
    const auto in = parse(read(kReal + GetParam()));
    ASSERT_GT(in.page_count(), 0u);
    ASSERT_GT(in.cols, 0);
    ASSERT_GT(in.rows, 0);
}

// PEF in, PEF out: page for page, its own grid, sections and duplex, metadata.
TEST_P(RealPef, PefExportIsPageForPage) {
    const auto in = parse(read(kReal + GetParam()));
    const auto r = layout(GetParam(), "pef");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto out = parse(r.out);
    EXPECT_EQ(out.cols, in.cols);
    EXPECT_EQ(out.rows, in.rows);
    ASSERT_EQ(out.sections.size(), in.sections.size()) << r.out;
    for (std::size_t s = 0; s < in.sections.size(); ++s) {
        SCOPED_TRACE("section " + std::to_string(s + 1));
        EXPECT_EQ(out.sections[s].duplex, in.sections[s].duplex);
        EXPECT_EQ(out.sections[s].volume, in.sections[s].volume);
        ASSERT_EQ(out.sections[s].pages.size(), in.sections[s].pages.size());
        for (std::size_t p = 0; p < in.sections[s].pages.size(); ++p)
            EXPECT_EQ(out.sections[s].pages[p], in.sections[s].pages[p]) << "page " << p + 1;
    }
    EXPECT_EQ(out.page_count(), in.page_count());
    // Every dc: element of the input, with its text (dc:format is PEF's own, and the same).
    for (const auto& [name, text] : in.dc) {
        const auto [first, last] = out.dc.equal_range(name);
        bool found = false;
        for (auto it = first; it != last; ++it) found = found || it->second == text;
        EXPECT_TRUE(found) << name << " '" << text << "' lost in:\n" << r.out;
    }
    EXPECT_EQ(out.dc.count("dc:identifier"), 1u);
}

// PEF in, BRF out on interpoint paper: the same pages, and blank backs only
// where the file asks for a new sheet (a section starting on a back, each page
// of a single-sided section).
TEST_P(RealPef, BrfExportStartsEachSectionOnANewSheet) {
    const auto in = parse(read(kReal + GetParam()));
    const auto r = layout(GetParam(), "brf", {"--interpoint"});
    if (in.eight_dot) {
        // BRF is 6-dot: an 8-dot file is refused, not cut down to 6 dots.
        EXPECT_EQ(r.exit_code, 3) << r.err;
        EXPECT_NE(r.err.find("8-dot"), std::string::npos) << r.err;
        return;
    }
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::size_t want = 0;
    for (const auto& s : in.sections) {
        if (want % 2 == 1) ++want;  // a blank back: the section starts on a front
        want += s.duplex ? s.pages.size() : 2 * s.pages.size();
    }
    // Pages in a BRF end with a form feed.
    EXPECT_EQ(static_cast<std::size_t>(std::count(r.out.begin(), r.out.end(), '\f')), want);
}

// A printer line one cell shorter than the file's longest row is refused
// (exit 5) before anything is written.
TEST_P(RealPef, SmallerPageIsRefused) {
    const auto in = parse(read(kReal + GetParam()));
    ASSERT_GT(in.longest_row, 4u);
    const auto r = tactus::test::run_captured(tactus::test::cli(
        {"layout", "--to", "pef", "--cells", std::to_string(in.longest_row - 1), "--lines", "30", kReal + GetParam()}));
    EXPECT_EQ(r.exit_code, 5) << r.err;
    EXPECT_TRUE(r.out.empty());
}

// A PEF of three volumes (tests/data/pef/volumes.pef, valid PEF 2008-1): the
// PEF written again has the same volumes, each with its sections, their
// duplex and pages; before, every volume was merged into one.
TEST(MultiVolumePef, KeepsItsVolumes) {
    const std::string file = TACTUS_TEST_DATA "/pef/volumes.pef";
    const auto in = parse(read(file));
    ASSERT_EQ(in.sections.size(), 4u);
    ASSERT_EQ(in.sections.back().volume, 2u);
    const auto r = tactus::test::run_captured(tactus::test::cli({"layout", "--to", "pef", file}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto out = parse(r.out);
    ASSERT_EQ(out.sections.size(), in.sections.size()) << r.out;
    for (std::size_t s = 0; s < in.sections.size(); ++s) {
        SCOPED_TRACE("section " + std::to_string(s + 1));
        EXPECT_EQ(out.sections[s].volume, in.sections[s].volume);
        EXPECT_EQ(out.sections[s].duplex, in.sections[s].duplex);
        EXPECT_EQ(out.sections[s].pages, in.sections[s].pages);
    }
    EXPECT_EQ(out.cols, 12);
    EXPECT_EQ(out.rows, 5);
    // Read back, written again: the same bytes (a fixed point).
    const auto again_file = fs::temp_directory_path() / "tactus-volumes-again.pef";
    {
        std::ofstream o(again_file, std::ios::binary);
        o << r.out;
    }
    const auto again = tactus::test::run_captured(tactus::test::cli({"layout", "--to", "pef", again_file.string()}));
    fs::remove(again_file);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out, r.out);
}

// Three volumes of three page sizes (tests/data/pef/volume_grids.pef, valid
// PEF 2008-1: 12 x 5, 20 x 8 single-sided, 16 x 6 rowgap 1 with a 10 x 4
// single-sided section): tactus-cli writes the file again byte for byte, each
// volume and section with its own cols, rows, rowgap and duplex. Before, every
// volume was written with the file's largest cols/rows (20 x 8) and rowgap 0.
TEST(MultiVolumePef, EachVolumeKeepsItsOwnGrid) {
    const std::string file = TACTUS_TEST_DATA "/pef/volume_grids.pef";
    const auto source = read(file);
    const auto r = tactus::test::run_captured(tactus::test::cli({"layout", "--to", "pef", file}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, source);
    // On a printer whose page holds volume 1 and 3 but not volume 2's 20
    // cells (its longest row is 19): refused, naming the file's page.
    const auto small = tactus::test::run_captured(
        tactus::test::cli({"layout", "--to", "pef", "--cells", "19", "--lines", "8", file}));
    EXPECT_EQ(small.exit_code, 5) << small.err;
    EXPECT_NE(small.err.find("20 cells x 8 lines"), std::string::npos) << small.err;
    EXPECT_TRUE(small.out.empty());
}

INSTANTIATE_TEST_SUITE_P(Files, RealPef,
                         ::testing::Values("book.pef", "butterfly.pef", "8-dot-chart.pef", "margin-uneven.pef",
                                           "flow-in-header-footer4.pef"),
                         [](const auto& param_info) {
                             std::string n = param_info.param;
                             n = n.substr(0, n.find('.'));
                             std::erase(n, '-');
                             return n;
                         });

}  // namespace
