// SPDX-License-Identifier: GPL-3.0-or-later
// Big inputs stay linear: one paragraph of 1, 4 and 16 MB (a text
// file that is a single line), laid out to pages. Time per MB must stay flat
// as the size grows; peak resident size is printed too. Two kinds of line:
// English words (what a converted e-book with lost line ends looks like) and
// one word without any space (the worst case: every line is a divided word).
// Usage: bench_single_line [words|no-space] [MB...]   (default both kinds, 1 4 16)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "pipeline/pipeline.hpp"

using namespace tactus;
using namespace tactus::document;
using namespace tactus::pipeline;
using Clock = std::chrono::steady_clock;

namespace {

std::string words_line(std::size_t bytes) {
    static const char* words[] = {"the", "quick", "brown", "fox", "jumps", "over", "lazy", "dog",
                                  "knowledge", "braille", "and", "of", "with", "children", "because",
                                  "Reading", "42", "well-known"};
    std::mt19937 rng(7);
    std::string s;
    s.reserve(bytes + 16);
    while (s.size() < bytes) {
        s += words[std::uniform_int_distribution<std::size_t>(0, std::size(words) - 1)(rng)];
        s += ' ';
    }
    s.resize(bytes);
    return s;
}

std::string no_space_line(std::size_t bytes) {
    std::mt19937 rng(11);
    std::string s(bytes, 'a');
    for (auto& c : s) c = static_cast<char>('a' + std::uniform_int_distribution<int>(0, 25)(rng));
    return s;
}

// Runs in a child so each size's peak resident size is its own.
void measure(const char* kind, std::size_t mb, bool words) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        Document doc;
        Block b;
        b.kind = BlockKind::paragraph;
        b.spans.push_back(Span{words ? words_line(mb << 20) : no_space_line(mb << 20), emphasis_none});
        doc.blocks.push_back(std::move(b));
        doc.source_name = "single-line.txt";
        PipelineOptions o;
        o.tables = "en-ueb-g2.ctb";
        const auto t0 = Clock::now();
        auto paged = lay_out(doc, o);
        const double s = std::chrono::duration<double>(Clock::now() - t0).count();
        if (!paged) {
            std::fprintf(stderr, "%s\n", paged.error().to_string().c_str());
            ::_exit(1);
        }
        rusage ru{};
        ::getrusage(RUSAGE_SELF, &ru);
        std::printf("%-9s %4zu MB: %7.2f s  %5.2f s/MB  %7zu pages  peak %6.0f MB\n", kind, mb, s,
                    s / static_cast<double>(mb), paged->pages.size(), static_cast<double>(ru.ru_maxrss) / 1024.0);
        std::fflush(stdout);
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes;
    bool words = true, no_space = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "words") no_space = false;
        else if (a == "no-space") words = false;
        else sizes.push_back(static_cast<std::size_t>(std::atoi(argv[i])));
    }
    if (sizes.empty()) sizes = {1, 4, 16};
    if (words)
        for (auto mb : sizes) measure("words", mb, true);
    if (no_space)
        for (auto mb : sizes) measure("no-space", mb, false);
    return 0;
}
