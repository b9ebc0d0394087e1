// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/translation_workers.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>

#include "translate/louis.hpp"

namespace tactus::pipeline {
namespace {

// Record header: cell count, or kErrorBit | message length.
constexpr std::uint32_t kErrorBit = 0x8000'0000u;

bool write_all(int fd, const void* data, std::size_t n) {
    const auto* p = static_cast<const char*>(data);
    while (n > 0) {
        const auto w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= static_cast<std::size_t>(w);
    }
    return true;
}

// 1: read all, 0: end of stream before anything, -1: error or short read.
int read_all(int fd, void* data, std::size_t n) {
    auto* p = static_cast<char*>(data);
    std::size_t done = 0;
    while (done < n) {
        const auto r = ::read(fd, p + done, n - done);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) return -1;
        if (r == 0) return done == 0 ? 0 : -1;
        done += static_cast<std::size_t>(r);
    }
    return 1;
}

// The worker: translate my chunks, write one record per block, exit.
[[noreturn]] void work(const document::Document& doc, const translate::Translator& translator, unsigned index,
                       unsigned workers, std::size_t chunk, int fd,
                       const TranslationWorkers::WordRoom& word_room) {
    const std::size_t n = doc.blocks.size();
    for (std::size_t c = index; c * chunk < n; c += workers) {
        for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) {
            auto tb = translate::translate_block(doc.blocks[i], translator,
                                      word_room ? word_room(doc.blocks[i]) : 0);
            if (!tb) {
                const auto e = located(tb.error(), doc.source_name);
                const std::string msg = e.where + '\0' + e.message;
                const std::uint32_t header = kErrorBit | static_cast<std::uint32_t>(msg.size());
                write_all(fd, &header, sizeof header);
                write_all(fd, msg.data(), msg.size());
                ::_exit(1);
            }
            const bool label = tb->kind == document::BlockKind::print_page_break;
            tb->breaks.resize(tb->cells.size(), translate::BreakBefore::never);
            const auto& cells = label ? tb->label : tb->cells;
            const auto header = static_cast<std::uint32_t>(cells.size());
            static_assert(sizeof(document::Cell) == 1 && sizeof(translate::BreakBefore) == 1);
            // The cells, then one break kind per cell (none for a page label).
            if (!write_all(fd, &header, sizeof header) ||
                !write_all(fd, cells.data(), cells.size()) ||
                (!label && !write_all(fd, tb->breaks.data(), cells.size())))
                ::_exit(2);  // the reader is gone: nothing left to do
        }
    }
    ::_exit(0);
}

}  // namespace

unsigned TranslationWorkers::suggested_workers(const document::Document& document) {
    // Forking pays off only when translation takes a while: a few thousand blocks.
    if (document.blocks.size() < 4000) return 1;
    return std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
}

Result<TranslationWorkers> TranslationWorkers::start(const document::Document& document,
                                                     const translate::Translator& translator,
                                                     unsigned workers, std::size_t chunk_blocks,
                                                     WordRoom word_room) {
    TranslationWorkers pool(document, std::max<std::size_t>(chunk_blocks, 1));
    workers = std::max(workers, 1u);
    // Compile the table before forking, so no worker compiles it again.
    if (auto warm = translator.translate(U"a"); !warm) return std::unexpected(warm.error());
    for (unsigned w = 0; w < workers; ++w) {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0)
            return fail(std::string("cannot create a pipe for translation: ") + std::strerror(errno));
        pid_t pid = 0;
        {
            // No other thread may be inside liblouis while its memory is copied.
            std::lock_guard guard(translate::louis::lock());
            pid = ::fork();
            if (pid == 0) {
                // The child's copy of the lock is held by this (its only) thread.
                translate::louis::lock().unlock();
                ::close(fds[0]);
                for (int fd : pool.fds_) ::close(fd);
                work(document, translator, w, workers, pool.chunk_blocks_, fds[1], word_room);
            }
        }
        ::close(fds[1]);
        if (pid < 0) {
            ::close(fds[0]);
            return fail(std::string("cannot start a translation worker: ") + std::strerror(errno));
        }
        pool.pids_.push_back(pid);
        pool.fds_.push_back(fds[0]);
    }
    return pool;
}

TranslationWorkers::TranslationWorkers(TranslationWorkers&& other) noexcept
    : document_(other.document_),
      chunk_blocks_(other.chunk_blocks_),
      pids_(std::move(other.pids_)),
      fds_(std::move(other.fds_)),
      next_block_(other.next_block_) {
    other.pids_.clear();
    other.fds_.clear();
}

TranslationWorkers::~TranslationWorkers() { stop(); }

void TranslationWorkers::stop() {
    for (int fd : fds_) ::close(fd);
    for (pid_t pid : pids_) {
        ::kill(pid, SIGTERM);
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
    }
    fds_.clear();
    pids_.clear();
}

Result<std::optional<translate::TranslatedBlock>> TranslationWorkers::next() {
    const auto& blocks = document_->blocks;
    if (next_block_ >= blocks.size()) return std::optional<translate::TranslatedBlock>{};
    const std::size_t i = next_block_++;
    const auto worker = (i / chunk_blocks_) % fds_.size();
    const int fd = fds_[worker];
    std::uint32_t header = 0;
    if (read_all(fd, &header, sizeof header) != 1) {
        int status = 0;
        ::waitpid(pids_[worker], &status, 0);
        pids_.erase(pids_.begin() + static_cast<std::ptrdiff_t>(worker));
        // Not the document's fault: a worker that dies is a bug in Tactus or
        // liblouis (a crash), or the system's (out of memory), never bad input.
        const auto why = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                             : "exit status " + std::to_string(WEXITSTATUS(status));
        return fail(ErrorKind::internal,
                    "translation worker ended unexpectedly (" + why + ") while translating from line " +
                        std::to_string(blocks[i].source_line),
                    document_->source_name);
    }
    if (header & kErrorBit) {
        std::string msg(header & ~kErrorBit, '\0');
        if (read_all(fd, msg.data(), msg.size()) != 1)
            return fail(ErrorKind::internal, "translation worker ended in the middle of an error report",
                        document_->source_name);
        const auto nul = msg.find('\0');
        return fail(msg.substr(nul + 1), msg.substr(0, nul));
    }
    document::BrailleLine cells(header);
    if (read_all(fd, cells.data(), cells.size()) != 1)
        return fail(ErrorKind::internal, "translation worker ended in the middle of a block", document_->source_name);
    const document::Block& b = blocks[i];
    translate::LineBreaks breaks;
    if (document::is_text_kind(b.kind)) {
        breaks.resize(cells.size());
        if (read_all(fd, breaks.data(), breaks.size()) != 1)
            return fail(ErrorKind::internal, "translation worker ended in the middle of a block",
                        document_->source_name);
    }
    translate::TranslatedBlock tb;
    tb.kind = b.kind;
    tb.level = b.level;
    tb.span = std::max(1, b.span);
    tb.source_line = b.source_line;
    if (b.kind == document::BlockKind::braille) tb.lines = b.braille_lines;
    if (b.kind == document::BlockKind::print_page_break) tb.label = std::move(cells);
    else tb.cells = std::move(cells);
    tb.breaks = std::move(breaks);
    return std::optional<translate::TranslatedBlock>(std::move(tb));
}

}  // namespace tactus::pipeline
