// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>

#include "translate/catalogue.hpp"

using namespace tactus;

TEST(Catalogue, NamesTheSpecifiedTablesByLanguage) {
    const auto tables = translate::table_catalogue();
    auto find = [&](std::string_view file) {
        return std::ranges::find(tables, file, &translate::TableInfo::file);
    };
    for (auto f : {"en-ueb-g1.ctb", "en-ueb-g2.ctb", "zh-tw.ctb", "zhcn-g1.ctb", "zhcn-g2.ctb"}) {
        const auto it = find(f);
        ASSERT_NE(it, tables.end()) << f;
        EXPECT_TRUE(it->recommended) << f;
        EXPECT_FALSE(it->name.empty()) << f;
    }
    EXPECT_EQ(find("en-ueb-g2.ctb")->language, "English");
    EXPECT_EQ(find("en-ueb-g2.ctb")->grade, "2");
    EXPECT_EQ(find("zh-tw.ctb")->language, "Chinese (Taiwan)");
    EXPECT_EQ(find("zhcn-g2.ctb")->language, "Chinese (China)");
    // Recommended tables come first, in the product's order: typing "Chinese"
    // in the picker finds Taiwan's table before China's.
    EXPECT_TRUE(tables.front().recommended);
    const auto first_chinese = std::ranges::find_if(
        tables, [](const translate::TableInfo& t) { return t.language.starts_with("Chinese"); });
    ASSERT_NE(first_chinese, tables.end());
    EXPECT_EQ(first_chinese->file, "zh-tw.ctb");
    EXPECT_GT(tables.size(), 50u);  // Debian's liblouis-data ships about 200
}

// A Chinese interface names languages in Chinese (from ICU),
// and the metadata a translated name is built from is there.
TEST(Catalogue, NamesLanguagesInTheReadersLocale) {
    const auto tables = translate::table_catalogue("zh-TW");
    auto find = [&](std::string_view file) { return std::ranges::find(tables, file, &translate::TableInfo::file); };
    ASSERT_NE(find("zh-tw.ctb"), tables.end());
    EXPECT_EQ(find("zh-tw.ctb")->language, "中文（台灣）");
    EXPECT_EQ(find("en-ueb-g2.ctb")->language, "英文");
    EXPECT_EQ(find("en-ueb-g1.ctb")->contraction, "no");
    EXPECT_EQ(find("en-ueb-g2.ctb")->contraction, "full");
    EXPECT_EQ(find("en-ueb-g2.ctb")->system, "ueb");
    // An unknown locale falls back to English rather than failing.
    const auto fallback = translate::table_catalogue("not a locale!");
    EXPECT_EQ(std::ranges::find(fallback, "en-ueb-g2.ctb", &translate::TableInfo::file)->language, "English");
}

// The languages a passage can be marked in are the recommended tables'
// languages, one each, as word processors tag them; each has its table
// (the same rule that picks the table for a marked passage), and each is
// named in the reader's locale.
TEST(Catalogue, PassageLanguagesAreThoseOfTheTables) {
    const auto languages = translate::passage_languages();
    std::vector<std::string> tags;
    for (const auto& l : languages) tags.push_back(l.tag);
    EXPECT_EQ(tags, (std::vector<std::string>{"en", "zh-TW", "zh-CN"}));
    EXPECT_EQ(translate::recommended_table("zh-TW"), "zh-tw.ctb");
    EXPECT_EQ(translate::recommended_table("zh-CN"), "zhcn-g1.ctb");
    for (const auto& l : languages) EXPECT_FALSE(translate::recommended_table(l.tag).empty()) << l.tag;
    ASSERT_EQ(languages.size(), 3u);
    EXPECT_EQ(languages[1].name, "Chinese (Taiwan)");
    EXPECT_EQ(translate::passage_languages("zh-TW")[1].name, "中文（台灣）");
    EXPECT_EQ(translate::language_display_name("de-DE"), "German (Germany)");
    EXPECT_EQ(translate::language_display_name(""), "");
}
