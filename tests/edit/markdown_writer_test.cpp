// SPDX-License-Identifier: GPL-3.0-or-later
// Saving the editor's lines as Markdown and opening the file again gives the
// same lines: the writer and the importer agree on the dialect.
#include <gtest/gtest.h>

#include "../common/edit_fixtures.hpp"
#include "edit/editor_lines.hpp"
#include "edit/markdown_writer.hpp"
#include "import/import.hpp"

using namespace tactus;

TEST(MarkdownWriter, SavedSamplesReopenToTheSameLines) {
    for (const std::string file : {"welcome.md", "chinese-tw.txt", "chinese-cn.txt"}) {
        SCOPED_TRACE(file);
        const auto lines = test::sample_lines(file);
        ASSERT_FALSE(lines.empty());
        const auto md = edit::to_markdown(lines);
        const auto reopened = import::import_bytes(md, "saved.md");
        ASSERT_TRUE(reopened.has_value()) << reopened.error().to_string();
        std::vector<std::string> nonblank;
        for (const auto& l : lines)
            if (l.find_first_not_of(" \t\r") != std::string::npos) nonblank.push_back(l);
        EXPECT_EQ(edit::render_editor_lines(*reopened), nonblank);
    }
}

TEST(MarkdownWriter, BlankLinesMakeNoBlocksAndBlocksAreParagraphsApart) {
    const std::vector<std::string> lines{"# Title", "", "first", "   ", "second"};
    EXPECT_EQ(edit::to_markdown(lines), "# Title\n\nfirst\n\nsecond\n");
}
