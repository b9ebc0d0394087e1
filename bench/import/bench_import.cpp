// SPDX-License-Identifier: GPL-3.0-or-later
// Imports a generated 100 MB plain-text file (UTF-8, then Windows-1252 so the
// ICU conversion path runs) and prints time, throughput and peak memory as a
// multiple of the input size. Each case runs in its own child process so the
// peak resident size belongs to that case alone.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "import/import.hpp"

namespace {

constexpr std::size_t target_bytes = std::size_t{100} << 20;

// Paragraphs of five wrapped lines, like a novel saved as text.
std::string make_text(bool latin1) {
    const std::string e_acute = latin1 ? "\xE9" : "\xC3\xA9";
    const std::string line = "The caf" + e_acute +
                             " on the corner served tea to the children after school, "
                             "and they read aloud together.\n";
    std::string text;
    text.reserve(target_bytes + 1024);
    while (text.size() < target_bytes) {
        for (int i = 0; i < 5; ++i) text += line;
        text += '\n';
    }
    return text;
}

long peak_rss_kib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

void run_case(const char* label, bool latin1) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("tactus_bench_import_" + std::to_string(::getpid()) + ".txt");
    std::size_t size = 0;
    {
        const auto text = make_text(latin1);
        size = text.size();
        std::ofstream(path, std::ios::binary).write(text.data(), static_cast<std::streamsize>(size));
    }
    const long before = peak_rss_kib();
    const auto start = std::chrono::steady_clock::now();
    const auto doc = tactus::import::import_file(path);
    const auto seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::filesystem::remove(path);
    if (!doc) {
        std::printf("%s: FAILED %s\n", label, doc.error().to_string().c_str());
        return;
    }
    const double mib = static_cast<double>(size) / (1 << 20);
    const long peak = peak_rss_kib();
    std::printf("%-14s %7.1f MiB  %6.2f s  %7.1f MiB/s  %zu blocks  encoding %s\n", label, mib,
                seconds, mib / seconds, doc->blocks.size(), doc->encoding.c_str());
    std::printf("%-14s peak RSS %.0f MiB = %.2f x input (generator peak before import %.0f MiB)\n",
                "", static_cast<double>(peak) / 1024, static_cast<double>(peak) / 1024 / mib,
                static_cast<double>(before) / 1024);
}

}  // namespace

int main() {
    for (const auto& [label, latin1] : {std::pair{"utf-8", false}, std::pair{"windows-1252", true}}) {
        std::fflush(stdout);
        const pid_t child = fork();
        if (child == 0) {
            run_case(label, latin1);
            std::fflush(stdout);
            _exit(0);
        }
        int status = 0;
        waitpid(child, &status, 0);
    }
    return 0;
}
