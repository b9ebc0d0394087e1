// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared body of the importer fuzz targets: an importer must return a document
// or an error for any input, never crash, hang or read out of bounds; a failure
// must say why, and a success must not contain empty text blocks.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "import/import.hpp"

inline int fuzz_import(const std::uint8_t* data, std::size_t size, tactus::import::SourceFormat format) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const auto doc = tactus::import::import_bytes(bytes, "fuzz", {format, {}});
    if (!doc) {
        if (doc.error().message.empty()) __builtin_trap();
        return 0;
    }
    for (const auto& b : doc->blocks)
        if ((b.kind == tactus::document::BlockKind::paragraph || b.kind == tactus::document::BlockKind::heading) &&
            b.spans.empty())
            __builtin_trap();
    return 0;
}
