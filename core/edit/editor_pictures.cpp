// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/editor_pictures.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "common/file_io.hpp"
#include "common/utf8.hpp"
#include "edit/editor_lines.hpp"
#include "export/document_save.hpp"

namespace tactus::edit {
namespace {

bool markable(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-' || c == '/';
}

// Private-use code points, one per mark, where the writer leaves a mark's place.
constexpr char32_t kFirstPlace = 0xF0000;  // plane 15, which no document here uses
constexpr std::size_t kPlaces = 0xFFFD;

std::string place(std::size_t i) { return utf32_to_utf8(std::u32string(1, kFirstPlace + static_cast<char32_t>(i))); }

}  // namespace

std::string picture_name(std::string_view name) {
    std::string out;
    for (const char c : name) out += markable(c) ? c : '_';
    return out.empty() ? std::string("picture") : out;
}

std::string picture_mark(std::string_view description, std::string_view name) {
    // Every ASCII punctuation character escaped: CommonMark reads "\x" as x
    // for any of them, so the description reads back as written.
    std::string alt;
    for (const char c : description) {
        if (c == '\n' || c == '\r' || c == '\t') {
            alt += ' ';
            continue;
        }
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x80 && std::ispunct(u)) alt += '\\';
        alt += c;
    }
    return "![" + alt + "](" + picture_name(name) + ")";
}

std::string store_picture(document::Image image, PictureStore& store) {
    const auto base = picture_name(image.name);
    std::string name = base;
    for (int n = 2;; ++n) {
        const auto it = store.find(name);
        if (it == store.end() || (it->second.bytes == image.bytes && it->second.media_type == image.media_type)) break;
        const auto dot = base.rfind('.');
        const auto slash = base.rfind('/');
        const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
        name = has_ext ? base.substr(0, dot) + "-" + std::to_string(n) + base.substr(dot)
                       : base + "-" + std::to_string(n);
    }
    image.name = name;
    store.insert_or_assign(name, std::move(image));
    return name;
}

void store_pictures(document::Document& document, PictureStore& store) {
    for (auto& block : document.blocks)
        for (auto& image : block.images)
            // A picture known by name only (a Markdown image whose file could
            // not be read) keeps its name: its mark stays as written.
            if (!image.bytes.empty()) image.name = store_picture(image, store);
}

void number_pictures(document::Document& document) {
    int n = 0;
    for (auto& block : document.blocks)
        for (auto& image : block.images) {
            const auto& type = image.media_type;
            const char* ext = type == "image/png" ? ".png" : type == "image/jpeg" ? ".jpg" : type == "image/svg+xml" ? ".svg" : "";
            image.name = "picture" + std::to_string(++n) + ext;
        }
}

void fill_pictures(document::Block& block, const PictureStore& store, std::vector<std::string>& missing) {
    std::vector<document::Image> kept;
    for (const auto& image : block.images) {
        const auto it = store.find(image.name);
        if (it == store.end()) {
            missing.push_back(image.name);
            continue;
        }
        kept.push_back(it->second);
    }
    block.images = std::move(kept);
}

std::vector<std::string> render_with_picture_marks(
    const document::Document& document, std::vector<std::string> (*write)(const document::Document&)) {
    const bool any = std::any_of(document.blocks.begin(), document.blocks.end(),
                                 [](const document::Block& b) { return !b.images.empty(); });
    if (!any) return write(document);
    std::vector<std::string> marks;
    document::Document held = document;
    for (auto& block : held.blocks) {
        std::size_t next = 0;
        std::vector<document::Span> spans;
        for (auto& span : block.spans) {
            if (span.transcriber_note && next < block.images.size() && marks.size() < kPlaces) {
                marks.push_back(picture_mark(span.text, block.images[next++].name));
                spans.push_back(document::Span{place(marks.size() - 1)});
            } else {
                spans.push_back(std::move(span));
            }
        }
        for (; next < block.images.size() && marks.size() < kPlaces; ++next) {
            marks.push_back(picture_mark("", block.images[next].name));
            spans.push_back(document::Span{place(marks.size() - 1)});
        }
        block.spans = std::move(spans);
        block.images.clear();
    }
    auto lines = write(held);
    for (auto& line : lines) {
        if (line.find("\xf3") == std::string::npos) continue;  // plane 15's UTF-8 lead byte
        for (std::size_t i = 0; i < marks.size(); ++i) {
            const auto p = place(i);
            if (const auto at = line.find(p); at != std::string::npos) line.replace(at, p.size(), marks[i]);
        }
    }
    return lines;
}

namespace {

enum class Beside { there, missing, other, outside };

// Whether the picture's file is beside `file` already, missing, a different
// file, or would be outside its folder.
Beside beside(const document::Image& image, const std::filesystem::path& file) {
    const std::filesystem::path name(image.name);
    if (name.empty() || name.is_absolute() ||
        std::any_of(name.begin(), name.end(), [](const std::filesystem::path& part) { return part == ".."; }))
        return Beside::outside;
    const auto path = file.parent_path() / name;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return Beside::missing;
    if (!std::filesystem::is_regular_file(path, error)) return Beside::other;
    auto bytes = read_file(path);
    return bytes && *bytes == image.bytes ? Beside::there : Beside::other;
}

}  // namespace

std::vector<PictureFile> picture_files(const document::Document& document, const std::filesystem::path& file) {
    std::vector<PictureFile> out;
    const auto format = exporter::document_format_for(file);
    if (format == exporter::DocumentFormat::docx || format == exporter::DocumentFormat::odt ||
        dialect_for(file.filename().string()) != Dialect::markdown)
        return out;
    for (const auto& block : document.blocks)
        for (const auto& image : block.images)
            if (beside(image, file) == Beside::missing &&
                std::none_of(out.begin(), out.end(), [&](const PictureFile& f) { return f.path == file.parent_path() / image.name; }))
                out.push_back({file.parent_path() / image.name, image.bytes});
    return out;
}

std::size_t pictures_lost(const document::Document& document, const std::filesystem::path& file) {
    const auto format = exporter::document_format_for(file);
    if (format == exporter::DocumentFormat::docx || format == exporter::DocumentFormat::odt) return 0;
    const bool markdown = dialect_for(file.filename().string()) == Dialect::markdown;
    std::size_t lost = 0;
    for (const auto& block : document.blocks)
        for (const auto& image : block.images)
            if (!markdown) {
                ++lost;
            } else if (const auto b = beside(image, file); b == Beside::other || b == Beside::outside) {
                ++lost;
            }
    return lost;
}

}  // namespace tactus::edit
