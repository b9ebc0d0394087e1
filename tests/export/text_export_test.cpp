// SPDX-License-Identifier: GPL-3.0-or-later
// The print text writers (core/export/text_export): a plain text file is
// written back as it was, with no Markdown escapes; Markdown keeps tables,
// list numbers and page labels through a save and reopen.
#include "export/text_export.hpp"

#include <gtest/gtest.h>

#include <random>

#include "import/import.hpp"
#include "../common/hex_bytes.hpp"

using namespace tactus;

namespace {

document::Document import_as(const std::string& bytes, const std::string& name) {
    auto doc = import::import_bytes(bytes, name);
    if (!doc) throw std::runtime_error(doc.error().to_string());
    return std::move(*doc);
}

std::vector<document::Block> without_lines(std::vector<document::Block> blocks) {
    for (auto& b : blocks) b.source_line = 0;
    return blocks;
}

document::Block text_block(document::BlockKind kind, int level, std::string text) {
    document::Block b;
    b.kind = kind;
    b.level = level;
    if (!text.empty()) b.spans.push_back(document::Span{std::move(text)});
    return b;
}

}  // namespace

// english.txt's "& and # and *" must not come back as "\& and # and \*".
TEST(TextExport, ATextFileIsWrittenBackUnchanged) {
    for (const std::string text : {
             "Hello.\n\n& and # and *\n",                       // paragraphs a blank line apart
             "one *star*\ntwo # hash\nthree <b> & [a]\n",        // a line a paragraph
             "Page one.\n\f\nPage two & more.\n\nStill two.\n",  // a form feed between print pages
             "a_b_c \\ `x` | y ~~z~~\n",
             // A hard-wrapped paragraph keeps its lines, their spaces too.
             "It was the best of times,\n  it was the worst  \nof times.\n\nThe end.\n",
         }) {
        SCOPED_TRACE(text);
        const auto doc = import_as(text, "english.txt");
        EXPECT_EQ(exporter::to_text(doc), text);
    }
}

TEST(TextExport, ParagraphsStayParagraphsWhenAnyBlankLineIsThere) {
    // Lines 1 and 3 are a blank line apart and 3, 4 are adjacent: the importer
    // would join 3 and 4, so the writer parts them.
    document::Document doc;
    for (const auto& [text, line] : {std::pair<std::string, int>{"a", 1}, {"b", 3}, {"c", 4}}) {
        doc.blocks.push_back(text_block(document::BlockKind::paragraph, 0, text));
        doc.blocks.back().source_line = line;
    }
    EXPECT_EQ(exporter::to_text(doc), "a\n\nb\n\nc\n");
    EXPECT_EQ(without_lines(import_as(exporter::to_text(doc), "x.txt").blocks), without_lines(doc.blocks));
}

TEST(MarkdownExport, ATableIsWrittenAsAPipeTableAndReadBack) {
    const auto doc = import_as("Plants:\n\n| Plant | Where *it* grows |\n|---|---|\n| Willow | by a \\| river |\n| Fern |  |\n",
                               "t.md");
    const auto md = exporter::to_markdown(doc);
    EXPECT_NE(md.find("| Plant | Where *it* grows |\n| --- | --- |\n| Willow | by a \\| river |\n| Fern |  |"),
              std::string::npos)
        << md;
    EXPECT_EQ(without_lines(import_as(md, "saved.md").blocks), without_lines(doc.blocks));
}

// A table's column alignment ("|:--|:-:|--:|---|") is kept on saving: the
// document model holds it. Each cell now holds its
// column's (Block::align), the importer reads it, the writer writes it, and
// the editor's own delimiter row is kept when its lines are saved.
TEST(MarkdownExport, ATablesColumnAlignmentIsKept) {
    const auto doc = import_as("| L | C | R | N |\n|:--|:-:|--:|---|\n| 1 | 2 | 3 |\n", "t.md");
    std::vector<document::Align> aligns;
    for (const auto& b : doc.blocks)
        if (b.kind == document::BlockKind::table_cell) aligns.push_back(b.align);
    using A = document::Align;
    EXPECT_EQ(aligns, (std::vector<A>{A::left, A::centre, A::right, A::none, A::left, A::centre, A::right, A::none}));
    const auto md = exporter::to_markdown(doc);
    EXPECT_EQ(md, "| L | C | R | N |\n| :-- | :-: | --: | --- |\n| 1 | 2 | 3 |  |\n");
    EXPECT_EQ(without_lines(import_as(md, "saved.md").blocks), without_lines(doc.blocks));
    // The editor's lines, as typed (a narrower delimiter row is made whole).
    const std::vector<std::string> lines{"| a | b | c |", "|:-:|--:|", "| 1 | 2 | 3 |"};
    EXPECT_EQ(exporter::join_markdown_lines(lines), "| a | b | c |\n| :-: | --: | --- |\n| 1 | 2 | 3 |\n");
    EXPECT_EQ(exporter::markdown_table_alignments("| :--- |:---:| ---: | - |"),
              (std::vector<A>{A::left, A::centre, A::right, A::none}));
}

