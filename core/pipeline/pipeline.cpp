// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/pipeline.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_map>

#include "common/utf8.hpp"
#include "layout/braille_pages.hpp"
#include "layout/braille_reflow.hpp"
#include "layout/paginator.hpp"
#include "translate/script_check.hpp"
#include "pipeline/page_range.hpp"
#include "pipeline/translation_workers.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"
#include "common/try.hpp"

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

// Code points of a block's text (UTF-8 bytes that start a character).
std::size_t text_size(const document::Block& b) {
    std::size_t n = 0;
    for (const auto& s : b.spans)
        for (char c : s.text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1u : 0u;
    return n;
}

layout::PagedDocument finish(layout::Paginator paginator, std::vector<std::string> first_warnings,
                             const document::Document& source) {
    auto doc = std::move(paginator).finish();
    // A PEF laid out again (--reflow) keeps its metadata, as it does kept page for page.
    doc.metadata = source.metadata;
    doc.warnings.insert(doc.warnings.begin(), first_warnings.begin(), first_warnings.end());
    return doc;
}

}  // namespace

namespace {
Result<layout::PagedDocument> lay_out_pages(const document::Document& document, const PipelineOptions& options,
                                            std::vector<std::string>* labels);
}  // namespace

Result<layout::PagedDocument> lay_out(const document::Document& document, const PipelineOptions& options,
                                      std::vector<std::string>* labels) {
    auto laid = lay_out_pages(document, options, labels);
    if (laid && labels && labels->size() != laid->pages.size()) *labels = page_labels(*laid);
    return laid;
}

