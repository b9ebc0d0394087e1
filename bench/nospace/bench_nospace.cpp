// SPDX-License-Identifier: GPL-3.0-or-later
// Text without spaces. One paragraph of 1 and 4 MB
// with no space at all (every line a divided word, or for Chinese a run of
// characters), laid out to pages, against the same characters with a space
// every few characters (spaced text of the same size), measured in the same
// run. Prints CPU seconds per MB of each (steadier than wall time on a shared
// machine; wall time beside it), the ratio unspaced / spaced, and peak memory.
// Kinds: letters (en-ueb-g1), base64 (base64-like ASCII, en-ueb-g1), han
// (traditional Chinese characters, zh-tw).
// Usage: bench_nospace [letters|base64|han ...] [MB ...]   (default: all kinds, 1 4)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "common/utf8.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::pipeline;
using Clock = std::chrono::steady_clock;

namespace {

struct Kind {
    const char* name;
    const char* table;
    std::u32string alphabet;
};

const Kind kKinds[] = {
    {"letters", "en-ueb-g1.ctb", U"abcdefghijklmnopqrstuvwxyz"},
    {"base64", "en-ueb-g1.ctb", U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/"},
    // Characters of resources/samples/chinese-tw.txt: all known to zh-tw.ctb.
    {"han", "zh-tw.ctb",
     U"點字是一種讓視障者用手指閱讀的文每個方由六組成分左右兩行三老師可以把課翻譯再印表機出來雙面刷節省紙張正和背互相錯開不會壓壞"},
};

// About `bytes` of UTF-8 (whole characters) drawn from the kind's characters; with `spaced`, a space
// after every 1 to 8 characters (a word), so both texts have the same size.
std::string text(const Kind& k, std::size_t bytes, bool spaced) {
    std::mt19937 rng(11);
    std::u32string s;
    std::string out;
    out.reserve(bytes + 8);
    std::size_t word = 0, next_space = 1 + rng() % 8;
    while (out.size() < bytes) {
        s.assign(1, k.alphabet[rng() % k.alphabet.size()]);
        out += utf32_to_utf8(s);
        if (spaced && ++word == next_space) {
            out += ' ';
            word = 0;
            next_space = 1 + rng() % 8;
        }
    }
    return out;
}

struct Figures {
    double cpu = 0, wall = 0, peak_mb = 0;
    std::size_t pages = 0;
    bool ok = false;
};

// One layout in a child process, so its peak resident size and CPU time are its own.
Figures measure(const Kind& k, std::size_t mb, bool spaced) {
    int fd[2];
    if (::pipe(fd) != 0) return {};
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fd[0]);
        Document doc;
        Block b;
        b.kind = BlockKind::paragraph;
        b.spans.push_back(Span{text(k, mb << 20, spaced), emphasis_none});
        doc.blocks.push_back(std::move(b));
        doc.source_name = "nospace.txt";
        PipelineOptions o;
        o.tables = k.table;
        rusage before{};
        ::getrusage(RUSAGE_SELF, &before);
        const auto t0 = Clock::now();
        auto paged = lay_out(doc, o);
        Figures f;
        f.wall = std::chrono::duration<double>(Clock::now() - t0).count();
        rusage after{};
        ::getrusage(RUSAGE_SELF, &after);
        const auto secs = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
        f.cpu = secs(after.ru_utime) + secs(after.ru_stime) - secs(before.ru_utime) - secs(before.ru_stime);
        f.peak_mb = static_cast<double>(after.ru_maxrss) / 1024.0;
        f.ok = static_cast<bool>(paged);
        if (!paged) std::fprintf(stderr, "%s\n", paged.error().to_string().c_str());
        else f.pages = paged->pages.size();
        const auto n = ::write(fd[1], &f, sizeof f);
        ::_exit(n == sizeof f ? 0 : 1);
    }
    ::close(fd[1]);
    Figures f;
    if (::read(fd[0], &f, sizeof f) != sizeof f) f.ok = false;
    ::close(fd[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<const Kind*> kinds;
    std::vector<std::size_t> sizes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        bool known = false;
        for (const auto& k : kKinds)
            if (a == k.name) {
                kinds.push_back(&k);
                known = true;
            }
        if (!known) sizes.push_back(static_cast<std::size_t>(std::atoi(argv[i])));
    }
    if (kinds.empty())
        for (const auto& k : kKinds) kinds.push_back(&k);
    if (sizes.empty()) sizes = {1, 4};
    std::printf("%-8s %-14s %5s  %-34s %-34s %s\n", "kind", "table", "size", "unspaced: CPU/MB (wall/MB) peak",
                "spaced: CPU/MB (wall/MB) peak", "ratio (CPU)");
    for (const auto* k : kinds) {
        for (auto mb : sizes) {
            const auto u = measure(*k, mb, false);
            const auto s = measure(*k, mb, true);
            if (!u.ok || !s.ok) {
                std::printf("%-8s %-14s %2zu MB  failed\n", k->name, k->table, mb);
                continue;
            }
            const double m = static_cast<double>(mb);
            std::printf("%-8s %-14s %2zu MB  %6.2f s (%6.2f s) %5.0f MB        %6.2f s (%6.2f s) %5.0f MB        %5.2f\n",
                        k->name, k->table, mb, u.cpu / m, u.wall / m, u.peak_mb, s.cpu / m, s.wall / m, s.peak_mb,
                        u.cpu / s.cpu);
            std::fflush(stdout);
        }
    }
    return 0;
}
