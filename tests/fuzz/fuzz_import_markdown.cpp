// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the markdown importer must return a document or an error for
// any input, never crash, hang or read out of bounds.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "import/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const auto doc = tactus::import_bytes(bytes, "fuzz", {tactus::SourceFormat::markdown, {}});
    // A failure must say why; a success must not contain empty text blocks.
    if (!doc) {
        if (doc.error().message.empty()) __builtin_trap();
        return 0;
    }
    for (const auto& b : doc->blocks)
        if ((b.kind == tactus::BlockKind::paragraph || b.kind == tactus::BlockKind::heading) &&
            b.spans.empty())
            __builtin_trap();
    return 0;
}
