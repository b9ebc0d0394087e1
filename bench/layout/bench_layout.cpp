// SPDX-License-Identifier: GPL-3.0-or-later
// Lays out a large real book (the KJV from Debian's bible-kjv) into interpoint
// BRF and PEF, and times `lou_translate` on the same text in the same run.
// Usage: bench_layout BOOK.txt [TABLE]
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "export/export.hpp"
#include "pipeline/pipeline.hpp"

using namespace tactus;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Runs lou_translate with the book on stdin and output discarded; returns seconds.
double time_lou_translate(const std::string& book, const std::string& table) {
    const auto t0 = Clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int in = ::open(book.c_str(), O_RDONLY);
        const int out = ::open("/dev/null", O_WRONLY);
        ::dup2(in, 0);
        ::dup2(out, 1);
        const std::string tables = "unicode.dis," + table;
        ::execlp("lou_translate", "lou_translate", tables.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "lou_translate failed (is liblouis-bin installed?)\n");
        std::exit(1);
    }
    return seconds_since(t0);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s BOOK.txt [TABLE]\n", argv[0]);
        return 2;
    }
    const std::string book = argv[1];
    const std::string table = argc > 2 ? argv[2] : "en-ueb-g2.ctb";
    const auto input_bytes = std::filesystem::file_size(book);

    const double lou = time_lou_translate(book, table);

    pipeline::PipelineOptions options;
    options.tables = table;
    options.layout.geometry.interpoint = true;
    const auto t0 = Clock::now();
    auto doc = pipeline::lay_out_file(book, options);
    if (!doc) {
        std::fprintf(stderr, "%s\n", doc.error().to_string().c_str());
        return 1;
    }
    const double layout_s = seconds_since(t0);
    const auto out_dir = std::filesystem::temp_directory_path();
    const auto brf_path = out_dir / "tactus-bench-kjv.brf";
    const auto pef_path = out_dir / "tactus-bench-kjv.pef";
    auto brf = exporter::export_to_file(*doc, exporter::ExportFormat::brf, {}, brf_path);
    auto pef = exporter::export_to_file(*doc, exporter::ExportFormat::pef, {}, pef_path);
    const double total = seconds_since(t0);
    if (!brf || !pef) {
        std::fprintf(stderr, "%s\n", (brf ? pef : brf).error().to_string().c_str());
        return 1;
    }

    rusage self{};
    ::getrusage(RUSAGE_SELF, &self);
    const double peak_mb = static_cast<double>(self.ru_maxrss) / 1024.0;
    const double input_mb = static_cast<double>(input_bytes) / (1024.0 * 1024.0);

    std::printf("book:               %s (%.2f MB), table %s\n", book.c_str(), input_mb, table.c_str());
    std::printf("pages / sheets:     %zu / %zu (interpoint 27x24)\n", doc->pages.size(), doc->sheet_count());
    std::printf("output:             BRF %.2f MB, PEF %.2f MB\n",
                static_cast<double>(std::filesystem::file_size(brf_path)) / 1048576.0,
                static_cast<double>(std::filesystem::file_size(pef_path)) / 1048576.0);
    std::filesystem::remove(brf_path);
    std::filesystem::remove(pef_path);
    std::printf("tactus pipeline:    %.3f s (import+translate+layout %.3f s, export BRF+PEF %.3f s)\n",
                total, layout_s, total - layout_s);
    std::printf("lou_translate:      %.3f s\n", lou);
    std::printf("ratio tactus/lou:   %.3f (goal <= 1.0)\n", total / lou);
    std::printf("peak memory:        %.1f MB = %.1fx input (goal < 10x)\n", peak_mb, peak_mb / input_mb);
    return 0;
}
