// SPDX-License-Identifier: GPL-3.0-or-later
// The job a translation worker started as a program reads: whatever the blocks
// hold comes back equal, and bytes that are not a whole job are refused.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

#include "pipeline/translation_job.hpp"

using namespace tactus;
using pipeline::TranslationJob;

namespace {

class RandomJobs {
public:
    explicit RandomJobs(unsigned seed) : rng_(seed) {}

    TranslationJob job(std::size_t max_blocks) {
        TranslationJob j;
        j.tables = text(20);
        j.language.enabled = coin();
        j.language.second_table = text(12);
        j.language.english_grade = text(2);
        j.language.indicators = static_cast<translate::SwitchIndicators>(below(4));
        j.source_name = text(30);
        const auto n = below(max_blocks + 1);
        for (std::size_t i = 0; i < n; ++i) {
            j.blocks.push_back(block());
            j.word_rooms.push_back(coin() ? below(80) : rng_());
        }
        return j;
    }

private:
    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
    bool coin() { return below(2) == 1; }
    int number() { return std::uniform_int_distribution<int>(std::numeric_limits<int>::min(), std::numeric_limits<int>::max())(rng_); }
    // Any bytes, NUL and invalid UTF-8 among them: the job carries them as they are.
    std::string text(std::size_t max) {
        std::string s(below(max + 1), '\0');
        for (auto& c : s) c = static_cast<char>(below(256));
        return s;
    }
    document::Block block() {
        document::Block b;
        b.kind = static_cast<document::BlockKind>(below(10));
        b.level = number();
        for (auto n = below(5); n > 0; --n) {
            document::Span s{text(40), static_cast<std::uint8_t>(below(256))};
            s.note_reference = coin();
            s.position = static_cast<document::Position>(below(3));
            s.transcriber_note = coin();
            s.language = text(6);
            b.spans.push_back(std::move(s));
        }
        for (auto n = below(3); n > 0; --n) {
            document::BrailleLine line(below(30));
            for (auto& c : line) c.dots = static_cast<std::uint8_t>(below(256));
            b.braille_lines.push_back(std::move(line));
        }
        b.label = text(5);
        b.label_counted = coin();
        b.source_line = number();
        b.span = number();
        b.align = static_cast<document::Align>(below(4));
        b.box = number();
        for (auto n = below(2); n > 0; --n) b.images.push_back({text(100), text(12), text(20)});
        return b;
    }
    std::mt19937_64 rng_;
};

}  // namespace

// Property: serialize, then parse, gives the same job, every field of every
// block included, over random jobs.
TEST(TranslationJob, RandomJobsComeBackEqual) {
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const auto job = RandomJobs(seed).job(12);
        const auto parsed = pipeline::parse_translation_job(pipeline::serialize(job));
        ASSERT_TRUE(parsed) << "seed " << seed << ": " << parsed.error().to_string();
        ASSERT_EQ(*parsed, job) << "seed " << seed;
    }
}

// A job cut short anywhere is refused as Tactus's own fault, with the byte it
// ended at, never read as a shorter job.
TEST(TranslationJob, EveryCutIsRefused) {
    const auto bytes = pipeline::serialize(RandomJobs(7).job(3));
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        const auto parsed = pipeline::parse_translation_job(std::string_view(bytes).substr(0, n));
        ASSERT_FALSE(parsed) << "cut at " << n;
        EXPECT_EQ(parsed.error().kind, ErrorKind::internal);
        EXPECT_EQ(parsed.error().where.rfind("byte ", 0), 0u) << parsed.error().where;
    }
}

TEST(TranslationJob, UnknownKindsAndExtraBytesAreRefused) {
    TranslationJob job;
    job.tables = "en-ueb-g2.ctb";
    const auto head = pipeline::serialize(job).size();  // everything before the first block
    job.blocks.emplace_back();
    job.word_rooms.push_back(40);
    auto bytes = pipeline::serialize(job);
    ASSERT_TRUE(pipeline::parse_translation_job(bytes));
    auto unknown = bytes;
    unknown[head] = static_cast<char>(200);  // the block's kind
    const auto refused = pipeline::parse_translation_job(unknown);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().to_string(),
              "byte " + std::to_string(head + 1) + ": a translation job this program cannot read: an unknown kind 200");
    EXPECT_FALSE(pipeline::parse_translation_job(bytes + "x"));
    EXPECT_FALSE(pipeline::parse_translation_job("x" + bytes));
}
