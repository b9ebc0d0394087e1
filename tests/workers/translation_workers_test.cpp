// SPDX-License-Identifier: GPL-3.0-or-later
// Translation workers started the way this system starts them give the pages
// one process gives, and a worker that crashes is an internal error. The same
// tests on POSIX (forked workers) and on Windows (this executable started
// again: tests/common/test_main.cpp hands it to the worker).
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <optional>
#include <string>

#include "export/export.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/translation_workers.hpp"
#include "platform/worker_process.hpp"

using namespace tactus;

namespace {

// Headings, paragraphs with bold and a note reference, their notes, quotes,
// list items, a table, print page breaks and a box: every kind a worker
// translates, and the word room differing between them.
document::Document mixed_blocks(std::size_t n) {
    using K = document::BlockKind;
    document::Document d;
    d.source_name = "generated.txt";
    const auto add = [&d](K kind, int level, std::vector<document::Span> spans) {
        document::Block b;
        b.kind = kind;
        b.level = level;
        b.spans = std::move(spans);
        b.source_line = static_cast<int>(d.blocks.size() + 1);
        d.blocks.push_back(std::move(b));
    };
    document::Span ref{"1"};
    ref.note_reference = true;
    for (std::size_t i = 0; d.blocks.size() < n; ++i) {
        const auto num = std::to_string(i);
        switch (i % 9) {
            case 0: add(K::heading, 1 + static_cast<int>(i % 3), {document::Span{"Chapter " + num}}); break;
            case 1:
                add(K::paragraph, 0, {document::Span{"Verse " + num + ": and the children of "},
                                      document::Span{"Israel", document::emphasis_bold}, ref,
                                      document::Span{" went forth, 1,250 of them, on 3/4 of the way."}});
                add(K::note, 0, {ref, document::Span{" The note of " + num + "."}});
                break;
            case 2: add(K::quote, 1, {document::Span{"A quoted line " + num + " that is long enough to wrap"}}); break;
            case 3: add(K::list_item, 1 + static_cast<int>(i % 2), {document::Span{"\u2022 item " + num}}); break;
            case 4:
                add(K::print_page_break, 0, {});
                d.blocks.back().label = num;
                break;
            case 5:
                add(K::table_row, 1, {});
                add(K::table_cell, 0, {document::Span{"cell " + num}});
                add(K::table_cell, 1, {document::Span{"a longer cell that will not fit " + num}});
                break;
            default: add(K::paragraph, 0, {document::Span{"Plain paragraph number " + num + " goes on and on."}});
        }
        if (i % 50 >= 45) d.blocks.back().box = static_cast<int>(i / 50) + 1;
    }
    return d;
}

std::string brf(const document::Document& doc, unsigned workers, std::optional<pipeline::BookOptions> book = {}) {
    pipeline::PipelineOptions o;
    o.translation_workers = workers;
    o.book = book;
    const auto pages = pipeline::lay_out(doc, o);
    EXPECT_TRUE(pages) << pages.error().to_string();
    return pages ? exporter::to_brf(*pages).value() : std::string{};
}

}  // namespace

TEST(TranslationWorkers, ThisSystemStartsThem) {
    EXPECT_TRUE(pipeline::TranslationWorkers::available());
}

// Byte-identical pages with 1, 2 and 3 workers, in the plain layout.
TEST(TranslationWorkers, PagesAreTheOneProcessPages) {
    const auto doc = mixed_blocks(2000);
    const auto one = brf(doc, 1);
    EXPECT_GT(one.size(), 50'000u);
    EXPECT_EQ(brf(doc, 2), one);
    EXPECT_EQ(brf(doc, 3), one);
}

TEST(TranslationWorkers, BookIsTheOneProcessBook) {
    pipeline::BookOptions book;
    book.sheets_per_volume = 20;
    book.title = "Generated";
    const auto doc = mixed_blocks(1000);
    EXPECT_EQ(brf(doc, 2, book), brf(doc, 1, book));
}

// The second language's options reach the workers: a passage marked as
// Chinese is translated with a Chinese table there too.
TEST(TranslationWorkers, PassagesInAnotherLanguage) {
    document::Document d;
    for (int i = 0; i < 200; ++i) {
        document::Block b;
        b.source_line = i + 1;
        document::Span marked{"\xE4\xBD\xA0\xE5\xA5\xBD"};  // 你好
        marked.language = "zh-CN";
        b.spans = {document::Span{"Line " + std::to_string(i) + " says "}, marked, document::Span{" again."}};
        d.blocks.push_back(std::move(b));
    }
    const auto one = brf(d, 1);
    EXPECT_EQ(brf(d, 2), one);
    pipeline::PipelineOptions off;
    off.translation_workers = 2;
    off.language_switch.enabled = false;
    const auto without = pipeline::lay_out(d, off);
    ASSERT_TRUE(without) << without.error().to_string();
    EXPECT_NE(exporter::to_brf(*without).value(), one) << "the switch changes the braille";
}

// A worker that dies is Tactus's fault, never the document's: an internal
// error naming the line it was working on, and the system's word for how it ended.
TEST(TranslationWorkers, CrashIsAnInternalError) {
    const auto doc = mixed_blocks(600);
    auto translator = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(translator);
    // A copied worker runs the word-room callback; a started one, the hook
    // of the test main, which reads this variable.
#ifdef _WIN32
    ASSERT_EQ(_putenv_s("TACTUS_TEST_WORKER_CRASH_LINE", "301"), 0);
#endif
    const auto crash_at_301 = [](const document::Block& b) -> std::size_t {
#ifdef SIGKILL
        if (b.source_line == 301) std::raise(SIGKILL);
#endif
        return b.source_line == 301 ? 0 : 30;
    };
    std::optional<Error> error;
    {
        auto pool = pipeline::TranslationWorkers::start(doc, *translator, 2, 16, crash_at_301);
        ASSERT_TRUE(pool) << pool.error().to_string();
        for (std::size_t read = 0; read <= doc.blocks.size(); ++read) {
            auto block = pool->next();
            if (!block) {
                error = block.error();
                break;
            }
            ASSERT_TRUE(block->has_value()) << "the crash went unnoticed";
        }
    }
#ifdef _WIN32
    _putenv_s("TACTUS_TEST_WORKER_CRASH_LINE", "");
#endif
    ASSERT_TRUE(error);
    EXPECT_EQ(error->kind, ErrorKind::internal) << error->to_string();
    EXPECT_NE(error->message.find("translation worker ended unexpectedly"), std::string::npos) << error->message;
    EXPECT_NE(error->message.find("line 301"), std::string::npos) << error->message;
#ifdef _WIN32
    EXPECT_NE(error->message.find("(exit status 3)"), std::string::npos) << error->message;  // abort()'s
#else
    EXPECT_NE(error->message.find("(killed by signal 9)"), std::string::npos) << error->message;
#endif
}

// Workers let go of in the middle of a document end, and the next pool works.
TEST(TranslationWorkers, StoppedEarlyTheyEnd) {
    const auto doc = mixed_blocks(3000);
    auto translator = translate::Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(translator);
    for (int round = 0; round < 2; ++round) {
        auto pool = pipeline::TranslationWorkers::start(doc, *translator, 2, 16);
        ASSERT_TRUE(pool) << pool.error().to_string();
        for (int i = 0; i < 40; ++i) ASSERT_TRUE(pool->next().value().has_value());
    }
}
