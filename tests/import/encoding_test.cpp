// SPDX-License-Identifier: GPL-3.0-or-later
// Real files in the encodings teachers have (made with iconv from the sentences
// in tests/data/import/README.md), detected without being told.
#include "import_test_util.hpp"

namespace tactus::test {
namespace {

// A paragraph keeps the file's line breaks (a hard-wrapped text is written
// back as it was; braille reflows it: document/soft_break.hpp).
std::vector<std::string> texts(const document::Document& doc) {
    std::vector<std::string> out;
    for (const auto& b : doc.blocks) out.push_back(b.kind == document::BlockKind::paragraph ? b.text() : "<break>");
    return out;
}

TEST(Encoding, Big5IsDetectedAndConverted) {
    const auto doc = import_data_file("big5.txt");
    EXPECT_EQ(doc.encoding, "BIG5");
    const std::vector<std::string> expected = {
        "盲人點字是一種讓視障者用手指觸摸閱讀的文字系統。\n每個點字方格由六個點組成，排成兩行三列。",
        "老師每天準備教材，學生們在課堂上認真學習。\n今天的天氣很好，我們一起去公園散步吧。"};
    EXPECT_EQ(texts(doc), expected);
}

TEST(Encoding, Gb18030IsDetectedAndConverted) {
    const auto doc = import_data_file("gb18030.txt");
    EXPECT_EQ(doc.encoding, "GB18030");
    const std::vector<std::string> expected = {
        "盲文是一种让视障人士用手指触摸阅读的文字系统。\n每个盲文方格由六个点组成，排成两列三行。",
        "老师每天准备教材，学生们在课堂上认真学习。\n今天的天气很好，我们一起去公园散步吧。"};
    EXPECT_EQ(texts(doc), expected);
}

TEST(Encoding, Windows1252IsDetectedWithCurlyQuotesAndEuro) {
    const auto doc = import_data_file("windows1252.txt");
    EXPECT_EQ(doc.encoding, "WINDOWS-1252");
    const std::vector<std::string> expected = {
        "“Café crème” costs 5 € – naïve señor.\nLe café est très bon.",
        "Müller a mangé à la gare."};
    EXPECT_EQ(texts(doc), expected);
}

TEST(Encoding, ByteOrderMarksSelectUtf8AndUtf16) {
    const auto reference = import_data_file("utf8.txt");
    ASSERT_EQ(reference.blocks.size(), 5u);
    for (const auto& [file, encoding] : std::vector<std::pair<std::string, std::string>>{
             {"utf8_bom.txt", "UTF-8"}, {"utf16le.txt", "UTF-16LE"}, {"utf16be.txt", "UTF-16BE"}}) {
        const auto doc = import_data_file(file);
        EXPECT_EQ(doc.encoding, encoding) << file;
        EXPECT_EQ(doc.blocks, reference.blocks) << file;
    }
}

TEST(Encoding, ExplicitEncodingOverridesDetection) {
    // Read as Big5, the GB18030 bytes would be wrong text; the override is obeyed.
    const auto doc = import_data_file("gb18030.txt", {import::SourceFormat::automatic, "GB18030"});
    EXPECT_EQ(doc.encoding, "GB18030");
    ASSERT_FALSE(doc.blocks.empty());
    EXPECT_TRUE(doc.blocks[0].text().starts_with("盲文是一种"));
}

TEST(Encoding, ShortChineseTextIsNotGuessedIntoMojibake) {
    // uchardet calls these two GB18030 characters ISO-8859-16; importing that
    // guess would produce Latin garbage, so the importer asks instead.
    const auto doc = import::import_bytes("\xC4\xE3\xBA\xC3\n", "short.txt");  // 你好
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("name it explicitly"));
    EXPECT_EQ(doc.error().where, "short.txt:byte 0");
    const auto told = import::import_bytes("\xC4\xE3\xBA\xC3\n", "short.txt", {import::SourceFormat::text, "gb18030"});
    ASSERT_TRUE(told) << told.error().to_string();
    EXPECT_EQ(told->blocks.at(0).text(), "你好");
}

TEST(Encoding, ShortLatinTextBecomesWindows1252) {
    // "Señor niño" in Windows-1252; uchardet alone guesses ISO-8859-10 (ñ -> ņ).
    const auto doc = import::import_bytes("Se\xF1or ni\xF1o\n", "es.txt");
    ASSERT_TRUE(doc) << doc.error().to_string();
    EXPECT_EQ(doc->encoding, "WINDOWS-1252");
    EXPECT_EQ(doc->blocks.at(0).text(), "Señor niño");
}

TEST(Encoding, InvalidByteInDeclaredUtf8IsAnErrorWithItsOffset) {
    const auto doc = import::import_file(import_data("invalid_utf8.txt"), {import::SourceFormat::automatic, "UTF-8"});
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("invalid UTF-8"));
    EXPECT_EQ(doc.error().where, import_data("invalid_utf8.txt").string() + ":byte 17");
}

TEST(Encoding, InvalidSequenceInLegacyEncodingIsAnErrorWithItsOffset) {
    // 0xFF is never a valid byte in GB18030.
    const auto doc = import::import_bytes("ok \xC4\xE3 \xFF\xFF", "b.txt", {import::SourceFormat::text, "GB18030"});
    ASSERT_FALSE(doc);
    EXPECT_EQ(doc.error().where, "b.txt:byte 6");
}

TEST(Encoding, TruncatedUtf16IsAnErrorNotSilentLoss) {
    const auto doc = import::import_bytes(std::string_view("\xFF\xFE" "a\0b", 5), "t.txt");
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("ends inside a character"));
}

TEST(Encoding, UnknownEncodingNameIsAClearError) {
    const auto doc = import_data_file_error("utf8.txt", "klingon-42");
    EXPECT_THAT(doc.message, testing::HasSubstr("unknown encoding 'klingon-42'"));
    EXPECT_THAT(doc.where, testing::HasSubstr("encoding"));
}

TEST(Encoding, EncodingIsRefusedForBinaryFormats) {
    const auto doc = import::import_file(import_data("lesson.docx"), {import::SourceFormat::automatic, "UTF-8"});
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("only be given for text and Markdown"));
}

TEST(Encoding, Utf16WithoutBomGivesAHint) {
    const auto doc = import::import_bytes(std::string_view("H\0i\0!\0\n\0", 8), "u.txt");
    ASSERT_FALSE(doc);
    EXPECT_THAT(doc.error().message, testing::HasSubstr("UTF-16 without a byte-order mark"));
    const auto told = import::import_bytes(std::string_view("H\0i\0!\0\n\0", 8), "u.txt", {import::SourceFormat::text, "UTF-16LE"});
    ASSERT_TRUE(told) << told.error().to_string();
    EXPECT_EQ(told->blocks.at(0).text(), "Hi!");
}

}  // namespace
}  // namespace tactus::test
