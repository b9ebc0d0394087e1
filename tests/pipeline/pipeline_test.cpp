// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <optional>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "export/export.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/translation_workers.hpp"

using namespace tactus;

namespace {

document::Document many_blocks(std::size_t n) {
    document::Document d;
    d.source_name = "generated.txt";
    for (std::size_t i = 0; i < n; ++i) {
        document::Block b;
        b.source_line = static_cast<int>(i + 1);
        if (i % 97 == 50) {
            b.kind = document::BlockKind::print_page_break;
            b.label = std::to_string(i);
        } else if (i % 211 == 3) {
            b.kind = document::BlockKind::heading;
            b.level = 1;
            b.spans = {document::Span{"Chapter " + std::to_string(i), document::emphasis_none}};
        } else {
            b.spans = {document::Span{"Verse " + std::to_string(i) + ": and the children of ", document::emphasis_none},
                       document::Span{"Israel", document::emphasis_bold}, document::Span{" went forth.", document::emphasis_none}};
        }
        d.blocks.push_back(std::move(b));
    }
    return d;
}

// Paragraphs with note references and their notes, block quotes, lists and
// tables (with an empty cell), as the importers give them.
document::Document structured_blocks(std::size_t n) {
    using K = document::BlockKind;
    document::Document d;
    const auto block = [&d](K kind, int level, std::vector<document::Span> spans) {
        document::Block b;
        b.kind = kind;
        b.level = level;
        b.spans = std::move(spans);
        d.blocks.push_back(std::move(b));
    };
    document::Span ref{"1"};
    ref.note_reference = true;
    for (std::size_t i = 0; i < n; ++i) {
        const auto num = std::to_string(i);
        switch (i % 5) {
            case 0:
                block(K::paragraph, 0, {document::Span{"Paragraph " + num}, ref, document::Span{" goes on."}});
                block(K::note, 0, {ref, document::Span{" The note of " + num + "."}});
                break;
            case 1: block(K::quote, 1 + static_cast<int>(i % 2), {document::Span{"A quoted line " + num}}); break;
            case 2: block(K::list_item, 1, {document::Span{"\u2022 item " + num}}); break;
            default:
                block(K::table_row, i % 3 == 0 ? 1 : 0, {});
                block(K::table_cell, 0, {document::Span{"cell " + num}});
                block(K::table_cell, 1, {});
                block(K::table_cell, 2, {document::Span{i % 2 ? "a longer cell that will not fit " + num : "x"}});
        }
    }
    return d;
}

// Forked workers give byte-identical pages to the in-process translator, in
// the plain layout or, given `book`, the book layout.
void expect_workers_match(const document::Document& doc, unsigned workers, std::size_t min_pages,
                          std::optional<pipeline::BookOptions> book = std::nullopt) {
    pipeline::PipelineOptions single;
    single.translation_workers = 1;
    single.book = book;
    pipeline::PipelineOptions parallel;
    parallel.translation_workers = workers;
    parallel.book = book;
    const auto a = pipeline::lay_out(doc, single);
    const auto b = pipeline::lay_out(doc, parallel);
    ASSERT_TRUE(a) << a.error().to_string();
    ASSERT_TRUE(b) << b.error().to_string();
    EXPECT_GT(a->pages.size(), min_pages);
    EXPECT_EQ(exporter::to_brf(*a).value(), exporter::to_brf(*b).value());
}

}  // namespace

// Structure blocks (notes, quotes, tables) through forked workers: the same
// pages as in process.
TEST(Pipeline, WorkersCarryStructureBlocks) { expect_workers_match(structured_blocks(400), 2, 10); }

// Boxed blocks through forked workers: each block keeps its box, so the box
// lines are drawn where they are in process.
document::Document boxed_blocks(std::size_t n) {
    auto doc = structured_blocks(n);
    for (std::size_t i = 0; i < doc.blocks.size(); ++i)
        if (i % 40 >= 30) doc.blocks[i].box = static_cast<int>(i / 40) + 1;
    return doc;
}

TEST(Pipeline, WorkersKeepBoxes) {
    const auto doc = boxed_blocks(400);
    pipeline::PipelineOptions o;
    o.translation_workers = 1;
    const auto in_process = pipeline::lay_out(doc, o);
    ASSERT_TRUE(in_process) << in_process.error().to_string();
    EXPECT_NE(exporter::to_brf(*in_process).value(), exporter::to_brf(*pipeline::lay_out(structured_blocks(400), o)).value())
        << "the boxes change the pages";
    expect_workers_match(doc, 2, 10);
}

// The book layout through forked workers: the same volumes, contents and
// running heads as in process.
TEST(Pipeline, WorkersLayOutTheSameBook) {
    pipeline::BookOptions book;
    book.sheets_per_volume = 20;
    book.title = "Generated";
    expect_workers_match(many_blocks(1500), 3, 50, book);
    expect_workers_match(boxed_blocks(400), 2, 10, book);
}

