// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How deep an input may nest (XML elements, tables in tables, lists in lists)
// before it is refused. Importers walk nested structures by recursion, each
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
                 std::move(where)};
}

// One level of a recursive walk: counts the depth while it lives.
// `if (NestingLevel level(depth_); level.too_deep()) return fail(...)`.
class NestingLevel {
public:
    explicit NestingLevel(int& depth) : depth_(depth) { ++depth_; }
    ~NestingLevel() { --depth_; }
    NestingLevel(const NestingLevel&) = delete;
    NestingLevel& operator=(const NestingLevel&) = delete;
    [[nodiscard]] bool too_deep() const { return depth_ > max_nesting_depth; }

private:
    int& depth_;
};

}  // namespace tactus
