// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/translation_workers.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdint>
#include <span>
#include <string>
#include <thread>

#include "common/try.hpp"
#include "pipeline/translation_job.hpp"
#include "translate/language_switch.hpp"
#include "translate/louis.hpp"

namespace tactus::pipeline {
namespace {

// Record header: cell count, or kErrorBit | length of the error (its kind, where, NUL, message).
constexpr std::uint32_t kErrorBit = 0x8000'0000u;

// A worker's error record: its kind, where, NUL, message.
void write_error(platform::WorkerOutput& out, const Error& e) {
    const std::string msg = static_cast<char>(e.kind) + e.where + '\0' + e.message;
    const std::uint32_t header = kErrorBit | static_cast<std::uint32_t>(msg.size());
    out.write_all(&header, sizeof header);
    out.write_all(msg.data(), msg.size());
}

// The blocks worker `index` of `workers` translates: chunks index, index + N, ...
std::vector<std::size_t> share_of(std::size_t n, unsigned index, unsigned workers, std::size_t chunk) {
    std::vector<std::size_t> share;
    for (std::size_t c = index; c * chunk < n; c += workers)
        for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) share.push_back(i);
    return share;
}

// The worker, however it was started: translate these blocks, write one
// record per block; the exit status. `room(k)` is the word room of blocks[k].
int work(std::span<const document::Block* const> blocks, const std::function<std::size_t(std::size_t)>& room,
         const translate::Translator& translator, const std::string& source_name, platform::WorkerOutput& out) {
    std::string record;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        auto tb = translate::translate_block(*blocks[k], translator, room(k));
        if (!tb) {
            write_error(out, located(tb.error(), source_name));
            return 1;
        }
        const bool label = tb->kind == document::BlockKind::print_page_break;
        tb->breaks.resize(tb->cells.size(), translate::BreakBefore::never);
        const auto& cells = label ? tb->label : tb->cells;
        const auto header = static_cast<std::uint32_t>(cells.size());
        static_assert(sizeof(document::Cell) == 1 && sizeof(translate::BreakBefore) == 1);
        // The cells, then one break kind per cell (none for a page label), in
        // one write: a pipe write costs a call into the system (under Wine, a
        // round trip to its server) whatever its size.
        record.assign(reinterpret_cast<const char*>(&header), sizeof header);
        record.append(reinterpret_cast<const char*>(cells.data()), cells.size());
        if (!label) record.append(reinterpret_cast<const char*>(tb->breaks.data()), cells.size());
        if (!out.write_all(record.data(), record.size())) return 2;  // the reader is gone: nothing left to do
    }
    return 0;
}

// Where workers are copies (POSIX): each runs work() on the document in its memory.
Result<void> start_copies(const document::Document& document, const translate::Translator& translator,
                          unsigned workers, std::size_t chunk, const TranslationWorkers::WordRoom& word_room,
                          std::vector<platform::WorkerProcess>& started) {
    for (unsigned w = 0; w < workers; ++w) {
        auto body = [&, w](platform::WorkerOutput& out) {
            // The child's copy of the lock is held by this (its only) thread.
            translate::louis::lock().unlock();
            std::vector<const document::Block*> blocks;
            for (const auto i : share_of(document.blocks.size(), w, workers, chunk))
                blocks.push_back(&document.blocks[i]);
            // The word room is worked out here, in the worker, as translation is.
            const auto room = [&](std::size_t k) { return word_room ? word_room(*blocks[k]) : 0; };
            return work(blocks, room, translator, document.source_name, out);
        };
        // No other thread may be inside liblouis while its memory is copied.
        std::lock_guard guard(translate::louis::lock());
        auto worker = platform::WorkerProcess::start(body, started);
        if (!worker) return fail(ErrorKind::internal, "cannot start a translation worker: " + worker.error().what);
        started.push_back(std::move(*worker));
    }
    return {};
}

// Where a worker is this program started again (Windows): each is sent its
// job, which its main() hands to run_translation_worker().
Result<void> start_programs(const document::Document& document, const translate::Translator& translator,
                            unsigned workers, std::size_t chunk, const TranslationWorkers::WordRoom& word_room,
                            std::vector<platform::WorkerProcess>& started) {
    // Every worker first, so that they start up side by side while the jobs are written.
    for (unsigned w = 0; w < workers; ++w) {
        auto worker = platform::WorkerProcess::start_program();
        if (!worker) return fail(ErrorKind::internal, "cannot start a translation worker: " + worker.error().what);
        started.push_back(std::move(*worker));
    }
    TranslationJob job;
    job.tables = translator.tables();
    job.language.enabled = translator.language_switch() != nullptr;
    if (const auto* sw = translator.language_switch()) job.language = sw->options();
    job.source_name = document.source_name;
    for (unsigned w = 0; w < workers; ++w) {
        job.blocks.clear();
        job.word_rooms.clear();
        for (const auto i : share_of(document.blocks.size(), w, workers, chunk)) {
            job.blocks.push_back(document.blocks[i]);
            // Translation reads a picture's description, never its bytes
            // (megabytes a picture): the worker is not sent them.
            job.blocks.back().images.clear();
            job.word_rooms.push_back(word_room ? word_room(document.blocks[i]) : 0);
        }
        if (auto sent = started[w].send_input(serialize(job)); !sent)
            return fail(ErrorKind::internal, "cannot send a translation worker its blocks: " + sent.error().what);
    }
    return {};
}

}  // namespace

bool TranslationWorkers::available() { return platform::WorkerProcess::supported(); }

unsigned TranslationWorkers::suggested_workers(const document::Document& document) {
    // Workers pay off only when translation takes a while (a few thousand
    // blocks): on Windows each also compiles the table again.
    if (document.blocks.size() < 4000 || !available()) return 1;
    return std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
}

Result<TranslationWorkers> TranslationWorkers::start(const document::Document& document,
                                                     const translate::Translator& translator,
                                                     unsigned workers, std::size_t chunk_blocks,
                                                     WordRoom word_room) {
    TranslationWorkers pool(document, std::max<std::size_t>(chunk_blocks, 1));
    workers = std::max(workers, 1u);
    // Compile the table first: a copied worker then does not compile it again,
    // and a table that does not compile fails here, not in every worker.
    TACTUS_TRY_VOID(translator.translate(U"a"));
    if (platform::WorkerProcess::how() == platform::WorkerStart::copy) {
        TACTUS_TRY_VOID(start_copies(document, translator, workers, pool.chunk_blocks_, word_room, pool.workers_));
    } else {
        TACTUS_TRY_VOID(start_programs(document, translator, workers, pool.chunk_blocks_, word_room, pool.workers_));
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


std::optional<int> run_translation_worker(int argc, char** argv, const BeforeBlock& before_block) {
    auto side = platform::WorkerProcess::worker_side(argc, argv);
    if (!side) return std::nullopt;
    if (!*side) {
        std::fprintf(stderr, "tactus translation worker: %s\n", side->error().what.c_str());
        return 70;
    }
    auto& out = (*side)->output;
    auto job = parse_translation_job((*side)->input);
    if (!job) {
        write_error(out, job.error());
        return 1;
    }
    auto translator = translate::open_translator(job->tables, job->language);
    if (!translator) {
        write_error(out, translator.error());
        return 1;
    }
    std::vector<const document::Block*> blocks;
    for (const auto& b : job->blocks) blocks.push_back(&b);
    const auto room = [&](std::size_t k) {
        if (before_block) before_block(job->blocks[k]);
        return job->word_rooms[k];
    };
    return work(blocks, room, *translator, job->source_name, out);
}

}  // namespace tactus::pipeline
