// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Early return of a Result error: the spool chains many fallible SQLite calls
// and spelling out each `if (!r) return std::unexpected(r.error());` would bury
// the logic. Private to core/spool.
#define SPOOL_TRY(expr)                                                     \
    do {                                                                    \
        if (auto spool_try_result_ = (expr); !spool_try_result_)            \
            return std::unexpected(std::move(spool_try_result_.error()));   \
    } while (false)

// Declares `var` from a Result, returning its error.
#define SPOOL_LET(var, expr)                                                \
    auto var##_result_ = (expr);                                            \
    if (!var##_result_) return std::unexpected(std::move(var##_result_.error())); \
    auto var = std::move(*var##_result_)
