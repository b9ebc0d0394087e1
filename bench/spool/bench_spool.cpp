// SPDX-License-Identifier: GPL-3.0-or-later
// Spool benchmark. (1) Queue operations per second on a real database file
// holding 10,000 jobs (WAL, synchronous=FULL: every operation is a durable
// commit). (2) Latency from `tactus-cli emboss --queue` to the first frame on
// the wire, with `tactus-cli serve` idle and a pseudo-terminal standing in for
// the printer (this program reads the pty master, so "on the wire" is literal).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "layout/page.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"

namespace {

using namespace tactus;
using namespace tactus::spool;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

template <typename T>
T must(Result<T> r, const char* what) {
    if (!r) {
        std::cerr << what << ": " << r.error().to_string() << '\n';
        std::exit(1);
    }
    if constexpr (!std::is_void_v<T>) return std::move(*r);
}

layout::PagedDocument book(std::size_t pages) {
    layout::PagedDocument doc;
    for (std::size_t p = 0; p < pages; ++p) {
        layout::Page page;
        page.braille_number = static_cast<int>(p + 1);
        for (int l = 0; l < 24; ++l) page.lines.push_back(document::BrailleLine(27, document::Cell{static_cast<std::uint8_t>(1 + (p + static_cast<std::size_t>(l)) % 63)}));
        doc.pages.push_back(std::move(page));
    }
    return doc;
}

void report(const char* name, std::size_t n, double seconds) {
    std::printf("  %-40s %8zu ops %9.3f s %10.0f ops/s %8.3f ms/op\n", name, n, seconds, static_cast<double>(n) / seconds,
                1000 * seconds / static_cast<double>(n));
}

void queue_operations(const std::filesystem::path& dir) {
    const auto db = dir / "bench.db";
    Spool s = must(Spool::open(db), "open");
    must(s.add_printer("lab", "pty:/dev/null", "{}"), "printer");
    const layout::PagedDocument doc = book(8);  // a 4-sheet job: ~20 KB snapshot
    JobSubmission job;
    job.printer = "lab";
    job.title = "bench";
    job.document = to_snapshot(doc);
    job.sheets_per_copy = doc.sheet_count();
    job.user = "bench";
    std::printf("queue operations, %s (snapshot %zu bytes per job)\n", db.c_str(), job.document.size());

    constexpr std::size_t kJobs = 10000;
    auto t = Clock::now();
    std::vector<JobId> ids;
    for (std::size_t i = 0; i < kJobs; ++i) {
        job.priority = static_cast<int>(i % 5);
        ids.push_back(must(s.submit(job), "submit"));
    }
    report("submit (10,000 jobs into the queue)", kJobs, since(t));
    std::printf("  database size: %.1f MB\n", static_cast<double>(std::filesystem::file_size(db)) / 1e6);

    constexpr std::size_t kOps = 2000;
    t = Clock::now();
    for (std::size_t i = 0; i < kOps; ++i) must(s.job(ids[(i * 7919) % kJobs]), "job");
    report("show one job (10,000 in the queue)", kOps, since(t));

    t = Clock::now();
    for (std::size_t i = 0; i < kOps; ++i) {
        const auto id = ids[(i * 7919) % kJobs];
        must(s.act(id, Action::pause), "pause");
        must(s.act(id, Action::resume), "resume");
    }
    report("pause + resume (2 durable commits)", 2 * kOps, since(t));

    t = Clock::now();
    constexpr std::size_t kLists = 20;
    std::size_t listed = 0;
    for (std::size_t i = 0; i < kLists; ++i) listed += must(s.jobs(false), "list").size();
    report("list the whole queue (10,000 rows)", kLists, since(t));
    (void)listed;

    const auto printer = must(s.printer("lab"), "printer").id;
    const std::string token = "bench:1";
    must(s.claim_printer(printer, token), "claim printer");
    t = Clock::now();
    constexpr std::size_t kClaims = 500;
    std::vector<JobId> claimed;
    for (std::size_t i = 0; i < kClaims; ++i) claimed.push_back(must(s.claim_next(printer, token, now_seconds()), "claim")->id);
    report("claim next job (priority order)", kClaims, since(t));

    must(s.set_sheet_passes(claimed[0], std::vector<std::size_t>(4, 250)), "passes");
    t = Clock::now();
    std::size_t passes = 0;
    for (std::size_t sheet = 1; sheet <= 4; ++sheet)
        for (std::size_t p = 1; p <= 250; ++p, ++passes) must(s.record_passes(claimed[0], sheet, p), "record");
    report("record an executed pass (durable)", passes, since(t));

    t = Clock::now();
    for (std::size_t i = 0; i < kOps; ++i) must(s.act(ids[kJobs - 1 - i], Action::cancel), "cancel");
    report("cancel a queued job", kOps, since(t));

    t = Clock::now();
    for (std::size_t i = 0; i < 50; ++i) must(s.events(std::nullopt, 200), "events");
    report("history (newest 200 of ~24,000 events)", 50, since(t));
}

struct Child {
    pid_t pid = -1;
    ~Child() {
        if (pid > 0) {
            kill(pid, SIGTERM);
            waitpid(pid, nullptr, 0);
        }
    }
};

pid_t spawn(const std::vector<std::string>& args, bool quiet) {
    const pid_t pid = fork();
    if (pid == 0) {
        if (quiet) {
            const int null = open("/dev/null", O_WRONLY);
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
        }
        std::vector<char*> argv;
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    return pid;
}

void first_frame(const std::filesystem::path& dir) {
    const std::string cli = TACTUS_CLI;
    const int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
        std::cerr << "no pseudo-terminal\n";
        return;
    }
    const std::string slave = ptsname(master);
    const auto db = (dir / "latency.db").string();
    const auto doc = (dir / "doc.txt").string();
    std::ofstream(doc) << "A teacher queues a book and walks away.\n";
    if (std::system((cli + " queue --db " + db + " printer add lab --device pty:" + slave + " > /dev/null").c_str()) != 0)
        return;
    Child serve;
    serve.pid = spawn({cli, "serve", "--db", db, "--poll-ms", "100"}, true);
    usleep(500000);  // serve is up and idle
    std::printf("latency from `emboss --queue` to the first frame on the wire (serve idle, --poll-ms 100)\n");
    constexpr int kRuns = 5;
    for (int run = 0; run < kRuns; ++run) {
        // Drain whatever the previous run left on the line.
        char buf[4096];
        for (pollfd p{master, POLLIN, 0}; poll(&p, 1, 0) > 0 && read(master, buf, sizeof buf) > 0;) {}
        const auto t0 = Clock::now();
        const pid_t emboss = spawn({cli, "emboss", "--queue", doc, "--db", db}, true);
        int status = 0;
        waitpid(emboss, &status, 0);
        const double queued = since(t0);
        pollfd p{master, POLLIN, 0};
        if (poll(&p, 1, 10000) <= 0) {
            std::printf("  run %d: no frame within 10 s\n", run + 1);
            continue;
        }
        const double first = since(t0);
        std::printf("  run %d: emboss --queue returned after %6.1f ms; first frame on the wire at %6.1f ms\n", run + 1,
                    1000 * queued, 1000 * first);
        // Let the job go: cancel it so the next run starts from an idle printer.
        std::system((cli + " queue --db " + db + " cancel " + std::to_string(run + 1) + " > /dev/null 2>&1").c_str());
        usleep(300000);
    }
    close(master);
}

}  // namespace

int main() {
    const auto dir = std::filesystem::temp_directory_path() / ("tactus-bench-spool-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    queue_operations(dir);
    first_frame(dir);
    std::filesystem::remove_all(dir);
}
