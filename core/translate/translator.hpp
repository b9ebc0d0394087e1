// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text -> braille cells and back, through liblouis, always with an explicit
// display table (unicode.dis) so cells come back as Unicode braille whatever the
// table's own display defaults are.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "common/result.hpp"
#include "document/cell.hpp"

namespace tactus::translate {

class Translator {
public:
    // `tables` is a liblouis table list, e.g. "en-ueb-g2.ctb" or
    // "en-ueb-g1.ctb,my-extra.cti". Fails with liblouis's own reason when a table
    // is missing or does not compile.
    static Result<Translator> open(std::string tables);

    [[nodiscard]] const std::string& tables() const { return tables_; }

    // `emphasis` is empty or one Emphasis bit set per code point of `text`.
    Result<document::BrailleLine> translate(std::u32string_view text,
                                  std::span<const std::uint8_t> emphasis = {}) const;

    // Back-translation for proofreading: what a reader of these cells would read.
    Result<std::u32string> back_translate(const document::BrailleLine& cells) const;

    // What liblouis produces for `text` with another display table, e.g.
    // "en-us-brf.dis" for Braille ASCII; used by `tactus-cli translate`.
    Result<std::u32string> translate_with_display(std::u32string_view text,
                                                  std::string_view display_table) const;

private:
    explicit Translator(std::string tables) : tables_(std::move(tables)) {}
    std::string tables_;
};

}  // namespace tactus::translate