// Passages in another language through forked workers: the second tables are
// opened before the fork, and the pages are the in-process ones.
TEST(Pipeline, WorkersCarryPassagesInAnotherLanguage) {
    document::Document d;
    for (int i = 0; i < 300; ++i) {
        document::Block b;
        document::Span marked{"\xE4\xBD\xA0\xE5\xA5\xBD"};  // 你好
        marked.language = "zh-CN";
        b.spans = {document::Span{"Line " + std::to_string(i) + " says \xE4\xB8\xAD\xE6\x96\x87 and "}, marked,
                   document::Span{" again."}};
        d.blocks.push_back(std::move(b));
    }
    expect_workers_match(d, 2, 10);
}

// Forked workers must give byte-identical pages to the in-process translator.
TEST(Pipeline, WorkerProcessesMatchInProcessTranslation) { expect_workers_match(many_blocks(1500), 3, 50); }

TEST(Pipeline, WorkerErrorNamesTheBlockLine) {
    auto doc = many_blocks(600);
    doc.blocks[450].spans = {document::Span{"broken \xFF text", document::emphasis_none}};
    pipeline::PipelineOptions o;
    o.translation_workers = 2;
    const auto r = pipeline::lay_out(doc, o);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "generated.txt:line 451:byte 7");
    // The in-process path reports the same place.
    o.translation_workers = 1;
    EXPECT_EQ(pipeline::lay_out(doc, o).error().where, "generated.txt:line 451:byte 7");
}

// A worker that crashes is Tactus's fault, not the document's: an internal
// error (its own exit code in the CLI), with the place it was working on.
TEST(Pipeline, WorkerCrashIsAnInternalError) {
    const auto doc = many_blocks(600);
    auto translator = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(translator);
    // The word-room callback runs inside the worker: block 300 kills it.
    const auto crash_at_300 = [&doc](const document::Block& b) -> std::size_t {
        if (&b == &doc.blocks[300]) ::kill(::getpid(), SIGKILL);
        return 0;
    };
    auto pool = pipeline::TranslationWorkers::start(doc, *translator, 2, 16, crash_at_300);
    ASSERT_TRUE(pool);
    Error error;
    for (;;) {
        auto block = pool->next();
        if (!block) {
            error = block.error();
            break;
        }
        ASSERT_TRUE(block->has_value()) << "the crash went unnoticed";
    }
    EXPECT_EQ(error.kind, ErrorKind::internal) << error.to_string();
    EXPECT_NE(error.message.find("killed by signal 9"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("line 301"), std::string::npos) << error.message;  // the block it died on
}

TEST(Pipeline, WorkersStoppedEarlyLeaveNoProcessBehind) {
    const auto doc = many_blocks(3000);
    auto translator = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(translator);
    {
        auto pool = pipeline::TranslationWorkers::start(doc, *translator, 2, 16);
        ASSERT_TRUE(pool);
        for (int i = 0; i < 10; ++i) ASSERT_TRUE(pool->next().value().has_value());
    }  // destroyed mid-document: workers are terminated and reaped
    EXPECT_EQ(::waitpid(-1, nullptr, WNOHANG), -1);  // no child left to reap
}

TEST(Pipeline, SmallDocumentsStayInProcess) {
    EXPECT_EQ(pipeline::TranslationWorkers::suggested_workers(many_blocks(10)), 1u);
}

TEST(Pipeline, InvalidLayoutOptionsAreRefusedBeforeTranslating) {
    pipeline::PipelineOptions o;
    o.layout.geometry.lines_per_page = 1;
    const auto r = pipeline::lay_out(many_blocks(3), o);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "lines_per_page");
}

TEST(Pipeline, UnknownTableIsAnError) {
    pipeline::PipelineOptions o;
    o.tables = "nope.ctb";
    EXPECT_FALSE(pipeline::lay_out(many_blocks(3), o));
}

// Cells with dots 7-8 on many lines of a six-dot layout: one warning, naming
// the first line and how many there are, not one per paragraph.
TEST(Pipeline, DotsSevenEightWarningOncePerDocument) {
    document::Document doc;
    doc.source_name = "letters.txt";
    for (int i = 0; i < 170; ++i) {
        document::Block b;
        b.source_line = 2 * i + 3;
        b.spans = {document::Span{"Dear Пётр, number " + std::to_string(i), document::emphasis_none}};
        doc.blocks.push_back(std::move(b));
    }
    pipeline::PipelineOptions o;
    o.translation_workers = 1;
    const auto paged = pipeline::lay_out(doc, o);
    ASSERT_TRUE(paged) << paged.error().to_string();
    std::vector<std::string> dots;
    for (const auto& w : paged->warnings)
        if (w.find("dots 7-8") != std::string::npos) dots.push_back(w);
    ASSERT_EQ(dots.size(), 1u) << (dots.empty() ? "" : dots[1]);
    EXPECT_TRUE(dots[0].starts_with("line 3: ")) << dots[0];
    EXPECT_NE(dots[0].find("on 170 lines"), std::string::npos) << dots[0];
}
