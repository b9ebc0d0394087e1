// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli serve: run the queue headless, one runner thread per printer,
// until SIGINT or SIGTERM. Stopping aborts the job in hand on its controller and
// puts it back in the queue; kill -9 is safe too (see docs/spool.md).
#include <atomic>
#include <iostream>
#include <thread>

#include "command.hpp"
#include "link/link.hpp"
#include "platform/termination.hpp"
#include "spool/runner.hpp"
#include "spool_args.hpp"

namespace tactus::cli {
namespace {

struct ServeArgs {
    std::string db;
    std::vector<std::string> printers;
    int max_retries = 5;
    int retry_ms = 2000;
    int poll_ms = 100;
    int reconnect_ms = 30000;
    int fault_wait_ms = 120000;
    int write_retry_ms = 10000;
};

std::atomic<bool> g_serve_stop{false};
extern "C" void on_serve_signal(int) { g_serve_stop.store(true); }

void run_serve(const ServeArgs& a) {
    spool::Spool s = open_spool(a.db, false);
    require(s.check());
    std::vector<std::string> names = a.printers;
    if (names.empty())
        for (const auto& p : require(s.printers())) names.push_back(p.name);
    if (names.empty())
        fail_with(exit_usage, Error{"no printers are set up; add one with `tactus-cli queue printer add`",
                                    s.path().string(), ErrorKind::usage});
    for (const auto& n : names) require(s.printer(n));

    spool::RunnerOptions options;
    options.max_retries = a.max_retries;
    options.retry_backoff = std::chrono::milliseconds(a.retry_ms);
    options.poll = std::chrono::milliseconds(a.poll_ms);
    options.write_retry = std::chrono::milliseconds(a.write_retry_ms);
    options.link.reconnect_deadline = std::chrono::milliseconds(a.reconnect_ms);
    options.link.fault_wait = std::chrono::milliseconds(a.fault_wait_ms);
    const auto link_options = options.link;
    auto connect = [link_options](const spool::PrinterRecord& p) { return spool::open_printer(p, link_options); };

    platform::on_termination(on_serve_signal);
    std::vector<std::unique_ptr<spool::Runner>> runners;
    for (const auto& n : names) {
        auto r = std::make_unique<spool::Runner>(s.path(), n, connect, options);
        require(r->start(), exit_failure);
        runners.push_back(std::move(r));
    }
    std::cerr << "tactus-cli serve: " << s.path().string() << ": serving " << names.size()
              << " printer(s); stop with Ctrl-C\n";
    std::vector<std::thread> threads;
    std::vector<std::optional<Error>> errors(runners.size());
    for (std::size_t i = 0; i < runners.size(); ++i)
        threads.emplace_back([&, i] {
            if (auto r = runners[i]->run(g_serve_stop); !r) {
                errors[i] = r.error();
                g_serve_stop = true;  // the spool is unusable: stop every printer
            }
        });
    for (auto& t : threads) t.join();
    for (auto& r : runners) r->finish();
    for (const auto& e : errors)
        if (e) fail_with(exit_failure, *e);
}

}  // namespace

void add_serve_command(CLI::App& app) {
    auto a = std::make_shared<ServeArgs>();
    auto* cmd = app.add_subcommand("serve", "Run the print queue headless until stopped (Ctrl-C, SIGTERM)");
    add_db_option(*cmd, a->db);
    cmd->add_option("--printer,-p", a->printers, "Serve only these printers (default: all)");
    cmd->add_option("--max-retries", a->max_retries, "Transient failures before a job is paused for the operator")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->add_option("--retry-ms", a->retry_ms, "First retry back-off (doubles per retry)")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->add_option("--poll-ms", a->poll_ms, "How often to look for jobs and operator requests")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd->add_option("--reconnect-ms", a->reconnect_ms, "How long to try reopening a device that went away")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd->add_option("--fault-wait-ms", a->fault_wait_ms, "How long to wait for paper before pausing the job")
        ->capture_default_str()->check(CLI::PositiveNumber);
    cmd->add_option("--write-retry-ms", a->write_retry_ms,
                    "How long a refused write to the spool (disk full) is tried again before the job is "
                    "stopped and paused with that reason, and serve exits 1")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    cmd->callback([a] { run_serve(*a); });
}

}  // namespace tactus::cli
