// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Passing an error up unchanged, written once: a stage that chains fallible
// calls would otherwise spell out `if (!r) return std::unexpected(r.error());`
// after each and bury its logic. Works for any std::expected (Result, OsResult)
// whose error converts to the caller's. An error that is wrapped, relocated
// (`located`) or converted on the way up is written out by hand instead.
#include <expected>
#include <utility>

// Evaluates `expr`; if it failed, returns its error from the calling function.
#define TACTUS_TRY_VOID(expr)                                                 \
    do {                                                                      \
        if (auto tactus_try_result_ = (expr); !tactus_try_result_)            \
            return std::unexpected(std::move(tactus_try_result_.error()));    \
    } while (false)

// Declares `var` as the value of `expr`, or returns its error from the
// calling function. Several statements: not for an unbraced `if`.
#define TACTUS_TRY(var, expr)                                                  \
    auto var##_tactus_try_ = (expr);                                           \
    if (!var##_tactus_try_) return std::unexpected(std::move(var##_tactus_try_.error())); \
    auto var = std::move(*var##_tactus_try_)
