// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text decoding for the plain-text and Markdown importers: byte-order marks,
// strict UTF-8, legacy encodings detected with uchardet and converted with ICU.
#include <cstddef>
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus::import::detail {

struct DecodedText {
    // Either `converted` holds the UTF-8 text, or (UTF-8 input) it is empty and the
    // text is `source` minus its byte-order mark: no copy of a large UTF-8 file.
    std::string converted;
    bool is_copy = false;
    std::size_t bom_bytes = 0;
    std::string encoding;  // as detected or as given by the user, e.g. "GB18030"
    bool byte_order_mark = false;  // the bytes began with one (removed from the text)

    [[nodiscard]] std::string_view text(std::string_view source) const {
        return is_copy ? std::string_view(converted) : source.substr(bom_bytes);
    }
};

// `declared` empty = detect. Fails on an unknown encoding name, on bytes that are
// not valid in the encoding (naming the byte offset), on NUL bytes (binary data)
// and on control characters other than tab, line feed, carriage return, vertical
// tab and form feed (naming line:column).
Result<DecodedText> decode_text(std::string_view bytes, std::string_view declared);

}  // namespace tactus::import::detail