TEST(MarkdownExport, ATableWithoutHeaderRowGetsAnEmptyOneThatReadsAsNone) {
    // A DOCX table without <w:tblHeader/>: no header row.
    document::Document doc;
    doc.blocks.push_back(text_block(document::BlockKind::paragraph, 0, "Before."));
    for (const auto& row : {std::vector<std::string>{"a", "b"}, {"c", ""}}) {
        doc.blocks.push_back(text_block(document::BlockKind::table_row, 0, ""));
        for (std::size_t c = 0; c < row.size(); ++c)
            doc.blocks.push_back(text_block(document::BlockKind::table_cell, static_cast<int>(c), row[c]));
    }
    const auto md = exporter::to_markdown(doc);
    EXPECT_EQ(md, "Before.\n\n|  |  |\n| --- | --- |\n| a | b |\n| c |  |\n");
    EXPECT_EQ(without_lines(import_as(md, "saved.md").blocks), doc.blocks);
}

TEST(MarkdownExport, ListNumbersAndNestingAreKept) {
    // Markdown counts an ordered list on from its first number and nests under
    // "10." at four spaces: the writer keeps each number and each level.
    document::Document doc;
    for (const auto& [level, text] : {std::pair<int, std::string>{1, "3. three"},
                                      {1, "7. seven"},
                                      {2, "10. ten"},
                                      {3, "\u2022 deep"},
                                      {3, "1) one"},
                                      {1, "8. eight"},
                                      {3, "\u2022 orphan"}})
        doc.blocks.push_back(text_block(document::BlockKind::list_item, level, text));
    const auto md = exporter::to_markdown(doc);
    EXPECT_EQ(without_lines(import_as(md, "saved.md").blocks), doc.blocks) << md;
}

TEST(MarkdownExport, PageLabelsAreKept) {
    const auto doc = import_as("one\n\n<!-- pagebreak 10 -->\n\ntwo\n\n---\n\nthree\n\n<!-- pagebreak xii -->\n\nfour\n", "p.md");
    const auto md = exporter::to_markdown(doc);
    EXPECT_EQ(without_lines(import_as(md, "saved.md").blocks), without_lines(doc.blocks));
}

// A merged cell (DOCX, ODT) has no Markdown form. Each cell keeps its
// column: the columns a merged cell covers, and a row's skipped ones, are
// empty entries (before, the next cell was written into the column after the
// merged one's first).
TEST(MarkdownExport, MergedCellsKeepTheirColumnsAsEmptyEntries) {
    document::Document doc;
    auto row = text_block(document::BlockKind::table_row, 1, "");
    auto cell = [](int column, std::string text, int span = 1) {
        auto c = text_block(document::BlockKind::table_cell, column, std::move(text));
        c.span = span;
        return c;
    };
    doc.blocks = {row, cell(0, "Bird"), cell(1, "Seen", 2), cell(3, "Where")};
    row.level = 0;
    doc.blocks.insert(doc.blocks.end(), {row, cell(1, "3"), cell(2, "1"), cell(3, "reeds")});
    const auto md = exporter::to_markdown(doc);
    EXPECT_EQ(md, "| Bird | Seen |  | Where |\n| --- | --- | --- | --- |\n|  | 3 | 1 | reeds |\n") << md;
    std::vector<std::string> columns;
    for (const auto& b : import_as(md, "saved.md").blocks)
        if (b.kind == document::BlockKind::table_cell) columns.push_back(std::to_string(b.level) + ":" + b.text());
    EXPECT_EQ(columns, (std::vector<std::string>{"0:Bird", "1:Seen", "2:", "3:Where", "0:", "1:3", "2:1", "3:reeds"}));
}

