// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Parallel translation for big documents. liblouis cannot be called from two
// threads (docs/translation.md), but it can run in two processes, each with
// its own liblouis globals. POSIX: the workers are forked after the table is
// compiled, so each starts with the document and the compiled table already in
// memory (copy-on-write). Windows: a worker is this program started again; it
// reads its job (pipeline/translation_job.hpp: the tables, its blocks and
// their word rooms) from a pipe and compiles the table itself. Worker w
// translates chunks w, w+N, w+2N, ... and streams the cells back through a
// pipe, in the same records on both systems; the caller reads the chunks in
// document order, so the pipes' own buffers are the only look-ahead and
// memory stays bounded.
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "common/result.hpp"
#include "document/document.hpp"
#include "platform/worker_process.hpp"
#include "translate/translated_document.hpp"
#include "translate/translator.hpp"

namespace tactus::pipeline {

class TranslationWorkers {
public:
    // The narrowest line each block's words must fit (layout::word_room()).
    using WordRoom = std::function<std::size_t(const document::Block&)>;

    // The document and translator must outlive this object.
    static Result<TranslationWorkers> start(const document::Document& document, const translate::Translator& translator,
                                            unsigned workers, std::size_t chunk_blocks = 64,
                                            WordRoom word_room = {});
    TranslationWorkers(TranslationWorkers&&) noexcept;
    TranslationWorkers& operator=(TranslationWorkers&&) = delete;
    ~TranslationWorkers();

    // The next block in document order; nullopt after the last one.
    Result<std::optional<translate::TranslatedBlock>> next();

    // Whether this system can run workers (platform::WorkerProcess): where it
    // cannot, translation stays in one process whatever was asked.
    static bool available();
    // How many workers a document of this size deserves on this machine.
    static unsigned suggested_workers(const document::Document& document);

private:
    TranslationWorkers(const document::Document& document, std::size_t chunk_blocks)
        : document_(&document), chunk_blocks_(chunk_blocks) {}
    void stop();

    const document::Document* document_;
    std::size_t chunk_blocks_;
    std::vector<platform::WorkerProcess> workers_;
    std::size_t next_block_ = 0;
};

// Called with each block a worker started as a program is about to translate;
// tests use it to make one crash.
using BeforeBlock = std::function<void(const document::Block&)>;

// Every main() that may start translation workers calls this before anything
// else (tactus-cli, the app, the test executables): when this process was
// started as a worker (platform::WorkerProcess::worker_side()), it translates
// the job its pipe brings and returns the exit status; nullopt otherwise.
std::optional<int> run_translation_worker(int argc, char** argv, const BeforeBlock& before_block = {});

}  // namespace tactus::pipeline
