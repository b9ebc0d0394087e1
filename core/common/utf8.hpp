// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

#include "common/result.hpp"

namespace tactus {

// Strict UTF-8 <-> UTF-32. Invalid input is an error naming the byte offset.
Result<std::u32string> utf8_to_utf32(std::string_view utf8);
// utf8_to_utf32 appended to `out`, without a copy of the whole text on the
// side (a 50 MB paragraph is 200 MB of UTF-32). On error `out` is unchanged.
Result<void> append_utf32(std::u32string& out, std::string_view utf8);
std::string utf32_to_utf8(std::u32string_view text);
void append_utf8(std::string& out, char32_t cp);
// Byte offset of the first invalid sequence, or npos when the text is valid.
std::size_t find_invalid_utf8(std::string_view utf8);

}  // namespace tactus
