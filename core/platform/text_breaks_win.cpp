// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/text_breaks.hpp"

#include <windows.h>
#include <usp10.h>

#include <cstdint>
#include <string>

namespace tactus::platform {

OsResult<std::vector<bool>> system_line_breaks(std::u32string_view text) {
    std::vector<bool> out(text.size() + 1, false);
    out.front() = true;
    out.back() = true;
    if (text.empty()) return out;
    // Uniscribe works in UTF-16: remember which code point each unit belongs to.
    std::wstring u16;
    std::vector<std::size_t> cp_of_unit;
    u16.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<std::uint32_t>(text[i]);
        if (c >= 0x10000 && c <= 0x10FFFF) {
            u16.push_back(static_cast<wchar_t>(0xD800 + ((c - 0x10000) >> 10)));
            u16.push_back(static_cast<wchar_t>(0xDC00 + ((c - 0x10000) & 0x3FF)));
            cp_of_unit.push_back(i);
            cp_of_unit.push_back(i);
        } else {
            u16.push_back(static_cast<wchar_t>(c));
            cp_of_unit.push_back(i);
        }
    }
    const int length = static_cast<int>(u16.size());
    std::vector<SCRIPT_ITEM> items(static_cast<std::size_t>(length) + 1);
    int count = 0;
    for (;;) {
        const HRESULT hr = ScriptItemize(u16.data(), length, static_cast<int>(items.size()) - 1, nullptr, nullptr,
                                         items.data(), &count);
        if (hr == E_OUTOFMEMORY) {
            items.resize(items.size() * 2);
            continue;
        }
        if (FAILED(hr)) return os_fail("ScriptItemize failed", OsErrorKind::other);
        break;
    }
    // Uniscribe breaks each script run on its own: at a run's first character
    // it sees no context before it, so a break there is what ScriptBreak says
    // for the run alone (ICU would look across the run boundary).
    std::vector<SCRIPT_LOGATTR> attrs(u16.size());
    for (int r = 0; r < count; ++r) {
        const int begin = items[static_cast<std::size_t>(r)].iCharPos;
        const int end = items[static_cast<std::size_t>(r) + 1].iCharPos;
        if (end <= begin) continue;
        if (FAILED(ScriptBreak(u16.data() + begin, end - begin, &items[static_cast<std::size_t>(r)].a,
                               attrs.data() + begin)))
            return os_fail("ScriptBreak failed", OsErrorKind::other);
    }
    for (std::size_t u = 1; u < u16.size(); ++u)
        if (attrs[u].fSoftBreak && cp_of_unit[u] != cp_of_unit[u - 1]) out[cp_of_unit[u]] = true;
    return out;
}

}  // namespace tactus::platform
