// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/import.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "common/file_io.hpp"
#include "import/encoding.hpp"
#include "import/importers.hpp"
#include "import/text_lines.hpp"
#include "common/try.hpp"

namespace tactus::import {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string extension_of(std::string_view name) {
    const auto slash = name.find_last_of("/\\");
    const auto base = slash == std::string_view::npos ? name : name.substr(slash + 1);
    const auto dot = base.rfind('.');
    return dot == std::string_view::npos || dot == 0 ? std::string{} : lower(base.substr(dot + 1));
}

std::optional<SourceFormat> format_from_extension(const std::string& ext) {
    if (ext == "txt" || ext == "text") return SourceFormat::text;
    if (ext == "md" || ext == "markdown") return SourceFormat::markdown;
    if (ext == "docx") return SourceFormat::docx;
    if (ext == "odt") return SourceFormat::odt;
    if (ext == "brf" || ext == "brl") return SourceFormat::brf;
    if (ext == "pef") return SourceFormat::pef;
    if (ext == "html" || ext == "htm" || ext == "xhtml" || ext == "xht") return SourceFormat::html;
    if (ext == "epub") return SourceFormat::epub;
    if (ext == "dtbook") return SourceFormat::dtbook;
    return std::nullopt;
}

// The root element's local name of an XML or HTML document ("pef", "dtbook",
// "html"), lower-cased; empty when the bytes do not start like markup. Looks
// only at the start: the root comes after at most a declaration, comments
// and a doctype.
std::string root_element(std::string_view bytes) {
    auto head = bytes.substr(0, 4096);
    if (head.starts_with("\xEF\xBB\xBF")) head.remove_prefix(3);
    const auto first = head.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || head[first] != '<') return {};
    for (std::size_t at = head.find('<'); at != std::string_view::npos; at = head.find('<', at + 1)) {
        const auto next = head.substr(at + 1);
        if (next.starts_with("!--")) {
            const auto end = head.find("-->", at);
            if (end == std::string_view::npos) return {};
            at = end;
            continue;
        }
        if (next.starts_with('?') || next.starts_with('!')) continue;
        const auto name_end = next.find_first_of(" \t\r\n/>");
        auto name = next.substr(0, name_end);
        if (const auto colon = name.find(':'); colon != std::string_view::npos)
            name = name.substr(colon + 1);
        return lower(name);
    }
    return {};
}

}  // namespace

Result<SourceFormat> parse_source_format(std::string_view name) {
    const auto n = lower(name);
    if (n == "auto" || n == "automatic") return SourceFormat::automatic;
    // The format names are the extensions (plus their long forms).
    if (const auto f = format_from_extension(n)) return *f;
    return fail(ErrorKind::usage, "unknown input format '" + std::string(name) +
                    "' (expected auto, txt, md, docx, odt, html, epub, dtbook, brf or pef)",
                "format");
}

Result<RubyGuide> parse_ruby_guide(std::string_view name) {
    const auto n = lower(name);
    if (n == "after") return RubyGuide::after;
    if (n == "omit") return RubyGuide::omit;
    return fail(ErrorKind::usage, "unknown ruby choice '" + std::string(name) + "' (expected after or omit)", "ruby");
}

std::string_view source_format_name(SourceFormat format) {
    switch (format) {
        case SourceFormat::automatic: return "auto";
        case SourceFormat::text: return "txt";
        case SourceFormat::markdown: return "md";
        case SourceFormat::docx: return "docx";
        case SourceFormat::odt: return "odt";
        case SourceFormat::brf: return "brf";
        case SourceFormat::pef: return "pef";
        case SourceFormat::html: return "html";
        case SourceFormat::epub: return "epub";
        case SourceFormat::dtbook: return "dtbook";
    }
    return "auto";
}

SourceFormat detect_source_format(std::string_view bytes, std::string_view name) {
    if (const auto f = format_from_extension(extension_of(name))) return *f;
    if (bytes.starts_with("PK\x03\x04")) {
        // OpenDocument and EPUB packages store their type, uncompressed, as the
        // first entry: its name at byte 30 of the local header, its content
        // after it. A file cut short before them is a damaged DOCX to its reader.
        constexpr std::size_t kName = 30, kContent = kName + 8;
        const auto stored_type = bytes.size() >= kContent && bytes.substr(kName, 8) == "mimetype"
                                     ? bytes.substr(kContent)
                                     : std::string_view{};
        if (stored_type.starts_with("application/vnd.oasis.opendocument.text")) return SourceFormat::odt;
        if (stored_type.starts_with("application/epub+zip")) return SourceFormat::epub;
        return SourceFormat::docx;
    }
    // An .xml file is told by its root element: DTBook (NIMAS), XHTML, PEF.
    const auto root = root_element(bytes);
    if (root == "pef") return SourceFormat::pef;
    if (root == "dtbook") return SourceFormat::dtbook;
    if (root == "html") return SourceFormat::html;
    // Braille ASCII cannot be told from upper-case English by content, and
    // Markdown is valid plain text: both need their extension or an explicit format.
    return SourceFormat::text;
}

