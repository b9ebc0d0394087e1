// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the spool's stored document (the snapshot every `serve` start reads
// back): any text must come back as a document or an error, never an abort
// (a wrong JSON type once stopped every printer). A document that loads
// must survive a second round trip unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "spool/snapshot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace tactus;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto doc = spool::from_snapshot(text);
    if (!doc) return 0;
    auto again = spool::from_snapshot(spool::to_snapshot(*doc));
    if (!again || again->pages != doc->pages || !(again->geometry == doc->geometry)) std::abort();
    return 0;
}
