// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/page_range.hpp"

#include <algorithm>
#include <cctype>

#include "common/try.hpp"

namespace tactus::pipeline {
namespace {

constexpr const char* kWhere = "pages";
constexpr const char* kForm = "expected FIRST-LAST, FIRST- or N, e.g. 3-10, 5-, 7 or p1-p2";

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// A label: optional t or p, then digits that are not all zero.
Result<std::string> parse_label(std::string_view text, std::string_view whole) {
    text = trim(text);
    std::string label;
    for (const char c : text) label += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string_view digits = label;
    if (!digits.empty() && (digits.front() == 't' || digits.front() == 'p')) digits.remove_prefix(1);
    if (digits.empty() || !std::ranges::all_of(digits, [](char c) { return c >= '0' && c <= '9'; }))
        return fail(ErrorKind::usage, "'" + std::string(whole) + "': " + kForm, kWhere);
    if (std::ranges::all_of(digits, [](char c) { return c == '0'; }))
        return fail(ErrorKind::usage, "'" + std::string(whole) + "': pages count from 1", kWhere);
    // "007" is page 7, as printed.
    const auto nonzero = digits.find_first_not_of('0');
    return label.substr(0, label.size() - digits.size()) + std::string(digits.substr(nonzero));
}

}  // namespace

Result<PageRange> parse_page_range(std::string_view text) {
    const auto whole = trim(text);
    if (whole.empty()) return fail(ErrorKind::usage, std::string("no pages given: ") + kForm, kWhere);
    PageRange range;
    const auto dash = whole.find('-');
    if (dash == std::string_view::npos) {
        TACTUS_TRY(one, parse_label(whole, whole));
        range.first = one;
        range.last = one;
        return range;
    }
    if (whole.find('-', dash + 1) != std::string_view::npos)
        return fail(ErrorKind::usage, "'" + std::string(whole) + "': " + kForm, kWhere);
    TACTUS_TRY(first, parse_label(whole.substr(0, dash), whole));
    range.first = first;
    if (!trim(whole.substr(dash + 1)).empty()) {
        TACTUS_TRY(last, parse_label(whole.substr(dash + 1), whole));
        range.last = last;
    }
    return range;
}

std::vector<std::string> page_labels(const layout::PagedDocument& doc) {
    std::vector<std::string> out;
    out.reserve(doc.pages.size());
    for (const auto& p : doc.pages)
        out.push_back(p.filler || p.braille_number <= 0 ? std::string{} : std::to_string(p.braille_number));
    return out;
}

std::vector<std::string> page_labels(const BookLayout& book) {
    auto out = page_labels(book.pages);
    for (const auto& v : book.volumes)
        for (std::size_t i = v.first_page; i < v.body_first_page && i < out.size(); ++i)
            if (!out[i].empty()) out[i] = (i < v.contents_first_page ? "t" : "p") + out[i];
    return out;
}

Result<std::pair<std::size_t, std::size_t>> find_page_range(const std::vector<std::string>& labels,
                                                            const PageRange& range) {
    const auto named = [&](const std::string& label) {
        std::string what = "page " + label + " is not in the document";
        const auto first = std::ranges::find_if(labels, [](const std::string& l) { return !l.empty(); });
        const auto last = std::ranges::find_if(labels.rbegin(), labels.rend(), [](const std::string& l) { return !l.empty(); });
        if (first != labels.end()) what += " (its pages run from " + *first + " to " + *last + ")";
        return what;
    };
    const auto first = std::ranges::find(labels, range.first);
    if (first == labels.end()) return fail(ErrorKind::input, named(range.first), kWhere);
    const auto from = static_cast<std::size_t>(first - labels.begin());
    if (range.last.empty()) return std::pair{from + 1, labels.size()};
    const auto last = std::find(first, labels.end(), range.last);
    if (last == labels.end()) {
        if (std::ranges::find(labels, range.last) != labels.end())
            return fail(ErrorKind::input,
                        "page " + range.last + " comes before page " + range.first + ": give the earlier page first",
                        kWhere);
        return fail(ErrorKind::input, named(range.last), kWhere);
    }
    return std::pair{from + 1, static_cast<std::size_t>(last - labels.begin()) + 1};
}

}  // namespace tactus::pipeline
