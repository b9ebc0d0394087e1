// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "common/file_io.hpp"
#include "import/import.hpp"

namespace tactus::document {
// Readable failure output for block comparisons (found by ADL).
inline void PrintTo(const document::Block& b, std::ostream* os) {
    *os << "Block{kind=" << static_cast<int>(b.kind) << " level=" << b.level << " line="
        << b.source_line << " label='" << b.label << (b.label_counted ? "' (counted)" : "'") << " spans=[";
    for (const auto& s : b.spans)
        *os << "('" << s.text << "'," << int{s.emphasis} << (s.note_reference ? ",ref" : "") << ")";
    *os << "] braille_lines=" << b.braille_lines.size() << "}";
}
}  // namespace tactus::document

namespace tactus::test {

inline std::filesystem::path import_data(const std::string& name) {
    return std::filesystem::path(TACTUS_TEST_DATA) / "import" / name;
}

inline std::string read_data(const std::string& name) {
    auto bytes = read_file(import_data(name));
    EXPECT_TRUE(bytes.has_value()) << name;
    return bytes.value_or(std::string{});
}

// Imports a file from tests/data/import, failing the test with the error text.
inline document::Document import_data_file(const std::string& name, const import::ImportOptions& options = {}) {
    auto doc = import::import_file(import_data(name), options);
    EXPECT_TRUE(doc.has_value()) << (doc ? "" : doc.error().to_string());
    return doc.value_or(document::Document{});
}

// Imports a file that must fail; returns the error.
inline Error import_data_file_error(const std::string& name, const std::string& encoding = {},
                                    import::SourceFormat format = import::SourceFormat::automatic) {
    auto doc = import::import_file(import_data(name), {format, encoding});
    EXPECT_FALSE(doc.has_value()) << name << " imported although it should not";
    return doc ? Error{} : doc.error();
}

// Short names for the expected blocks of the importer tests:
// `using namespace shorthand;` where they are written out.
namespace shorthand {
inline constexpr auto H = document::BlockKind::heading;
inline constexpr auto P = document::BlockKind::paragraph;
inline constexpr auto LI = document::BlockKind::list_item;
inline constexpr auto N = document::BlockKind::note;
inline constexpr auto C = document::BlockKind::table_cell;
inline constexpr std::uint8_t I = document::emphasis_italic;
inline constexpr std::uint8_t B = document::emphasis_bold;
inline constexpr std::uint8_t U = document::emphasis_underline;
}  // namespace shorthand

inline document::Span reference(const std::string& label) {
    document::Span s{label};
    s.note_reference = true;
    return s;
}

inline document::Block table_row(bool header) {
    document::Block b;
    b.kind = document::BlockKind::table_row;
    b.level = header ? 1 : 0;
    return b;
}

inline std::vector<document::BlockKind> kinds(const document::Document& doc) {
    std::vector<document::BlockKind> out;
    for (const auto& b : doc.blocks) out.push_back(b.kind);
    return out;
}

inline document::Block text_block(document::BlockKind kind, int level, std::vector<document::Span> spans, int line = 0) {
    document::Block b;
    b.kind = kind;
    b.level = level;
    b.spans = std::move(spans);
    b.source_line = line;
    return b;
}

// A print page break as an importer gives it: `label` counted on from the page
// before (the source gave none), unless `counted` is false (the source's own).
inline document::Block page_break(std::string label, int line = 0, bool counted = true) {
    document::Block b;
    b.kind = document::BlockKind::print_page_break;
    b.label = std::move(label);
    b.label_counted = counted;
    b.source_line = line;
    return b;
}

}  // namespace tactus::test
