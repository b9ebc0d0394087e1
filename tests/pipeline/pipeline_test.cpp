// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <sys/wait.h>

#include "export/export.hpp"
#include "pipeline/pipeline.hpp"
#include "pipeline/translation_workers.hpp"

using namespace tactus;

namespace {

Document many_blocks(std::size_t n) {
    Document d;
    d.source_name = "generated.txt";
    for (std::size_t i = 0; i < n; ++i) {
        Block b;
        b.source_line = static_cast<int>(i + 1);
        if (i % 97 == 50) {
            b.kind = BlockKind::print_page_break;
            b.label = std::to_string(i);
        } else if (i % 211 == 3) {
            b.kind = BlockKind::heading;
            b.level = 1;
            b.spans = {Span{"Chapter " + std::to_string(i), emphasis_none}};
        } else {
            b.spans = {Span{"Verse " + std::to_string(i) + ": and the children of ", emphasis_none},
                       Span{"Israel", emphasis_bold}, Span{" went forth.", emphasis_none}};
        }
        d.blocks.push_back(std::move(b));
    }
    return d;
}

}  // namespace

// Forked workers must give byte-identical pages to the in-process translator.
TEST(Pipeline, WorkerProcessesMatchInProcessTranslation) {
    const auto doc = many_blocks(1500);
    PipelineOptions single;
    single.translation_workers = 1;
    PipelineOptions parallel;
    parallel.translation_workers = 3;
    const auto a = lay_out(doc, single);
    const auto b = lay_out(doc, parallel);
    ASSERT_TRUE(a) << a.error().to_string();
    ASSERT_TRUE(b) << b.error().to_string();
    EXPECT_GT(a->pages.size(), 50u);
    EXPECT_EQ(to_brf(*a).value(), to_brf(*b).value());
}

TEST(Pipeline, WorkerErrorNamesTheBlockLine) {
    auto doc = many_blocks(600);
    doc.blocks[450].spans = {Span{"broken \xFF text", emphasis_none}};
    PipelineOptions o;
    o.translation_workers = 2;
    const auto r = lay_out(doc, o);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "generated.txt:line 451:byte 7");
    // The in-process path reports the same place.
    o.translation_workers = 1;
    EXPECT_EQ(lay_out(doc, o).error().where, "generated.txt:line 451:byte 7");
}

TEST(Pipeline, WorkersStoppedEarlyLeaveNoProcessBehind) {
    const auto doc = many_blocks(3000);
    auto translator = Translator::open("en-ueb-g2.ctb");
    ASSERT_TRUE(translator);
    {
        auto pool = TranslationWorkers::start(doc, *translator, 2, 16);
        ASSERT_TRUE(pool);
        for (int i = 0; i < 10; ++i) ASSERT_TRUE(pool->next().value().has_value());
    }  // destroyed mid-document: workers are terminated and reaped
    EXPECT_EQ(::waitpid(-1, nullptr, WNOHANG), -1);  // no child left to reap
}

TEST(Pipeline, SmallDocumentsStayInProcess) {
    EXPECT_EQ(TranslationWorkers::suggested_workers(many_blocks(10)), 1u);
}

TEST(Pipeline, InvalidLayoutOptionsAreRefusedBeforeTranslating) {
    PipelineOptions o;
    o.layout.geometry.lines_per_page = 1;
    const auto r = lay_out(many_blocks(3), o);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().where, "lines_per_page");
}

TEST(Pipeline, UnknownTableIsAnError) {
    PipelineOptions o;
    o.tables = "nope.ctb";
    EXPECT_FALSE(lay_out(many_blocks(3), o));
}
