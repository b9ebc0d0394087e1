// SPDX-License-Identifier: GPL-3.0-or-later
// Lists (bullets kept), tables, notes and block quotes carried
// from Markdown, DOCX and ODT. The three files of tests/golden/structure hold
// one document; each importer must give the same blocks.
#include "import_test_util.hpp"

using namespace tactus;
using namespace tactus::document;

namespace {

const std::filesystem::path kStructure = std::filesystem::path(TACTUS_TEST_DATA) / ".." / "golden" / "structure";

Document import_structure(const std::string& name) {
    auto doc = import::import_file(kStructure / name, {});
    EXPECT_TRUE(doc.has_value()) << (doc ? "" : doc.error().to_string());
    auto d = doc.value_or(Document{});
    for (auto& b : d.blocks) b.source_line = 0;  // DOCX and ODT have no lines
    d.source_name.clear();
    d.encoding.clear();
    return d;
}

Document md(std::string_view text) {
    auto doc = import::import_bytes(text, "t.md", {import::SourceFormat::markdown, "UTF-8"});
    EXPECT_TRUE(doc.has_value()) << (doc ? "" : doc.error().to_string());
    return doc.value_or(Document{});
}

std::string texts(const Document& d) {
    std::string out;
    for (const auto& b : d.blocks) {
        out += std::to_string(static_cast<int>(b.kind)) + ":" + std::to_string(b.level) + ":";
        for (const auto& s : b.spans) out += s.note_reference ? "[" + s.text + "]" : s.text;
        out += "|";
    }
    return out;
}

}  // namespace

TEST(StructureImport, MarkdownCarriesEveryStructure) {
    const auto d = import_structure("structure.md");
    using K = BlockKind;
    EXPECT_EQ(test::kinds(d),
              (std::vector<K>{K::heading, K::paragraph, K::note, K::heading, K::list_item, K::list_item,
                              K::list_item, K::list_item, K::list_item, K::list_item, K::quote,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell,
                              K::paragraph,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell,
                              K::table_row, K::table_cell, K::table_cell, K::table_cell}));
    ASSERT_GE(d.blocks.size(), 12u);
    // The reference in the text, the note right after its paragraph, numbered 1.
    Document two;
    two.blocks = {d.blocks[1], d.blocks[2]};
    EXPECT_EQ(texts(two),
              "1:0:Our class visited the river.[1] We saw herons and a kingfisher.|7:0:[1] The walk took an hour.|");
    EXPECT_EQ(d.blocks[4].text(), "\u2022 A notebook");
    EXPECT_EQ(d.blocks[6].level, 2);
    EXPECT_EQ(d.blocks[8].text(), "1. Meet at the gate.");
    EXPECT_EQ(d.blocks[11].level, 1);   // the head row
    EXPECT_EQ(d.blocks[15].level, 0);   // a body row
    EXPECT_EQ(d.blocks[13].level, 1);   // the second column
    EXPECT_EQ(d.blocks[13].text(), "Seen");
}

TEST(StructureImport, DocxAndOdtGiveTheMarkdownBlocks) {
    const auto markdown = import_structure("structure.md");
    EXPECT_EQ(texts(import_structure("structure.docx")), texts(markdown));
    EXPECT_EQ(texts(import_structure("structure.odt")), texts(markdown));
    // The page header ("Class 4 newsletter") is left out on purpose.
    EXPECT_EQ(texts(import_structure("structure.docx")).find("newsletter"), std::string::npos);
    EXPECT_EQ(texts(import_structure("structure.odt")).find("newsletter"), std::string::npos);
}

TEST(StructureImport, MarkdownFootnoteExtension) {
    // An undefined reference and one in code stay text; a note referred to
    // twice is placed once, after the first; ids are numbered by first use.
    const auto d = md("See[^b] and[^nope].\n\n```\nx[^a]\n```\n\nAgain[^b] and[^a].\n\n"
                      "[^a]: Note A\n[^b]: Note *B*\n  goes on.\n\nLast.\n");
    EXPECT_EQ(texts(d), "1:0:See[1] and[^nope].|7:0:[1] Note B goes on.|1:0:x[^a]|1:0:Again[1] and[2].|"
                        "7:0:[2] Note A|1:0:Last.|");
    // Definitions leave their lines: the paragraph after them is still on line 13.
    EXPECT_EQ(d.blocks.back().source_line, 13);
    // A note's own emphasis is kept.
    bool italic = false;
    for (const auto& s : d.blocks[1].spans) italic = italic || (s.emphasis & emphasis_italic);
    EXPECT_TRUE(italic);
}

TEST(StructureImport, MarkdownQuotesAndEmptyCells) {
    const auto d = md("> one\n>\n> > two\n\n| a | |\n|---|---|\n| | b |\n");
    EXPECT_EQ(texts(d), "6:1:one|6:2:two|8:1:|9:0:a|9:1:|8:0:|9:0:|9:1:b|");
}

TEST(StructureImport, PageBreakInATableCellComesAfterTheTable) {
    const auto d = import_structure("table_break.docx");
    EXPECT_EQ(texts(d), "8:0:|9:0:one|9:1:two|8:0:|9:0:three four|3:0:|1:0:after|");
    ASSERT_EQ(d.blocks.size(), 7u);
    EXPECT_EQ(d.blocks[5].label, "2");
}

namespace {

// The table blocks as "row(header)" and "column+span:text" entries.
std::string table_cells(const Document& d) {
    std::string out;
    for (const auto& b : d.blocks) {
        if (b.kind == BlockKind::table_row) out += b.level == 1 ? "\nH " : "\nR ";
        if (b.kind == BlockKind::table_cell)
            out += std::to_string(b.level) + "+" + std::to_string(b.span) + ":" + b.text() + " ";
    }
    return out;
}

}  // namespace

// Merged cells. Every cell keeps its column (a merged cell's columns
// are its own, a row's skipped columns hold no cell), and a cell merged across
// columns says how many; before, the cells after a merged one moved left into
// the wrong columns.
TEST(StructureImport, MergedCellsKeepTheirColumns) {
    const std::string expected =
        "\nH 0+1:Bird 1+2:Seen "
        "\nH 0+1: 1+1:Morning 2+1:Evening "
        "\nR 0+1:Heron 1+1:3 2+1:1 "
        "\nR 0+1:Owl 1+2:none "
        "\nR 0+1:Kingfisher 1+1:1 2+1:2 "
        "\nH 0+1:Plant 1+1:Where it grows 2+1:What it needs "
        "\nR 0+1:Willow 1+1:on the river bank 2+1:wet soil and sun "
        "\nR 0+1:Moss 1+2:anywhere damp and shady, on stones and bark ";
    // DOCX: the merged-down cell under "Bird" is an empty cell of the file; the
    // last row starts one column in (w:gridBefore).
    EXPECT_EQ(table_cells(import_structure("structure-spans.docx")), expected + "\nR 1+1:by the gate 2+1:little water ");
    // ODT: the covered cell under "Bird" holds no cell; the last row's first cell is empty.
    auto odt = expected + "\nR 0+1: 1+1:by the gate 2+1:little water ";
    odt.replace(odt.find("H 0+1: 1+1:Morning"), 7, "H ");
    EXPECT_EQ(table_cells(import_structure("structure-spans.odt")), odt);
}
