// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/pipeline.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_map>

#include "common/utf8.hpp"
#include "layout/paginator.hpp"
#include "pipeline/translation_workers.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

namespace tactus::pipeline {
namespace {

// Bounded single-producer/single-consumer hand-off of translated blocks.
class BlockQueue {
public:
    void push(translate::TranslatedBlock b) {
        std::unique_lock lock(m_);
        not_full_.wait(lock, [&] { return q_.size() < kCapacity; });
        q_.push_back(std::move(b));
        not_empty_.notify_one();
    }
    void close(std::optional<Error> error = std::nullopt) {
        std::lock_guard lock(m_);
        closed_ = true;
        error_ = std::move(error);
        not_empty_.notify_one();
    }
    // Empty optional: the producer is done (check error()).
    std::optional<translate::TranslatedBlock> pop() {
        std::unique_lock lock(m_);
        not_empty_.wait(lock, [&] { return !q_.empty() || closed_; });
        if (q_.empty()) return std::nullopt;
        auto b = std::move(q_.front());
        q_.pop_front();
        not_full_.notify_one();
        return b;
    }
    std::optional<Error> error() {
        std::lock_guard lock(m_);
        return error_;
    }

private:
    static constexpr std::size_t kCapacity = 256;
    std::mutex m_;
    std::condition_variable not_empty_, not_full_;
    std::deque<translate::TranslatedBlock> q_;
    bool closed_ = false;
    std::optional<Error> error_;
};

}  // namespace

Result<layout::PagedDocument> lay_out(const document::Document& document, const PipelineOptions& options) {
    if (auto ok = validate(options.layout); !ok) return std::unexpected(ok.error());
    auto translator = translate::Translator::open(options.tables);
    if (!translator) return std::unexpected(translator.error());

    std::unordered_map<int, document::BrailleLine> numbers;
    std::optional<Error> number_error;
    auto number_cells = [&](int n) -> document::BrailleLine {
        if (auto it = numbers.find(n); it != numbers.end()) return it->second;
        const auto digits = std::to_string(n);
        auto cells = translator->translate(std::u32string(digits.begin(), digits.end()));
        if (!cells) {
            number_error = cells.error();
            return {};
        }
        return numbers.emplace(n, std::move(*cells)).first->second;
    };
    layout::Paginator paginator(options.layout, number_cells);

    const unsigned workers = options.translation_workers != 0
                                 ? options.translation_workers
                                 : TranslationWorkers::suggested_workers(document);
    if (workers > 1) {
        auto pool = TranslationWorkers::start(document, *translator, workers);
        if (!pool) return std::unexpected(pool.error());
        for (;;) {
            auto block = pool->next();
            if (!block) return std::unexpected(block.error());
            if (!*block) break;
            paginator.add(**block);
        }
        if (number_error) return std::unexpected(*number_error);
        return std::move(paginator).finish();
    }

    BlockQueue queue;
    std::jthread producer([&] {
        for (const auto& block : document.blocks) {
            auto tb = translate::translate_block(block, *translator);
            if (!tb) {
                queue.close(located(tb.error(), document.source_name));
                return;
            }
            queue.push(std::move(*tb));
        }
        queue.close();
    });
    while (auto block = queue.pop()) paginator.add(*block);
    producer.join();
    if (auto e = queue.error()) return std::unexpected(*e);
    if (number_error) return std::unexpected(*number_error);
    return std::move(paginator).finish();
}

Result<layout::PagedDocument> lay_out_file(const std::filesystem::path& path,
                                   const PipelineOptions& options) {
    auto doc = import::import_file(path, options.import);
    if (!doc) return std::unexpected(doc.error());
    return lay_out(*doc, options);
}

}  // namespace tactus::pipeline
