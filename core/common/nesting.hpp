// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How deep an input may nest (XML elements, tables in tables, lists in lists)
// before it is refused, checked where a tree is parsed (import/xml_util.cpp). Importers walk nested structures by recursion, each
// level a few stack frames; a file nested thousands of levels deep (made by a
// program, or hostile) would exhaust the stack and crash. No document a person
// wrote nests this deep: Word's own limit for nested tables is 63.
#include <string>

#include "common/result.hpp"

namespace tactus {

inline constexpr int max_nesting_depth = 256;

// The error for an input nested deeper than max_nesting_depth, at `where`.
inline Error too_deeply_nested(std::string what, std::string where) {
    return Error{what + " nested more than " + std::to_string(max_nesting_depth) +
                     " levels deep: refused, as no document needs that and reading it could exhaust the stack",
                 std::move(where), ErrorKind::input};
}

// An error made by too_deeply_nested: a file refused for its depth is not
// read again by a more lenient parser (it would fail deeper, and say less).
inline bool is_too_deeply_nested(const Error& e) {
    return e.message.find(" levels deep: refused, as no document needs that") != std::string::npos;
}

}  // namespace tactus
