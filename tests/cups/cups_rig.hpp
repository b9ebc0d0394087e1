// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A real cupsd for end-to-end tests, private to one test: its own
// ServerRoot, spool and logs in a temporary folder, listening on loopback
// only (private_cupsd.sh). Nothing under /etc/cups is read or written. The
// Tactus backend and filter are the built ones; the queue is added with
// lpadmin on a tactus: URI to `tactus-cli sim --pty`, as a system
// administrator would add it on a tactus: URI to a cable.
//
// Run as root (CI), cupsd runs the backend and filter as `lp`, as the
// packaged CUPS does, and jobs are sent as a second, unprivileged user made
// for the test (`tactus-teacher`). Run as anyone else, cupsd cannot switch
// users: everything runs as that user, and jobs are sent as that user.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "e2e_rig.hpp"

namespace tactus::cups::test {

using spool::test::E2E;
using spool::test::Process;
using spool::test::PtySim;

inline const std::string kScript = TACTUS_CUPS_SCRIPT;
inline const std::string kTeacher = "tactus-teacher";

inline bool have_cupsd() { return spool::test::run({"/bin/sh", "-c", "command -v cupsd lpadmin lp lpstat"}).first == 0; }
inline bool is_root() { return geteuid() == 0; }

// A Markdown lesson long enough for several sheets on the interpoint A4 default profile.
inline std::string lesson(int paragraphs) {
    std::string md = "# Braille for everyone\n\n";
    for (int i = 0; i < paragraphs; ++i)
        md += "Paragraph " + std::to_string(i + 1) +
              ": the school's one embosser is shared through CUPS, so every teacher can print "
              "from their own desk while the spool keeps each sheet exactly once.\n\n";
    return md;
}

class CupsRig {
public:
    E2E e;  // the spool database the CUPS backend and filter use, and its helpers
    std::filesystem::path cups_dir = e.dir / "cups";

    CupsRig() {
        // lp (the backend) creates the spool database and its WAL beside it.
        std::filesystem::permissions(e.dir.path(), std::filesystem::perms::all);
        const auto [code, out] = spool::test::run(
            {"/bin/bash", kScript, "start", cups_dir.string(), TACTUS_CUPS_BACKEND, TACTUS_CUPS_FILTER,
             TACTUS_CUPS_PPD, TACTUS_CUPS_TYPES, "TACTUS_SPOOL_DB=" + e.db.string()});
        started_ = code == 0;
        std::size_t pos = 0;
        while (pos < out.size()) {
            const auto nl = out.find('\n', pos);
            const auto line = out.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
            if (line.find('=') != std::string::npos) env_.push_back(line);
            if (nl == std::string::npos) break;
            pos = nl + 1;
        }
        if (is_root()) (void)spool::test::run({"/bin/sh", "-c", "id " + kTeacher + " >/dev/null 2>&1 || useradd -M -s /usr/sbin/nologin " + kTeacher});
    }
    ~CupsRig() { (void)spool::test::run({"/bin/bash", kScript, "stop", cups_dir.string()}); }
    CupsRig(const CupsRig&) = delete;
    CupsRig& operator=(const CupsRig&) = delete;

    [[nodiscard]] bool started() const { return started_; }
    [[nodiscard]] std::string error_log() const { return spool::test::read_text((cups_dir / "log/error_log").string()); }

    // The command line that runs `args` with the private server's
    // environment; as the teacher when `as_teacher` and we are root.
    [[nodiscard]] std::vector<std::string> command(const std::vector<std::string>& args, bool as_teacher = false) const {
        std::vector<std::string> cmd;
        if (as_teacher && is_root()) cmd = {"/usr/sbin/runuser", "-u", kTeacher, "--"};
        cmd.push_back("/usr/bin/env");
        cmd.insert(cmd.end(), env_.begin(), env_.end());
        cmd.insert(cmd.end(), args.begin(), args.end());
        return cmd;
    }

    // host:port of the private cupsd (its CUPS_SERVER), and a queue's IPP address there.
    [[nodiscard]] std::string server() const {
        for (const auto& kv : env_)
            if (kv.starts_with("CUPS_SERVER=")) return kv.substr(12);
        return {};
    }
    [[nodiscard]] std::string queue_uri(const std::string& name) const { return "ipp://" + server() + "/printers/" + name; }

    // Points this process's libcups at the private server (CUPS_SERVER and
    // friends), for a client that runs in the test itself (the app).
    void use_in_this_process() const {
        for (const auto& kv : env_) {
            const auto eq = kv.find('=');
            ::setenv(kv.substr(0, eq).c_str(), kv.substr(eq + 1).c_str(), 1);
        }
    }

