// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The import stage: turns a teacher's file (plain text, Markdown, DOCX, ODT, HTML,
// EPUB, DTBook, BRF, PEF)
// into the document model. Policies (encodings, page-break conventions, lists,
// limits) are described in docs/import.md.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "document/document.hpp"

namespace tactus::import {

enum class SourceFormat { automatic, text, markdown, docx, odt, brf, pef, html, epub, dtbook };

// A ruby (DOCX w:ruby, Word's Phonetic Guide; ODT text:ruby) always keeps
// its base text; its guide (注音, furigana) is the transcriber's choice
// (docs/import.md, "Ruby"): after the base as a transcriber's note, or left out.
enum class RubyGuide { after, omit };

struct ImportOptions {
    SourceFormat format = SourceFormat::automatic;
    std::string encoding;  // text and Markdown only; empty = detect
    RubyGuide ruby = RubyGuide::after;  // DOCX and ODT
    // Keep the bytes of pictures a graphic can be made of (PNG, JPEG, SVG) on
    // the block they stand in (document::Block::images): DOCX, ODT, Markdown,
    // HTML and EPUB.
    // A picture of another type keeps only its description, with a warning.
    bool images = false;
    // Markdown only: the editor's line dialect (edit/editor_pictures.hpp). An
    // image's alt text is its description, a transcriber's note as a DOCX
    // picture's is, and its src is kept as the picture's name
    // (document::Image::name) with no bytes: the editor holds the bytes.
    bool picture_marks = false;
};

// "after", "omit".
Result<RubyGuide> parse_ruby_guide(std::string_view name);

// Inputs above this are refused before anything is decoded, so a mistaken
// argument (a disk image, a video) fails fast instead of exhausting memory.
inline constexpr std::size_t max_import_bytes = std::size_t{256} << 20;

Result<document::Document> import_file(const std::filesystem::path& path, const ImportOptions& options = {});
// `name` is used in messages and, when the format is automatic, for its extension.
Result<document::Document> import_bytes(std::string_view bytes, std::string_view name,
                              const ImportOptions& options = {});

// A text file's content as UTF-8, decoded as import_file decodes it (the
// encoding detected or given, docs/import.md "Encodings"): what the editor
// shows of a .txt, its lines as written (import/text_lines.hpp); and the
// encoding it is saved in again (Document::encoding, byte_order_mark).
struct TextFile {
    std::string text;  // UTF-8, without the byte-order mark
    std::string encoding;
    bool byte_order_mark = false;
};
Result<TextFile> read_text_file(const std::filesystem::path& path, const ImportOptions& options = {});

// "txt"/"text", "md"/"markdown", "docx", "odt", "brf", "pef", "html"/"htm"/"xhtml",
// "epub", "dtbook", "auto"/"automatic"; case-insensitive.
Result<SourceFormat> parse_source_format(std::string_view name);
// The canonical short name ("txt", "md", ...), for messages and the CLI.
std::string_view source_format_name(SourceFormat format);

// The format `import_bytes` would use for these bytes: extension first, then content.
SourceFormat detect_source_format(std::string_view bytes, std::string_view name);

}  // namespace tactus::import
