// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs a command through /bin/sh for end-to-end tests of the real binaries.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

struct RunResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

inline RunResult run_command(const std::string& command, const std::string& stdin_text = {}) {
    namespace fs = std::filesystem;
    static int counter = 0;
    const auto base = fs::temp_directory_path() /
                      ("tactus-run-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    const auto in = base.string() + ".in", out = base.string() + ".out", err = base.string() + ".err";
    std::ofstream(in, std::ios::binary) << stdin_text;
    const std::string full = command + " <'" + in + "' >'" + out + "' 2>'" + err + "'";
    const int status = std::system(full.c_str());
    auto slurp = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    };
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    fs::remove(in);
    fs::remove(out);
    fs::remove(err);
    return r;
}

inline std::string cli(const std::string& args) { return std::string("'") + TACTUS_CLI + "' " + args; }
