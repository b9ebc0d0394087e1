// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/markdown_footnotes.hpp"

#include <map>

#include "common/utf8.hpp"

namespace tactus::import {

std::optional<std::string_view> note_reference_id(std::string_view text, std::size_t at) {
    if (at > text.size() || !text.substr(at).starts_with("[^")) return std::nullopt;
    std::size_t backslashes = 0;
    while (backslashes < at && text[at - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 1) return std::nullopt;
    const auto close = text.find(']', at + 2);
    if (close == std::string_view::npos || close == at + 2) return std::nullopt;
    const auto id = text.substr(at + 2, close - at - 2);
    if (id.find_first_of(" \t[") != std::string_view::npos) return std::nullopt;
    return id;
}

}  // namespace tactus::import

namespace tactus::import::detail {
namespace {

// Supplementary Private Use Area-A: never in a real document's text that we
// keep (a source that has one loses nothing: only [^id] becomes a marker, and a
// marker is read back only for an index the source defined).
constexpr char32_t kMarkerBase = 0xF0000;
constexpr std::size_t kMaxNotes = 0xFFFD;

std::string_view trim_right(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// "[^id]: text" -> id and text; ids have no space, no bracket.
std::optional<std::pair<std::string_view, std::string_view>> definition(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && i < 3 && line[i] == ' ') ++i;
    line.remove_prefix(i);
    if (!line.starts_with("[^")) return std::nullopt;
    const auto close = line.find("]:");
    if (close == std::string_view::npos || close < 3) return std::nullopt;
    const auto id = line.substr(2, close - 2);
    if (id.find_first_of(" \t[]") != std::string_view::npos) return std::nullopt;
    auto text = line.substr(close + 2);
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    return std::pair{id, trim_right(text)};
}

bool indented(std::string_view line) { return line.starts_with("  ") || line.starts_with("\t"); }
bool blank(std::string_view line) { return trim_right(line).empty(); }

}  // namespace

std::string footnote_marker(std::size_t index) {
    std::string out;
    append_utf8(out, kMarkerBase + static_cast<char32_t>(index));
    return out;
}

std::optional<std::pair<std::size_t, std::size_t>> read_footnote_marker(std::string_view s) {
    // U+F0000..U+FFFFD is F3 B0..BF xx xx in UTF-8.
    if (s.size() < 4 || static_cast<unsigned char>(s[0]) != 0xF3 || (static_cast<unsigned char>(s[1]) & 0xF0) != 0xB0)
        return std::nullopt;
    const char32_t cp = (static_cast<char32_t>(s[1] & 0x3F) << 12) | (static_cast<char32_t>(s[2] & 0x3F) << 6) |
                        static_cast<char32_t>(s[3] & 0x3F) | (0x3u << 18);
    return std::pair{static_cast<std::size_t>(cp - kMarkerBase), std::size_t{4}};
}

PreparedMarkdown prepare_footnotes(std::string_view md) {
    PreparedMarkdown out;
    // Split into lines, keeping each line's end: LF, CRLF or CR alone, as md4c
    // and LineIndex read them (a CR-only file was one line here: no note found).
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start < md.size();) {
        auto end = md.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = md.size();
        else end += md.substr(end, 2) == "\r\n" ? std::size_t{2} : std::size_t{1};
        lines.push_back(md.substr(start, end - start));
        start = end;
    }
    const auto body = [](std::string_view l) {
        while (!l.empty() && (l.back() == '\n' || l.back() == '\r')) l.remove_suffix(1);
        return l;
    };
    // Pass 1: definitions (and their indented continuation lines) are blanked.
    std::vector<bool> blanked(lines.size(), false);
    std::map<std::string, std::size_t, std::less<>> by_id;
    bool in_fence = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto l = body(lines[i]);
        if (l.starts_with("```") || l.starts_with("~~~")) in_fence = !in_fence;
        if (in_fence) continue;
        const auto def = definition(l);
        if (!def || by_id.contains(def->first) || out.notes.size() >= kMaxNotes) continue;
        MarkdownFootnote note{std::string(def->first), std::string(def->second), static_cast<int>(i) + 1};
        blanked[i] = true;
        for (std::size_t j = i + 1; j < lines.size() && indented(body(lines[j])) && !blank(body(lines[j])); ++j) {
            auto more = body(lines[j]);
            while (!more.empty() && (more.front() == ' ' || more.front() == '\t')) more.remove_prefix(1);
            note.text += ' ';
            note.text += trim_right(more);
            blanked[j] = true;
            i = j;
        }
        by_id.emplace(note.id, out.notes.size());
        out.notes.push_back(std::move(note));
    }
    // Pass 2: the text, with references to defined notes as markers.
    out.text.reserve(md.size());
    in_fence = false;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto l = lines[i];
        if (blanked[i]) {
            out.text += l.substr(body(l).size());  // its line end
            continue;
        }
        const auto b = body(l);
        if (b.starts_with("```") || b.starts_with("~~~")) in_fence = !in_fence;
        std::size_t pos = 0;
        while (!in_fence && !by_id.empty()) {
            const auto open = l.find("[^", pos);
            if (open == std::string_view::npos) break;
            const auto id = note_reference_id(l, open);
            const auto it = id ? by_id.find(*id) : by_id.end();
            if (it == by_id.end()) {  // none, undefined, or escaped "\[^1]"
                out.text.append(l.substr(pos, open + 2 - pos));
                pos = open + 2;
                continue;
            }
            out.text.append(l.substr(pos, open - pos));
            out.text += footnote_marker(it->second);
            pos = open + id->size() + 3;
        }
        out.text.append(l.substr(pos));
    }
    return out;
}

}  // namespace tactus::import::detail
