// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/translation_workers.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>

#include "translate/louis.hpp"
#include "common/try.hpp"

namespace tactus::pipeline {
namespace {

// Record header: cell count, or kErrorBit | length of the error (its kind, where, NUL, message).
constexpr std::uint32_t kErrorBit = 0x8000'0000u;

// The worker: translate my chunks, write one record per block; the exit status.
int work(const document::Document& doc, const translate::Translator& translator, unsigned index,
         unsigned workers, std::size_t chunk, platform::WorkerOutput& out,
         const TranslationWorkers::WordRoom& word_room) {
    const std::size_t n = doc.blocks.size();
    for (std::size_t c = index; c * chunk < n; c += workers) {
        for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) {
            auto tb = translate::translate_block(doc.blocks[i], translator,
                                      word_room ? word_room(doc.blocks[i]) : 0);
            if (!tb) {
                const auto e = located(tb.error(), doc.source_name);
                const std::string msg = static_cast<char>(e.kind) + e.where + '\0' + e.message;
                const std::uint32_t header = kErrorBit | static_cast<std::uint32_t>(msg.size());
                out.write_all(&header, sizeof header);
                out.write_all(msg.data(), msg.size());
                return 1;
            }
            const bool label = tb->kind == document::BlockKind::print_page_break;
            tb->breaks.resize(tb->cells.size(), translate::BreakBefore::never);
            const auto& cells = label ? tb->label : tb->cells;
            const auto header = static_cast<std::uint32_t>(cells.size());
            static_assert(sizeof(document::Cell) == 1 && sizeof(translate::BreakBefore) == 1);
            // The cells, then one break kind per cell (none for a page label).
            if (!out.write_all(&header, sizeof header) ||
                !out.write_all(cells.data(), cells.size()) ||
                (!label && !out.write_all(tb->breaks.data(), cells.size())))
                return 2;  // the reader is gone: nothing left to do
        }
    }
    return 0;
}

}  // namespace

bool TranslationWorkers::available() { return platform::WorkerProcess::supported(); }

unsigned TranslationWorkers::suggested_workers(const document::Document& document) {
    // Forking pays off only when translation takes a while: a few thousand blocks.
    if (document.blocks.size() < 4000 || !available()) return 1;
    return std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
}

Result<TranslationWorkers> TranslationWorkers::start(const document::Document& document,
                                                     const translate::Translator& translator,
                                                     unsigned workers, std::size_t chunk_blocks,
                                                     WordRoom word_room) {
    TranslationWorkers pool(document, std::max<std::size_t>(chunk_blocks, 1));
    workers = std::max(workers, 1u);
    // Compile the table before forking, so no worker compiles it again.
    TACTUS_TRY_VOID(translator.translate(U"a"));
    for (unsigned w = 0; w < workers; ++w) {
        auto body = [&, w](platform::WorkerOutput& out) {
            // The child's copy of the lock is held by this (its only) thread.
            translate::louis::lock().unlock();
            return work(document, translator, w, workers, pool.chunk_blocks_, out, word_room);
        };
        // No other thread may be inside liblouis while its memory is copied.
        std::lock_guard guard(translate::louis::lock());
        auto worker = platform::WorkerProcess::start(body, pool.workers_);
        if (!worker) return fail(ErrorKind::internal, "cannot start a translation worker: " + worker.error().what);
        pool.workers_.push_back(std::move(*worker));
    }
    return pool;
}

TranslationWorkers::TranslationWorkers(TranslationWorkers&& other) noexcept
    : document_(other.document_),
      chunk_blocks_(other.chunk_blocks_),
      workers_(std::move(other.workers_)),
      next_block_(other.next_block_) {
    other.workers_.clear();
}

TranslationWorkers::~TranslationWorkers() { stop(); }

void TranslationWorkers::stop() { workers_.clear(); }

Result<std::optional<translate::TranslatedBlock>> TranslationWorkers::next() {
    const auto& blocks = document_->blocks;
    if (next_block_ >= blocks.size()) return std::optional<translate::TranslatedBlock>{};
    const std::size_t i = next_block_++;
    auto& worker = workers_[(i / chunk_blocks_) % workers_.size()];
    std::uint32_t header = 0;
    if (worker.read_all(&header, sizeof header) != 1) {
        const auto why = worker.wait_for_end();
        // Not the document's fault: a worker that dies is a bug in Tactus or
        // liblouis (a crash), or the system's (out of memory), never bad input.
        return fail(ErrorKind::internal,
                    "translation worker ended unexpectedly (" + why + ") while translating from line " +
                        std::to_string(blocks[i].source_line),
                    document_->source_name);
    }
    if (header & kErrorBit) {
        std::string msg(header & ~kErrorBit, '\0');
        if (msg.empty() || worker.read_all(msg.data(), msg.size()) != 1)
            return fail(ErrorKind::internal, "translation worker ended in the middle of an error report",
                        document_->source_name);
        // The worker's error keeps its kind: a bad table stays bad input, a liblouis failure internal.
        const auto code = static_cast<unsigned char>(msg[0]);
        const auto kind = code <= static_cast<unsigned char>(ErrorKind::internal) ? static_cast<ErrorKind>(code)
                                                                             : ErrorKind::internal;
        const auto nul = msg.find('\0', 1);
        return fail(kind, msg.substr(nul + 1), msg.substr(1, nul - 1));
    }
    document::BrailleLine cells(header);
    if (worker.read_all(cells.data(), cells.size()) != 1)
        return fail(ErrorKind::internal, "translation worker ended in the middle of a block", document_->source_name);
    const document::Block& b = blocks[i];
    translate::LineBreaks breaks;
    if (document::is_text_kind(b.kind)) {
        breaks.resize(cells.size());
        if (worker.read_all(breaks.data(), breaks.size()) != 1)
            return fail(ErrorKind::internal, "translation worker ended in the middle of a block",
                        document_->source_name);
    }
    translate::TranslatedBlock tb;
    tb.kind = b.kind;
    tb.level = b.level;
    tb.span = std::max(1, b.span);
    tb.source_line = b.source_line;
    tb.box = b.box;
    if (b.kind == document::BlockKind::braille) tb.lines = b.braille_lines;
    if (b.kind == document::BlockKind::print_page_break) tb.label = std::move(cells);
    else tb.cells = std::move(cells);
    tb.breaks = std::move(breaks);
    return std::optional<translate::TranslatedBlock>(std::move(tb));
}

}  // namespace tactus::pipeline