// Property: a random text file of hard-wrapped paragraphs (lines with spaces or
// a tab at their ends, any characters), a blank line between paragraphs, and
// form feeds, is written back byte for byte after it was opened (joining
// the lines of a paragraph into one would change a file nothing was done
// to).
TEST(TextExport, RandomHardWrappedTextFilesAreWrittenBackUnchanged) {
    static const std::vector<std::string> words{"word", "*", "_x_", "#", "&", "<b>", "[a]", "\\", "`c`", "1.", "-",
                                                "42", "\u4eca\u5929", "a*b", "|", "**b**", "x", "Gutenberg,"};
    static const std::vector<std::string> edges{"", "", "", "", " ", "  ", "\t"};
    std::mt19937 rng(13);
    const auto pick = [&rng](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    const auto line = [&] {
        std::string t = edges[pick(edges.size())];
        for (auto n = 1 + pick(6); n > 0; --n) t += words[pick(words.size())] + (n > 1 ? " " : "");
        return t + edges[pick(edges.size())];
    };
    for (int round = 0; round < 300; ++round) {
        std::string text;
        const auto paragraphs = 2 + pick(5);
        for (std::size_t p = 0; p < paragraphs; ++p) {
            if (p > 0) text += pick(5) == 0 ? "\f\n" : "\n";
            for (auto n = 1 + pick(4); n > 0; --n) text += line() + "\n";
        }
        SCOPED_TRACE(text);
        const auto doc = import_as(text, "book.txt");
        ASSERT_EQ(exporter::to_text(doc), text);
    }
}

// The editor shows a Markdown document's text as its author
// wrote it: the writer escapes a character only where Markdown would read it
// as something else ("5 \\* 3 \\& co." was shown for "5 * 3 & co.").
TEST(MarkdownExport, TextIsEscapedOnlyWhereMarkdownWouldReadIt) {
    document::Block b;
    b.spans = {document::Span{"5 * 3 & co. <3 snake_case a*b *x* &amp; <b> ~~s~~ _y_ ** a"}};
    const auto line = exporter::markdown_line(b);
    EXPECT_EQ(line, "5 * 3 & co. <3 snake_case a\\*b \\*x\\* \\&amp; \\<b> \\~\\~s\\~\\~ \\_y\\_ ** a");
    auto doc = import::import_bytes(line + "\n", "e.md");
    ASSERT_TRUE(doc.has_value());
    ASSERT_EQ(doc->blocks.size(), 1u);
    EXPECT_EQ(doc->blocks[0].spans, b.spans);
    // At a block's start the same characters would open a list, a break or a fence.
    for (const std::string text : {"* x", "_ _ _", "~~~ x", "*"}) {
        b.spans = {document::Span{text}};
        const auto start = exporter::markdown_line(b);
        EXPECT_EQ(start, "\\" + text);
        auto again = import::import_bytes(start + "\n", "e.md");
        ASSERT_TRUE(again.has_value());
        ASSERT_EQ(again->blocks.size(), 1u) << start;
        EXPECT_EQ(again->blocks[0].text(), text);
    }
}

// ---- A text file is saved in its own encoding ----

namespace {

using tactus::test::from_hex;

struct EncodedSample {
    const char* name;
    std::string bytes;             // the file as another program wrote it
    const char* encoding;          // what the importer detects
    std::string edited_bytes;      // after `edit`, as that program would write it
    std::string from, to;          // the edit: the first `from` becomes `to` (UTF-8)
};

std::vector<EncodedSample> encoded_samples() {
    return {
        // "Café “quoted” costs €5.\n\nNaïve résumé, façade.\n" (iconv -t WINDOWS-1252)
        {"windows-1252",
         from_hex("4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 2e0a 0a4e 61ef 7665 2072 e973 756d "
                  "e92c 2066 61e7 6164 652e 0a"),
         "WINDOWS-1252",
         from_hex("4361 66e9 2093 7175 6f74 6564 9420 636f 7374 7320 8035 2e0a 0a4e 61ef 7665 2072 e973 756d "
                  "e92c 2066 61e7 6164 65fc 2e0a"),
         "façade.", "façadeü."},
        // BOM + "Hello 世界\n\nbye\n" in UTF-16LE
        {"UTF-16LE with BOM",
         from_hex("fffe 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 6200 7900 6500 0a00"),
         "UTF-16LE",
         from_hex("fffe 4800 6500 6c00 6c00 6f00 2000 164e 4c75 0a00 0a00 6200 7900 6500 2100 0a00"),
         "bye", "bye!"},
        // "春眠不覺曉，處處聞啼鳥。\n夜來風雨聲，花落知多少。\n" (iconv -t BIG5)
        {"Big5",
         from_hex("ac4b af76 a4a3 c4b1 bee5 a141 b342 b342 bb44 b3da b3be a143 0aa9 5da8 d3ad b7ab 42c1 6ea1 "
                  "41aa e1b8 a8aa bea6 68a4 d6a1 430a"),
         "BIG5",
         // the last 少 (a4d6) becomes 中 (a4a4)
         from_hex("ac4b af76 a4a3 c4b1 bee5 a141 b342 b342 bb44 b3da b3be a143 0aa9 5da8 d3ad b7ab 42c1 6ea1 "
                  "41aa e1b8 a8aa bea6 68a4 a4a1 430a"),
         "多少", "多中"},
        // "春眠不觉晓，处处闻啼鸟。\n夜来风雨声，花落知多少。\n" (iconv -t GB18030)
        {"GB18030",
         from_hex("b4ba c3df b2bb bef5 cffe a3ac b4a6 b4a6 cec5 cce4 c4f1 a1a3 0ad2 b9c0 b4b7 e7d3 eac9 f9a3 "
                  "acbb a8c2 e4d6 aab6 e0c9 d9a1 a30a"),
         "GB18030",
         // 少 (c9d9) becomes 中 (d6d0)
         from_hex("b4ba c3df b2bb bef5 cffe a3ac b4a6 b4a6 cec5 cce4 c4f1 a1a3 0ad2 b9c0 b4b7 e7d3 eac9 f9a3 "
                  "acbb a8c2 e4d6 aab6 e0d6 d0a1 a30a"),
         "多少", "多中"},
    };
}

}  // namespace

TEST(TextEncoding, AFileOpenedAndSavedIsTheSameBytes) {
    for (const auto& s : encoded_samples()) {
        SCOPED_TRACE(s.name);
        const auto doc = import_as(s.bytes, "poem.txt");
        EXPECT_EQ(doc.encoding, s.encoding);
        auto saved = exporter::encode_text(exporter::to_text(doc), doc.encoding, doc.byte_order_mark);
        ASSERT_TRUE(saved) << saved.error().to_string();
        EXPECT_EQ(*saved, s.bytes);
    }
}

TEST(TextEncoding, AnEditedFileIsSavedInItsEncoding) {
    for (const auto& s : encoded_samples()) {
        SCOPED_TRACE(s.name);
        auto doc = import_as(s.bytes, "poem.txt");
        bool edited = false;
        for (auto& b : doc.blocks)
            for (auto& span : b.spans)
                if (const auto at = span.text.find(s.from); !edited && at != std::string::npos) {
                    span.text.replace(at, s.from.size(), s.to);
                    edited = true;
                }
        ASSERT_TRUE(edited);
        auto saved = exporter::encode_text(exporter::to_text(doc), doc.encoding, doc.byte_order_mark);
        ASSERT_TRUE(saved) << saved.error().to_string();
        EXPECT_EQ(*saved, s.edited_bytes);
        // ... and it reads back as the edited text, in the same encoding.
        const auto again = import_as(*saved, "poem.txt");
        EXPECT_EQ(again.encoding, s.encoding);
        EXPECT_EQ(without_lines(again.blocks), without_lines(doc.blocks));
    }
}

TEST(TextEncoding, ACharacterTheEncodingCannotHoldIsNeverWrittenLossily) {
    // 中 in a Western file, 们 (Simplified only) in a Big5 one, an emoji in GB2312-era Big5.
    const struct {
        const char* text;
        const char* encoding;
        const char* where;
        const char* character;
    } cases[] = {
        {"Caf\xC3\xA9\n\nand \xE4\xB8\xAD here\n", "WINDOWS-1252", "3:5", "U+4E2D"},
        {"\xE6\x88\x91\xE4\xBB\xAC\n", "BIG5", "1:2", "U+4EEC"},
        {"ok\n\xF0\x9F\x98\x80\n", "BIG5", "2:1", "U+1F600"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.text);
        const auto saved = exporter::encode_text(c.text, c.encoding);
        ASSERT_FALSE(saved) << "wrote " << saved->size() << " bytes";
        EXPECT_TRUE(exporter::is_unrepresentable_error(saved.error()));
        EXPECT_EQ(saved.error().where, c.where);
        EXPECT_NE(saved.error().message.find(c.character), std::string::npos) << saved.error().message;
        EXPECT_NE(saved.error().message.find(c.encoding), std::string::npos) << saved.error().message;
    }
    // GB18030 holds every Unicode character; UTF-8 too.
    EXPECT_TRUE(exporter::encode_text("\xE6\x88\x91\xE4\xBB\xAC \xF0\x9F\x98\x80\n", "GB18030"));
    const auto unknown = exporter::encode_text("a", "no-such-encoding");
    ASSERT_FALSE(unknown);
    EXPECT_FALSE(exporter::is_unrepresentable_error(unknown.error()));
}
