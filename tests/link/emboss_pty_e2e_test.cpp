// SPDX-License-Identifier: GPL-3.0-or-later
// End to end over a real pseudo-terminal: `tactus-cli sim --pty` in one process,
// `tactus-cli emboss --device pty:...` in another, and the simulator's strike
// log compared with the plan dot for dot, with line faults injected.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "controller/sim_controller.hpp"
#include "plan/plan_file.hpp"
#include "../common/test_plans.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

struct Proc {
    pid_t pid = -1;
    int out = -1;  // its stdout
};

Proc spawn(const std::vector<std::string>& argv, bool capture_stdout, bool merge_stderr = false) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        if (capture_stdout) dup2(fds[1], STDOUT_FILENO);
        if (merge_stderr) dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    close(fds[1]);
    return {pid, fds[0]};
}

std::string read_line(int fd) {
    std::string line;
    char c;
    while (read(fd, &c, 1) == 1 && c != '\n') line.push_back(c);
    return line;
}

std::string read_all(int fd) {
    std::string s;
    char buf[4096];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) > 0) s.append(buf, static_cast<std::size_t>(n));
    return s;
}

int wait_exit(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

struct Result {
    int exit_code = -1;
    std::string output;
    std::vector<controller::LoggedStrike> log;
};

class PtyEndToEnd : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("tactus-e2e-" + std::to_string(getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
        plan_ = test::make_plan(2, 6, 14, 11);
        std::ofstream(dir_ / "plan.json") << plan::plan_to_json(plan_).dump();
    }
    void TearDown() override { fs::remove_all(dir_); }

    Result run(std::vector<std::string> sim_faults, const std::string& baud = "115200") {
        std::vector<std::string> sim{TACTUS_CLI, "sim", "--pty", "--baud", baud, "--time-scale", "40",
                                     "--strike-log", (dir_ / "strikes.jsonl").string()};
        sim.insert(sim.end(), sim_faults.begin(), sim_faults.end());
        const Proc server = spawn(sim, true);
        const std::string pty = read_line(server.out);
        EXPECT_EQ(pty.rfind("/dev/pts/", 0), 0U) << pty;
        const Proc client = spawn({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(),
                                   "--device", "pty:" + pty + "?baud=" + baud},
                                  true);
        Result r;
        r.output = read_all(client.out);
        r.exit_code = wait_exit(client.pid);
        kill(server.pid, SIGTERM);
        wait_exit(server.pid);
        close(server.out);
        close(client.out);
        std::ifstream in(dir_ / "strikes.jsonl");
        std::string line;
        while (std::getline(in, line)) {
            const auto j = nlohmann::json::parse(line);
            controller::LoggedStrike s;
            s.sheet = j["sheet"];
            s.side = j["side"] == "front" ? plan::Side::front : plan::Side::back;
            s.hammer = j["hammer"] == "convex" ? plan::Hammer::convex : plan::Hammer::concave;
            s.carriage_step = j["carriage_step"];
            s.feed_step = j["feed_step"];
            r.log.push_back(s);
        }
        return r;
    }

    fs::path dir_;
    plan::JobPlan plan_;
};

TEST_F(PtyEndToEnd, CleanLine) {
    const auto r = run({});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
    EXPECT_NE(r.output.find("pass 12/12 executed"), std::string::npos) << r.output;
}

TEST_F(PtyEndToEnd, NoisyLine) {
    const auto r = run({"--noise", "0.001", "--seed", "3"}, "57600");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
}

TEST_F(PtyEndToEnd, DisconnectMidJob) {
    const auto r = run({"--disconnect-at", "0.25", "--disconnect-for", "3.5"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
}

TEST_F(PtyEndToEnd, ControllerResetMidSheet) {
    const auto r = run({"--reset-at-strike", "23"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.log, controller::planned_strikes(plan_));
    EXPECT_NE(r.output.find("restarted"), std::string::npos) << r.output;
}

TEST_F(PtyEndToEnd, PowerLossFailsWithResumeHint) {
    const auto r = run({"--power-loss-at-strike", "60"});
    EXPECT_EQ(r.exit_code, 1);
    ASSERT_GE(r.log.size(), 60U);
    const auto planned = controller::planned_strikes(plan_);
    EXPECT_TRUE(std::equal(r.log.begin(), r.log.begin() + 60, planned.begin()));
}

TEST_F(PtyEndToEnd, AbsentDeviceGivesTheDocumentedError) {
    for (const std::string dev : {"pty:/dev/pts/999999", "serial:/dev/ttyTACTUS-NONE", "lpt:/dev/parport9",
                                  "hid:10c4:ea80:NOPE"}) {
        const Proc p = spawn({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device", dev},
                             true, true);
        const auto out = read_all(p.out);
        close(p.out);
        EXPECT_EQ(wait_exit(p.pid), 4) << dev << ": " << out;  // exit_device
        EXPECT_NE(out.find("no such device"), std::string::npos) << dev << ": " << out;
    }
}

TEST_F(PtyEndToEnd, DryRunPrintsTheByteCount) {
    const Proc p = spawn({TACTUS_CLI, "emboss", "--dry-run", "--plan", (dir_ / "plan.json").string()}, true);
    const auto out = read_all(p.out);
    close(p.out);
    EXPECT_EQ(wait_exit(p.pid), 0);
    EXPECT_NE(out.find(" bytes of job stream in "), std::string::npos) << out;
}

TEST_F(PtyEndToEnd, EmbossOnTheInProcessSimulator) {
    const Proc p = spawn({TACTUS_CLI, "emboss", "--plan", (dir_ / "plan.json").string(), "--device", "sim"}, true);
    const auto out = read_all(p.out);
    close(p.out);
    EXPECT_EQ(wait_exit(p.pid), 0) << out;
    EXPECT_NE(out.find("embossed 12 passes"), std::string::npos) << out;
}

}  // namespace
}  // namespace tactus
