// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target over the whole front half: bytes -> import (format detected
// from the content) -> translate, with emphasis and text in scripts the table
// may not know -> layout (ready-made braille kept or reflowed). Whatever the
// bytes, the result is pages or an error that says why: never a crash, a hang
// or a read out of bounds.
//
// The first three bytes choose: the table, the page width and whether braille
// is reflowed; the emphasis mixed into the text; the script of the extra text.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "import/import.hpp"
#include "pipeline/pipeline.hpp"

namespace {

constexpr std::array<const char*, 5> kTables = {"en-ueb-g2.ctb", "en-ueb-g1.ctb", "zh-tw.ctb", "zhcn-g1.ctb",
                                                "en-us-g2.ctb"};

// Words in scripts the tables know and do not know, a rare CJK character, an emoji.
constexpr std::array<std::string_view, 8> kScripts = {
    "Привет мир", "مرحبا بالعالم", "नमस्ते", "שלום", "\xF0\xA0\x80\x80\xF0\xA0\x80\x81", "\xF0\x9F\x98\x80 ok",
    "我們的書", "Ελληνικά 42"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return 0;
    const std::uint8_t choice = data[0], marks = data[1], script = data[2];
    const std::string_view bytes(reinterpret_cast<const char*>(data + 3), size - 3);
    auto doc = tactus::import::import_bytes(bytes, "fuzz");
    if (!doc) {
        if (doc.error().message.empty()) __builtin_trap();
        return 0;
    }
    // Emphasis on the text, and a span in another script, bold or italic.
    std::size_t n = 0;
    for (auto& block : doc->blocks) {
        if (block.spans.empty()) continue;
        for (auto& span : block.spans)
            if (!span.note_reference) span.emphasis = static_cast<std::uint8_t>((marks >> (n++ % 6)) & 0x07);
        tactus::document::Span extra{std::string(" ") + std::string(kScripts[(script + n) % kScripts.size()]),
                                     static_cast<std::uint8_t>(marks & 0x07)};
        block.spans.push_back(std::move(extra));
    }
    tactus::pipeline::PipelineOptions o;
    o.tables = kTables[choice % kTables.size()];
    o.translation_workers = 1;  // no fork inside the fuzzer
    o.layout.geometry.cells_per_line = 12 + (choice >> 3) % 30;
    o.reflow_braille = (choice & 0x04) != 0;
    o.allow_empty = true;
    const auto paged = tactus::pipeline::lay_out(*doc, o);
    if (!paged) {
        if (paged.error().message.empty()) __builtin_trap();
        return 0;
    }
    for (const auto& page : paged->pages)
        for (const auto& line : page.lines)
            if (static_cast<int>(line.size()) > paged->geometry.cells_per_line) __builtin_trap();
    return 0;
}