    // A lesson of `paragraphs` paragraphs in the test folder, readable by
    // every user (the teacher sends it).
    std::filesystem::path lesson_file(const std::string& name, int paragraphs) {
        const auto doc = e.dir / name;
        std::ofstream(doc) << lesson(paragraphs);
        std::filesystem::permissions(
            doc, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                     std::filesystem::perms::group_read | std::filesystem::perms::others_read);
        return doc;
    }

    // The newest spool job so far (0: none), so a test finds the one its job makes.
    spool::JobId last_spool_job() {
        spool::JobId last = 0;
        if (std::filesystem::exists(e.db))
            if (auto s = spool::Spool::open(e.db, {.create = false}))
                if (auto jobs = s->jobs(true); jobs)
                    for (const auto& j : *jobs) last = std::max(last, j.id);
        return last;
    }

    // A CUPS client command with the private server's environment; as the
    // teacher when `as_teacher` and we are root.
    std::pair<int, std::string> client(const std::vector<std::string>& args, bool as_teacher = false) {
        const auto cmd = command(args, as_teacher);
        // stderr too: lp and lpadmin explain failures there.
        std::vector<std::string> sh{"/bin/sh", "-c", ""};
        for (const auto& a : cmd) sh[2] += "'" + a + "' ";
        sh[2] += "2>&1";
        return spool::test::run(sh);
    }

    // The queue: lpadmin on the simulator's pty; the pty is opened by lp.
    bool add_queue(const PtySim& sim, const std::string& name = "Embosser") {
        if (sim.path().empty()) {
            ADD_FAILURE() << "tactus-cli sim --pty printed no pty path (machine overloaded?)";
            return false;
        }
        if (is_root()) ::chmod(sim.path().c_str(), 0666);
        const auto [code, out] =
            client({"lpadmin", "-p", name, "-E", "-v", "tactus:" + sim.device(), "-P", TACTUS_CUPS_PPD});
        return code == 0;
    }

    // `lp` as the teacher; the CUPS job number (0 if lp failed, `out` says why).
    int lp(const std::filesystem::path& file, const std::vector<std::string>& options, std::string& out) {
        std::filesystem::permissions(file, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                                               std::filesystem::perms::group_read | std::filesystem::perms::others_read);
        std::vector<std::string> args{"lp", "-d", "Embosser"};
        for (const auto& o : options) args.push_back(o);
        args.push_back(file.string());
        int code = 0;
        std::tie(code, out) = client(args, true);
        std::smatch m;
        if (code != 0 || !std::regex_search(out, m, std::regex("request id is Embosser-([0-9]+)"))) return 0;
        return std::stoi(m[1]);
    }

    // CUPS's view of job `id`: pending/processing jobs are listed by `lpstat -o`.
    bool cups_job_active(int id) {
        const auto out = client({"lpstat", "-o", "Embosser"}).second;
        return out.find("Embosser-" + std::to_string(id) + " ") != std::string::npos;
    }
    bool wait_cups_job_gone(int id, std::chrono::seconds timeout = std::chrono::seconds(90)) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            if (!cups_job_active(id)) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        return false;
    }
    std::string printer_status() { return client({"lpstat", "-l", "-p", "Embosser"}).second; }

    // The newest spool job (the backend made it for the last CUPS job sent;
    // 0 if none within `timeout`), newer than `after`.
    spool::JobId newest_spool_job(spool::JobId after, std::chrono::seconds timeout = std::chrono::seconds(60)) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            if (std::filesystem::exists(e.db))
                if (auto s = spool::Spool::open(e.db, {.create = false}))
                    if (auto jobs = s->jobs(true); jobs)
                        for (const auto& j : *jobs)
                            if (j.id > after) return j.id;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return 0;
    }

    // The spool job the backend made for the (one) CUPS job sent so far.
    spool::JobId spool_job(std::chrono::seconds timeout = std::chrono::seconds(60)) {
        const auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            if (std::filesystem::exists(e.db))
                if (auto s = spool::Spool::open(e.db, {.create = false}))
                    if (auto jobs = s->jobs(true); jobs && !jobs->empty()) return jobs->front().id;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return 0;
    }

    void kill_cupsd() { (void)spool::test::run({"/bin/bash", kScript, "kill", cups_dir.string()}); }
    bool restart_cupsd() { return spool::test::run({"/bin/bash", kScript, "restart", cups_dir.string()}).first == 0; }

private:
    bool started_ = false;
    std::vector<std::string> env_;
};

}  // namespace tactus::cups::test
