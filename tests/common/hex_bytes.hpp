// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bytes written as hex ("e9 20 41", spaces ignored): files in a legacy
// encoding, spelled out in a test as another program wrote them.
#include <string>
#include <string_view>

namespace tactus::test {

inline std::string from_hex(std::string_view hex) {
    std::string out;
    for (std::size_t i = 0; i + 1 < hex.size();) {
        if (hex[i] == ' ') {
            ++i;
            continue;
        }
        out += static_cast<char>(std::stoi(std::string(hex.substr(i, 2)), nullptr, 16));
        i += 2;
    }
    return out;
}

}  // namespace tactus::test