namespace {
Result<layout::PagedDocument> lay_out_pages(const document::Document& document, const PipelineOptions& options,
                                            std::vector<std::string>* labels) {
    TACTUS_TRY_VOID(validate(options.layout));
    if (document.blocks.empty() && !options.allow_empty) {
        // Pictures without a description, say, are not nothing: the reader
        // learns what was there and could not be put in braille.
        if (!document.warnings.empty()) {
            std::string what;
            for (const auto& w : document.warnings) what += (what.empty() ? "" : "; ") + w;
            return fail(ErrorKind::input, "no text to emboss: " + what, document.source_name);
        }
        return fail(ErrorKind::input, "the document is empty: there is nothing to emboss (ask for a blank page to get one)",
                    document.source_name);
    }
    if (layout::is_ready_braille(document) && !options.reflow_braille)
        return layout::keep_braille_pages(document, options.layout);
    TACTUS_TRY(translator, translate::open_translator(options.tables, options.language_switch));
    // The second language's tables are compiled once, here, not in every forked worker.
    if (const auto* sw = translator.language_switch()) TACTUS_TRY_VOID(sw->prepare(document));
    std::string first_book_warning;
    // Worker processes translate a big document, for the book layout and the plain one alike.
    const unsigned workers = options.translation_workers != 0
                                 ? options.translation_workers
                                 : TranslationWorkers::suggested_workers(document);
    if (options.book) {
        if (options.graphic_pages && std::any_of(document.blocks.begin(), document.blocks.end(),
                                                 [](const document::Block& b) { return !b.images.empty(); }))
            first_book_warning = "pictures are not embossed as graphics in a book layout (--volumes): "
                                 "their descriptions stay";
        TACTUS_TRY(book, lay_out_book(document, options.layout, *options.book, translator, workers));
        if (labels) *labels = page_labels(book);
        auto doc = std::move(book.pages);
        doc.metadata = document.metadata;
        std::vector<std::string> first = document.warnings;
        if (auto w = translate::check_script(document, options.tables)) first.push_back(*w);
        if (!first_book_warning.empty()) first.push_back(first_book_warning);
        doc.warnings.insert(doc.warnings.begin(), first.begin(), first.end());
        return doc;
    }
    const auto room = [&options](const document::Block& b) { return layout::word_room(options.layout, b.kind, b.level); };
    std::size_t total = 0;
    if (options.progress)
        for (const auto& b : document.blocks) total += text_size(b);
    std::vector<std::string> script_warnings = document.warnings;
    if (auto w = translate::check_script(document, options.tables)) script_warnings.push_back(*w);

    std::unordered_map<int, document::BrailleLine> numbers;
    std::optional<Error> number_error;
    auto number_cells = [&](int n) -> document::BrailleLine {
        if (auto it = numbers.find(n); it != numbers.end()) return it->second;
        const auto digits = std::to_string(n);
        auto cells = translator.translate(std::u32string(digits.begin(), digits.end()));
        if (!cells) {
            number_error = cells.error();
            return {};
        }
        return numbers.emplace(n, std::move(*cells)).first->second;
    };
    layout::Paginator paginator(options.layout, number_cells);

    if (layout::is_ready_braille(document)) {
        // --reflow: the old pages' numbers and running heads out, paragraphs
        // joined and broken again only where braille may break.
        for (const auto& block : layout::reflow_braille(document)) paginator.add(block);
        if (number_error) return std::unexpected(*number_error);
        return finish(std::move(paginator), std::move(script_warnings), document);
    }

    const bool has_images = std::any_of(document.blocks.begin(), document.blocks.end(),
                                        [](const document::Block& b) { return !b.images.empty(); });
    if (options.graphic_pages && has_images) {
        // Pictures as graphic pages: blocks translated here, one at a time, so
        // the graphic stage's braille labels never meet a translation running
        // on another thread. A table's pictures follow the whole table.
        std::vector<const document::Image*> waiting;
        auto place = [&] {
            for (const auto* image : waiting) {
                auto pages = options.graphic_pages(*image);
                if (!pages) {
                    script_warnings.push_back("picture " + image->name + ": " + pages.error().message +
                                              "; its description stays");
                    continue;
                }
                for (auto& w : pages->warnings) w = "picture " + image->name + ": " + w;
                paginator.add_graphic(*pages);
            }
            waiting.clear();
        };
        std::size_t done = 0;
        for (const auto& block : document.blocks) {
            if (!document::is_table_kind(block.kind)) place();
            // A paragraph that is only a picture without a description is its graphic alone.
            const bool picture_only = !block.images.empty() && document::is_text_kind(block.kind) &&
                                      block.kind != document::BlockKind::table_cell &&
                                      block.text().find_first_not_of(" \t\r\n") == std::string::npos;
            if (!picture_only) {
                auto tb = translate::translate_block(block, translator, room(block));
                if (!tb) return std::unexpected(located(tb.error(), document.source_name));
                paginator.add(*tb);
            }
            for (const auto& image : block.images) waiting.push_back(&image);
            if (!document::is_table_kind(block.kind)) place();
            if (options.progress) options.progress(done += text_size(block), total);
        }
        place();
        if (number_error) return std::unexpected(*number_error);
        return finish(std::move(paginator), std::move(script_warnings), document);
    }

    if (workers > 1 && TranslationWorkers::available()) {
        auto pool = TranslationWorkers::start(document, translator, workers, 64, room);
        std::size_t done = 0, index = 0;
        if (!pool) return std::unexpected(pool.error());
        for (;;) {
            auto block = pool->next();
            if (!block) return std::unexpected(block.error());
            if (!*block) break;
            if (options.progress) {
                done += text_size(document.blocks[index++]);
                options.progress(done, total);
            }
            paginator.add(**block);
        }
        if (number_error) return std::unexpected(*number_error);
        return finish(std::move(paginator), std::move(script_warnings), document);
    }

    BlockQueue queue;
    std::jthread producer([&] {
        std::size_t done = 0;
        const std::function<void(std::size_t)> on_piece = [&](std::size_t in_block) {
            options.progress(done + in_block, total);
        };
        for (const auto& block : document.blocks) {
            auto tb = translate::translate_block(block, translator, room(block),
                                      options.progress ? on_piece : std::function<void(std::size_t)>{});
            if (options.progress) done += text_size(block);
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
    return finish(std::move(paginator), std::move(script_warnings), document);
}

}  // namespace

Result<layout::PagedDocument> lay_out_file(const std::filesystem::path& path,
                                   const PipelineOptions& options) {
    TACTUS_TRY(doc, import::import_file(path, options.import));
    return lay_out(doc, options);
}

}  // namespace tactus::pipeline
