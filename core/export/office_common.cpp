// SPDX-License-Identifier: GPL-3.0-or-later
#include "export/office_common.hpp"

#include <algorithm>
#include <cmath>

#include "export/markdown_syntax.hpp"
#include "export/picture_size.hpp"

namespace tactus::exporter::office {

std::string escape(std::string_view text, std::size_t* dropped) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
                    if (dropped) ++*dropped;
                } else {
                    out += c;
                }
        }
    }
    return out;
}

ListLabel list_label(const document::Block& item) {
    ListLabel out;
    if (item.spans.empty()) return out;
    const auto& first = item.spans.front();
    if (first.emphasis != document::emphasis_none || first.note_reference || first.transcriber_note ||
        first.position != document::Position::baseline || !first.language.empty())
        return out;
    const std::string_view text = first.text;
    std::size_t length = 0;
    if (text.starts_with(markdown::kBullet)) {
        out.style = ListStyle::bullet;
        length = markdown::kBullet.size();
    } else if (const auto ordinal = markdown::ordinal_length(text);
               ordinal > 0 && ordinal < text.size() && text[ordinal] == ' ' && text[0] != '0') {
        out.style = text[ordinal - 1] == '.' ? ListStyle::decimal_dot : ListStyle::decimal_paren;
        out.number = std::stoi(std::string(text.substr(0, ordinal - 1)));
        length = ordinal + 1;
    } else {
        return out;
    }
    // The importers write a label only in front of text: a label with
    // nothing after it is the item's text.
    bool rest = text.substr(length).find_first_not_of(" \t\n") != std::string_view::npos;
    for (std::size_t i = 1; i < item.spans.size() && !rest; ++i)
        rest = item.spans[i].note_reference || item.spans[i].transcriber_note ||
               item.spans[i].text.find_first_not_of(" \t\n") != std::string::npos;
    if (!rest) return ListLabel{};
    out.length = length;
    return out;
}

std::vector<document::Span> without_label(const document::Block& item, const ListLabel& label) {
    auto spans = item.spans;
    if (label.length == 0 || spans.empty()) return spans;
    spans.front().text.erase(0, label.length);
    if (spans.front().text.empty()) spans.erase(spans.begin());
    return spans;
}

std::vector<document::Span> note_body(const document::Block& note) {
    std::vector<document::Span> spans(note.spans.begin() + (note.spans.empty() ? 0 : 1), note.spans.end());
    if (!spans.empty() && !spans.front().note_reference && !spans.front().transcriber_note &&
        spans.front().text.starts_with(' ')) {
        spans.front().text.erase(0, 1);
        if (spans.front().text.empty()) spans.erase(spans.begin());
    }
    return spans;
}

Notes::Notes(const document::Document& document) {
    for (std::size_t i = 0; i < document.blocks.size(); ++i) {
        const auto& b = document.blocks[i];
        if (b.kind == document::BlockKind::note) {
            if (!b.spans.empty() && b.spans.front().note_reference) by_label.emplace(b.spans.front().text, i);
            continue;
        }
        for (const auto& s : b.spans)
            if (s.note_reference) referenced.insert(s.text);
    }
}

void Losses::add(const std::string& what, std::size_t block) {
    const auto it = std::find_if(kinds_.begin(), kinds_.end(), [&](const auto& k) { return k.first == what; });
    if (it != kinds_.end()) {
        ++it->second.count;
        return;
    }
    kinds_.emplace_back(what, Count{1, block});
}

std::vector<std::string> Losses::lines(std::string_view format) const {
    std::vector<std::string> out;
    for (const auto& [what, c] : kinds_)
        out.push_back(std::string(format) + ": " + what + " (" + std::to_string(c.count) +
                      (c.count == 1 ? " time" : " times") + "; the first at block " + std::to_string(c.first + 1) + ")");
    return out;
}

std::string picture_file_name(int number, std::string_view media_type) {
    const std::string_view extension = media_type == "image/png"       ? "png"
                                       : media_type == "image/jpeg"    ? "jpeg"
                                       : media_type == "image/svg+xml" ? "svg"
                                                                       : "";
    if (extension.empty()) return {};
    return "image" + std::to_string(number) + "." + std::string(extension);
}

bool add_picture_file(std::vector<PictureFile>& files, const document::Image& image, std::size_t block, Losses& losses) {
    auto file = picture_file_name(static_cast<int>(files.size()) + 1, image.media_type);
    if (file.empty()) {
        losses.add("a picture not PNG, JPEG or SVG is left out (its description stays)", block);
        return false;
    }
    files.push_back({std::move(file), &image});
    return true;
}

Extent picture_extent(const document::Image& image) {
    constexpr double emu_per_px = 914400.0 / 96;
    // The text's width on the writers' page (A4, 2.54 cm margins): wider
    // pictures are narrowed to it, keeping their shape, as Word does.
    constexpr double text_width = (11906 - 2 * 1440) * 635.0;
    // A picture is written at its own pixel size at 96 to the inch, what
    // Word and LibreOffice give a picture inserted with no size of its own;
    // the model keeps the bytes and not a print size. One that does not say
    // its size (an SVG without width, height or viewBox) is a square of
    // 8 cm, about a third of the text's width, visible without hiding the
    // text around it.
    const auto own = picture_pixel_size(image.bytes, image.media_type);
    double cx = own ? own->width * emu_per_px : 8 * 360000.0;
    double cy = own ? own->height * emu_per_px : 8 * 360000.0;
    if (cx > text_width) {
        cy = cy * text_width / cx;
        cx = text_width;
    }
    const auto at_least_one = [](double v) { return std::max(1LL, static_cast<long long>(std::llround(v))); };
    return {at_least_one(cx), at_least_one(cy)};
}

std::string odf_length(long long emu) {
    const long long thousandths = (emu + 180) / 360;  // 360000 EMU to the centimetre
    std::string fraction = std::to_string(thousandths % 1000);
    fraction.insert(0, 3 - fraction.size(), '0');
    return std::to_string(thousandths / 1000) + "." + fraction + "cm";
}

const document::Block* next_shown(const std::vector<document::Block>& blocks, std::size_t i, std::size_t end) {
    for (++i; i < end; ++i)
        if (blocks[i].kind != document::BlockKind::note) return &blocks[i];
    return nullptr;
}

std::size_t table_end(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end) {
    std::size_t i = begin;
    while (i < end && document::is_table_kind(blocks[i].kind)) ++i;
    return i;
}

int table_columns(const std::vector<document::Block>& blocks, std::size_t begin, std::size_t end) {
    int columns = 1;
    for (std::size_t i = begin; i < end; ++i)
        if (blocks[i].kind == document::BlockKind::table_cell)
            columns = std::max(columns, blocks[i].level + std::max(blocks[i].span, 1));
    return columns;
}

}  // namespace tactus::exporter::office
