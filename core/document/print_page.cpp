// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/print_page.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace tactus::document {
namespace {

constexpr int kMaxRoman = 3999;

int roman_value(char c) {
    switch (std::tolower(static_cast<unsigned char>(c))) {
        case 'i': return 1;
        case 'v': return 5;
        case 'x': return 10;
        case 'l': return 50;
        case 'c': return 100;
        case 'd': return 500;
        case 'm': return 1000;
        default: return 0;
    }
}

std::string to_roman(int n, bool upper) {
    static constexpr std::array<std::pair<int, std::string_view>, 13> kParts{{
        {1000, "m"}, {900, "cm"}, {500, "d"}, {400, "cd"}, {100, "c"}, {90, "xc"}, {50, "l"},
        {40, "xl"}, {10, "x"}, {9, "ix"}, {5, "v"}, {4, "iv"}, {1, "i"}}};
    std::string out;
    for (const auto& [value, text] : kParts)
        for (; n >= value; n -= value) out += text;
    if (upper) std::ranges::transform(out, out.begin(), [](char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

// The value of a well-formed roman numeral in one case, 0 otherwise.
int roman(std::string_view s) {
    if (s.empty() || s.size() > 15) return 0;
    const bool upper = std::isupper(static_cast<unsigned char>(s[0])) != 0;
    int total = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const int v = roman_value(s[i]);
        if (v == 0 || (std::isupper(static_cast<unsigned char>(s[i])) != 0) != upper) return 0;
        const int next = i + 1 < s.size() ? roman_value(s[i + 1]) : 0;
        total += next > v ? -v : v;
    }
    // Only the canonical spelling counts ("iiii" and "vx" are words, not numbers).
    return total > 0 && total <= kMaxRoman && to_roman(total, upper) == s ? total : 0;
}

}  // namespace

std::string next_print_page(std::string_view current) {
    const auto last = current.find_last_of("0123456789");
    if (last != std::string_view::npos) {
        auto first = last;
        while (first > 0 && std::isdigit(static_cast<unsigned char>(current[first - 1])) != 0) --first;
        std::string digits(current.substr(first, last + 1 - first));
        // Decimal increment on the digits themselves: no overflow, leading zeros kept.
        std::size_t i = digits.size();
        while (i > 0 && digits[i - 1] == '9') digits[--i] = '0';
        if (i == 0) digits.insert(digits.begin(), '1');
        else ++digits[i - 1];
        return std::string(current.substr(0, first)) + digits + std::string(current.substr(last + 1));
    }
    if (const int n = roman(current); n > 0 && n < kMaxRoman)
        return to_roman(n + 1, std::isupper(static_cast<unsigned char>(current[0])) != 0);
    return {};
}

}  // namespace tactus::document
