// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/cell_paragraphs.hpp"

#include <algorithm>

namespace tactus::document {
namespace {

bool cuttable(const Span& s) { return !s.note_reference && !s.transcriber_note; }

}  // namespace

bool has_cell_paragraphs(std::span<const Span> spans) {
    return std::ranges::any_of(spans, [](const Span& s) { return cuttable(s) && s.text.find('\n') != std::string::npos; });
}

std::vector<std::vector<Span>> cell_paragraphs(std::span<const Span> spans) {
    std::vector<std::vector<Span>> out(1);
    for (const auto& s : spans) {
        if (!cuttable(s) || s.text.find('\n') == std::string::npos) {
            out.back().push_back(s);
            continue;
        }
        std::size_t from = 0;
        while (true) {
            const auto nl = s.text.find('\n', from);
            Span piece = s;
            piece.text = s.text.substr(from, nl == std::string::npos ? std::string::npos : nl - from);
            if (!piece.text.empty()) out.back().push_back(std::move(piece));
            if (nl == std::string::npos) break;
            out.emplace_back();
            from = nl + 1;
        }
    }
    return out;
}

}  // namespace tactus::document