Result<document::Document> import_bytes(std::string_view bytes, std::string_view name,
                              const ImportOptions& options) {
    const std::string where(name);
    if (bytes.size() > max_import_bytes)
        return fail(ErrorKind::input, "input is " + std::to_string(bytes.size()) + " bytes, above the limit of " +
                        std::to_string(max_import_bytes),
                    where);
    // An SVG is a drawing, not text: read as text it would be its markup in braille.
    if (options.format == SourceFormat::automatic && (extension_of(name) == "svg" || root_element(bytes) == "svg"))
        return fail(ErrorKind::input,
                    "is an SVG drawing: Tactus embosses it as a tactile graphic laid out for a printer "
                    "(tactus-cli layout, plan or emboss with the file; docs/graphics.md), not as a document's text",
                    where);
    // So is a PNG or JPEG picture: read as text it would be its bytes.
    if (options.format == SourceFormat::automatic) {
        const auto ext = extension_of(name);
        const bool png = ext == "png" || bytes.starts_with("\x89PNG\r\n\x1a\n");
        const bool jpeg = ext == "jpg" || ext == "jpeg" || bytes.starts_with("\xFF\xD8\xFF");
        if (png || jpeg)
            return fail(ErrorKind::input,
                        std::string("is a ") + (png ? "PNG" : "JPEG") +
                            " picture: Tactus embosses it as a tactile graphic traced from its dark regions, laid out "
                            "for a printer (tactus-cli layout, plan or emboss with the file; docs/graphics.md), not as "
                            "a document's text",
                        where);
    }
    const auto format = options.format == SourceFormat::automatic
                            ? detect_source_format(bytes, name)
                            : options.format;
    if (!options.encoding.empty() && format != SourceFormat::text &&
        format != SourceFormat::markdown)
        return fail(ErrorKind::usage, "an encoding can only be given for text and Markdown input, not " +
                        std::string(source_format_name(format)),
                    where);

    Result<document::Document> doc = document::Document{};
    std::string encoding;
    std::string line_ending;
    bool byte_order_mark = false;
    switch (format) {
        case SourceFormat::text:
        case SourceFormat::markdown: {
            auto decoded = detail::decode_text(bytes, options.encoding);
            if (!decoded) return std::unexpected(located(decoded.error(), where));
            const auto text = decoded->text(bytes);
            // Pictures are read from the document's folder (its name's).
            std::error_code folder_error;
            auto parent = std::filesystem::path(name).parent_path();
            if (parent.empty()) parent = ".";
            const auto folder = std::filesystem::absolute(parent, folder_error);
            doc = format == SourceFormat::text ? detail::import_text(text)
                                               : detail::import_markdown(text, options.images ? &folder : nullptr,
                                                                         options.picture_marks);
            encoding = decoded->encoding;
            byte_order_mark = decoded->byte_order_mark;
            line_ending = line_ending_of(text);
            break;
        }
        case SourceFormat::docx:
            if (bytes.empty()) return fail(ErrorKind::input, "empty file is not a DOCX document", where);
            doc = detail::import_docx(bytes, options.ruby, options.images);
            break;
        case SourceFormat::odt:
            if (bytes.empty()) return fail(ErrorKind::input, "empty file is not an ODT document", where);
            doc = detail::import_odt(bytes, options.ruby, options.images);
            break;
        case SourceFormat::brf: doc = detail::import_brf(bytes); break;
        case SourceFormat::pef:
            if (bytes.empty()) return fail(ErrorKind::input, "empty file is not a PEF document", where);
            doc = detail::import_pef(bytes);
            break;
        case SourceFormat::html: {
            std::error_code folder_error;
            auto parent = std::filesystem::path(name).parent_path();
            if (parent.empty()) parent = ".";
            const auto folder = std::filesystem::absolute(parent, folder_error);
            doc = detail::import_html(bytes, options.images ? &folder : nullptr);
            break;
        }
        case SourceFormat::epub:
            if (bytes.empty()) return fail(ErrorKind::input, "empty file is not an EPUB", where);
            doc = detail::import_epub(bytes, options.images);
            break;
        case SourceFormat::dtbook:
            if (bytes.empty()) return fail(ErrorKind::input, "empty file is not a DTBook document", where);
            doc = detail::import_dtbook(bytes);
            break;
        case SourceFormat::automatic: break;  // resolved above
    }
    if (!doc) return std::unexpected(located(doc.error(), where));
    doc->source_name = where;
    doc->encoding = std::move(encoding);
    doc->byte_order_mark = byte_order_mark;
    doc->line_ending = std::move(line_ending);
    return doc;
}

Result<document::Document> import_file(const std::filesystem::path& path, const ImportOptions& options) {
    TACTUS_TRY(bytes, read_file(path, max_import_bytes));
    return import_bytes(bytes, path.string(), options);
}

Result<TextFile> read_text_file(const std::filesystem::path& path, const ImportOptions& options) {
    TACTUS_TRY(bytes, read_file(path, max_import_bytes));
    auto decoded = detail::decode_text(bytes, options.encoding);
    if (!decoded) return std::unexpected(located(decoded.error(), path.string()));
    return TextFile{std::string(decoded->text(bytes)), decoded->encoding, decoded->byte_order_mark};
}

}  // namespace tactus::import
