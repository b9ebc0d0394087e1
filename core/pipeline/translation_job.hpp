// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a translation worker started as a program of its own needs (Windows,
// where a worker cannot be a copy of its parent: pipeline/translation_workers.hpp):
// the translator's configuration, which it compiles itself, and the blocks of
// its share with the room each block's words must fit, worked out by the
// parent so that the worker needs no layout. Serialized to bytes for the
// worker's input pipe and parsed back there; parent and worker are the same
// program, so the format needs no version, only a mark that it is one.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "translate/language_switch.hpp"

namespace tactus::pipeline {

struct TranslationJob {
    std::string tables;                         // Translator::tables()
    translate::LanguageSwitchOptions language;  // enabled = false: the translator had no switch
    std::string source_name;                    // for the place in an error
    std::vector<document::Block> blocks;        // the worker's share, in the order it answers
    std::vector<std::size_t> word_rooms;        // one per block (layout::word_room())
    bool operator==(const TranslationJob&) const = default;
};

std::string serialize(const TranslationJob& job);
// An internal error (never the user's input) when `bytes` is not a whole job:
// what is wrong and at which byte.
Result<TranslationJob> parse_translation_job(std::string_view bytes);

}  // namespace tactus::pipeline
