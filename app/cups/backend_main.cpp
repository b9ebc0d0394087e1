// SPDX-License-Identifier: GPL-3.0-or-later
// The CUPS backend `tactus` (backend(7)); installed as
// /usr/lib/cups/backend/tactus, mode 0755, so cupsd runs it as `lp`, never
// as root: it needs no more than the embosser's cable (group lp through the
// udev rule, see docs/cups.md) and the spool folder (owned by lp).
//   tactus                                   discovery: one line per cable
//   tactus job user title copies options [file]   emboss one job
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <string>

#include "backend_job.hpp"
#include "cups_options.hpp"
#include "discovery.hpp"
#include "platform/console.hpp"
#include "platform/process_info.hpp"
#include "platform/termination.hpp"

namespace {

std::atomic<bool> g_terminate{false};
extern "C" void on_terminate(int) { g_terminate.store(true); }

std::mutex g_say_mutex;
void say(const std::string& line) {
    std::lock_guard lock(g_say_mutex);
    // cupsd reads stderr line by line; one write per line so two threads'
    // lines never interleave. A dead cupsd (EPIPE) is ignored: the job goes on.
    const std::string text = line + "\n";
    tactus::platform::write_stderr(text);
}

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

int discovery() {
    std::vector<std::string> warnings;
    for (const auto& port : tactus::cups::list_all_ports(warnings))
        std::cout << tactus::cups::discovery_line(port) << '\n';
    for (const auto& w : warnings) say("DEBUG: " + w);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace tactus::cups;
    // cupsd may die while we emboss; the sheet in the machine must still be
    // finished and recorded, so a closed stderr pipe is not fatal.
    tactus::platform::ignore_broken_pipe();
    if (argc == 1) return discovery();
    if (argc < 6 || argc > 7) {
        std::cerr << "Usage: tactus job-id user title copies options [file]\n"
                     "       tactus            (list the cables an embosser may be on)\n";
        return backend_failed;
    }
    if (tactus::platform::running_as_root()) {
        say("ERROR: the tactus backend does not run as root; install it with mode 0755 so CUPS runs it as lp");
        return backend_stop;
    }
    BackendJob job;
    job.cups_job_id = argv[1];
    job.user = argv[2];
    job.title = argv[3];
    try {
        job.copies = std::stoul(argv[4]);
    } catch (const std::exception&) {
        say("ERROR: copies '" + std::string(argv[4]) + "' is not a number");
        return backend_cancel;
    }
    if (job.copies == 0) job.copies = 1;
    job.options = parse_cups_options(argv[5]);
    if (argc == 7) job.file = argv[6];
    job.device_uri = env("DEVICE_URI");
    job.queue = env("PRINTER");

    tactus::platform::on_termination_interrupting(on_terminate);
    return run_backend_job(job, BackendTuning{}, say, g_terminate);
}
