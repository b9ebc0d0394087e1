// SPDX-License-Identifier: GPL-3.0-or-later
// The platform layer through its interfaces only, so the same cases check the
// POSIX implementations here and the Windows ones when built for Windows.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/durable_file.hpp"
#include "platform/process_info.hpp"
#include "platform/program_file.hpp"
#include "platform/sim_endpoint.hpp"
#include "platform/terminal.hpp"
#include "platform/user_dirs.hpp"
#include "platform/worker_process.hpp"

namespace fs = std::filesystem;
using namespace tactus::platform;

namespace {

struct TempDir {
    fs::path path;
    TempDir() : path(make_private_dir("tactus-platform-test").value()) {}
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::span<const std::uint8_t> bytes_of(std::string_view s) {
    return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// Reads from a channel until `n` bytes came or nothing more comes within a second.
std::string read_channel(Channel& c, std::size_t n) {
    std::string got;
    Channel* const cs[] = {&c};
    while (got.size() < n) {
        const auto ready = wait_readable(cs, std::chrono::seconds(1));
        if (!ready || !(*ready)[0]) break;
        std::array<std::uint8_t, 256> buf{};
        const auto r = c.read_some(buf);
        if (!r) break;
        got.append(reinterpret_cast<const char*>(buf.data()), *r);
    }
    return got;
}

std::string read_terminal(Terminal& t, std::size_t n) {
    std::string got;
    while (got.size() < n) {
        std::array<std::uint8_t, 256> buf{};
        const auto r = t.read(buf, std::chrono::seconds(1));
        if (!r || *r == 0) break;
        got.append(reinterpret_cast<const char*>(buf.data()), *r);
    }
    return got;
}

}  // namespace

TEST(DurableFile, NewFileReplacesTheOldOneInOneStep) {
    TempDir dir;
    const auto target = dir.path / "doc.md";
    const auto tmp = dir.path / ".doc.md.tmp";
    { std::ofstream(target) << "old"; }
    auto f = NewFile::create(tmp);
    ASSERT_TRUE(f) << f.error().what;
    ASSERT_TRUE(f->write_all("new text"));
    ASSERT_TRUE(f->sync_and_close());
    EXPECT_EQ(slurp(target), "old");  // nothing visible before the replacement
    ASSERT_TRUE(replace_file(tmp, target));
    EXPECT_EQ(slurp(target), "new text");
    EXPECT_FALSE(fs::exists(tmp));
}

TEST(DurableFile, NewFileNeverOpensAnExistingFile) {
    TempDir dir;
    const auto p = dir.path / "there";
    { std::ofstream(p) << "keep"; }
    EXPECT_FALSE(NewFile::create(p));
    EXPECT_EQ(slurp(p), "keep");
}

TEST(DurableFile, ReadableFileTellsFilesFromFolders) {
    TempDir dir;
    const auto p = dir.path / "f.txt";
    { std::ofstream(p) << "12345"; }
    auto f = ReadableFile::open(p);
    ASSERT_TRUE(f);
    const auto info = f->info();
    ASSERT_TRUE(info);
    EXPECT_EQ(info->type, FileType::regular);
    EXPECT_EQ(info->size, 5u);
    char buf[8] = {};
    EXPECT_EQ(f->read(buf, sizeof buf).value(), 5u);
    EXPECT_EQ(f->read(buf, sizeof buf).value(), 0u);
    auto d = ReadableFile::open(dir.path);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->info().value().type, FileType::directory);
    const auto missing = ReadableFile::open(dir.path / "missing");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().kind, OsErrorKind::not_found);
}

TEST(DurableFile, SyncFileAndRemoveFile) {
    TempDir dir;
    const auto p = dir.path / "s";
    { std::ofstream(p) << "x"; }
    EXPECT_TRUE(sync_file(p));
    EXPECT_FALSE(sync_file(dir.path / "missing"));
    remove_file(p);
    EXPECT_FALSE(fs::exists(p));
}

TEST(ProcessInfo, ThisProcessIsAliveAndAnEndedOneIsNot) {
    EXPECT_FALSE(host_name().empty());
    EXPECT_FALSE(user_name().empty());
    EXPECT_TRUE(process_alive(current_process_id()));
    EXPECT_FALSE(process_alive(0));
    EXPECT_FALSE(process_alive(-5));
#ifdef _WIN32
    const std::vector<std::string> args = {"cmd", "/c", "exit 0"};
#else
    const std::vector<std::string> args = {"true"};
#endif
    TempDir dir;
    auto child = ChildProcess::spawn({.args = args, .dir = dir.path, .log = dir.path / "log"});
    ASSERT_TRUE(child) << child.error().what;
    const auto pid = child->id();
    EXPECT_TRUE(pid > 0);
    EXPECT_EQ(child->wait(), 0);
    EXPECT_FALSE(process_alive(pid));  // ended and reaped
}

TEST(ChildProcess, RunsAProgramInItsFolderWithItsOutputLogged) {
    TempDir dir;
    EXPECT_FALSE(find_in_path("tactus-no-such-program"));
#ifdef _WIN32
    const std::vector<std::string> args = {"cmd", "/c", "cd & echo said hello & exit 3"};
#else
    ASSERT_TRUE(find_in_path("sh"));
    const std::vector<std::string> args = {"sh", "-c", "pwd; echo said hello; exit 3"};
#endif
    auto child = ChildProcess::spawn({.args = args, .dir = dir.path, .log = dir.path / "log"});
    ASSERT_TRUE(child) << child.error().what;
    EXPECT_EQ(child->wait(), 3);
    EXPECT_FALSE(child->running());
    const auto log = slurp(dir.path / "log");
    EXPECT_NE(log.find("said hello"), std::string::npos) << log;
    EXPECT_NE(log.find(dir.path.filename().string()), std::string::npos) << log;  // ran in its folder
}

TEST(ChildProcess, StopEndsAChildThatWaitsOnItsIdleInput) {
    TempDir dir;
#ifdef _WIN32
    const std::vector<std::string> args = {"cmd", "/c", "set /p x="};
#else
    const std::vector<std::string> args = {"cat"};  // never sees the end of its input
#endif
    auto child = ChildProcess::spawn({.args = args, .dir = dir.path, .log = dir.path / "log", .idle_input = true});
    ASSERT_TRUE(child);
    EXPECT_TRUE(child->running());
    child->stop();
    EXPECT_FALSE(child->running());
}

TEST(WorkerProcess, StreamsWhatItFindsAndSaysHowItEnded) {
    if (WorkerProcess::how() != WorkerStart::copy) {
        // Windows: a worker is the program started again (start_program(),
        // tested through the translation workers in tests/workers), never a copy.
        const auto w = WorkerProcess::start([](WorkerOutput&) { return 0; }, {});
        ASSERT_FALSE(w);
        EXPECT_EQ(w.error().kind, OsErrorKind::unsupported);
        return;
    }
    const std::string message = "from the copy";
    auto w = WorkerProcess::start(
        [&](WorkerOutput& out) { return out.write_all(message.data(), message.size()) ? 3 : 1; }, {});
    ASSERT_TRUE(w) << w.error().what;
    std::string got(message.size(), '\0');
    EXPECT_EQ(w->read_all(got.data(), got.size()), 1);
    EXPECT_EQ(got, message);
    char more = 0;
    EXPECT_EQ(w->read_all(&more, 1), 0);  // the end of its stream
    EXPECT_EQ(w->wait_for_end(), "exit status 3");
}

TEST(WorkerProcess, StopEndsAWorkerStillWriting) {
    if (WorkerProcess::how() != WorkerStart::copy) GTEST_SKIP() << "workers here are not copies of this process";
    auto w = WorkerProcess::start(
        [](WorkerOutput& out) {
            const char block[512] = {};
            while (out.write_all(block, sizeof block)) {
            }
            return 0;
        },
        {});
    ASSERT_TRUE(w);
    char first = 1;
    EXPECT_EQ(w->read_all(&first, 1), 1);
    w->stop();  // returns only once the worker is gone
    EXPECT_EQ(w->read_all(&first, 1), -1);
}

TEST(SimEndpoint, ATerminalOnItsPathTalksBothWays) {
    auto ep = SimEndpoint::open(true);
    ASSERT_TRUE(ep) << ep.error().what;
    ASSERT_FALSE(ep->path().empty());
    auto client = Terminal::open(ep->path(), LineSettings{});
    ASSERT_TRUE(client) << client.error().what;
    // Every byte value passes (raw), both ways.
    std::string all(256, '\0');
    for (int i = 0; i < 256; ++i) all[static_cast<std::size_t>(i)] = static_cast<char>(i);
    ASSERT_TRUE(client->write_all(bytes_of(all)));
    EXPECT_EQ(read_channel(ep->line(), all.size()), all);
    const std::string reply = "HELLO_REPLY\r\n\x03\x11\x13";
    std::size_t done = 0;
    while (done < reply.size()) {
        const auto n = ep->line().write_some(bytes_of(reply).subspan(done));
        ASSERT_TRUE(n);
        ASSERT_GT(*n, 0u);
        done += *n;
    }
    EXPECT_EQ(read_terminal(*client, reply.size()), reply);
    // Nothing waiting: a read times out with nothing, not an error.
    std::array<std::uint8_t, 4> buf{};
    EXPECT_EQ(client->read(buf, std::chrono::milliseconds(20)).value(), 0u);
}

TEST(SimEndpoint, TheLineIsOneClientsAtATime) {
    auto ep = SimEndpoint::open(true);
    ASSERT_TRUE(ep);
    auto first = Terminal::open(ep->path(), LineSettings{});
    ASSERT_TRUE(first);
    const auto second = Terminal::open(ep->path(), LineSettings{});
    ASSERT_FALSE(second);
    EXPECT_NE(second.error().what.find("busy"), std::string::npos) << second.error().what;
}

TEST(SimEndpoint, AClientThatLeavesMakesRoomForTheNext) {
    auto ep = SimEndpoint::open(true);
    ASSERT_TRUE(ep);
    {
        auto first = Terminal::open(ep->path(), LineSettings{});
        ASSERT_TRUE(first) << first.error().what;
        ASSERT_TRUE(first->write_all(bytes_of("one")));
        EXPECT_EQ(read_channel(ep->line(), 3), "one");
    }
    // The simulator notices the client gone as it waits for the next bytes.
    Channel* const line[] = {&ep->line()};
    ASSERT_TRUE(wait_readable(line, std::chrono::milliseconds(5)));
    auto second = Terminal::open(ep->path(), LineSettings{});
    ASSERT_TRUE(second) << second.error().what;
    ASSERT_TRUE(second->write_all(bytes_of("two")));
    EXPECT_EQ(read_channel(ep->line(), 3), "two");
}

TEST(Terminal, RefusesWhatIsNotThereAndWhatIsNotATerminal) {
    TempDir dir;
    const auto missing = Terminal::open((dir.path / "ttyNONE").string(), LineSettings{});
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().what, "no such device");
#ifndef _WIN32
    const auto plain = dir.path / "plain";
    { std::ofstream(plain) << "x"; }
    const auto not_tty = Terminal::open(plain.string(), LineSettings{});
    ASSERT_FALSE(not_tty);
    EXPECT_EQ(not_tty.error().what, "not a terminal");
    auto ep = SimEndpoint::open(true);
    ASSERT_TRUE(ep);
    LineSettings odd;
    odd.baud = 12345;
    const auto bad_baud = Terminal::open(ep->path(), odd);
    ASSERT_FALSE(bad_baud);
    EXPECT_EQ(bad_baud.error().what, "unsupported baud rate 12345");
#endif
}

TEST(Channel, AFifoCarriesBytesOrIsRefusedWhereThereIsNone) {
    TempDir dir;
    auto fifo = open_fifo(dir.path / "f");
#ifdef _WIN32
    ASSERT_FALSE(fifo);
    EXPECT_EQ(fifo.error().kind, OsErrorKind::unsupported);
#else
    ASSERT_TRUE(fifo) << fifo.error().what;
    ASSERT_EQ(fifo->write_some(bytes_of("abc")).value(), 3u);
    EXPECT_EQ(read_channel(*fifo, 3), "abc");
    // Nothing left: the wait ends at its timeout with nothing ready.
    Channel* const cs[] = {&*fifo};
    const auto ready = wait_readable(cs, std::chrono::milliseconds(10));
    ASSERT_TRUE(ready);
    EXPECT_FALSE((*ready)[0]);
#endif
}

#ifndef _WIN32
// The XDG base directory rules: an absolute $XDG_DATA_HOME, else ~/.local/share.
TEST(UserDirs, DataHomeFollowsXdg) {
    const auto keep = [](const char* name) -> std::optional<std::string> {
        const char* v = std::getenv(name);
        return v ? std::optional<std::string>(v) : std::nullopt;
    };
    const auto xdg = keep("XDG_DATA_HOME"), home = keep("HOME");
    setenv("HOME", "/home/reader", 1);
    setenv("XDG_DATA_HOME", "/data/xdg", 1);
    EXPECT_EQ(user_data_home(), fs::path("/data/xdg"));
    setenv("XDG_DATA_HOME", "relative/is/ignored", 1);
    EXPECT_EQ(user_data_home(), fs::path("/home/reader/.local/share"));
    unsetenv("XDG_DATA_HOME");
    unsetenv("HOME");
    EXPECT_EQ(user_data_home(), std::nullopt);
    for (const auto& [name, value] : {std::pair{"XDG_DATA_HOME", xdg}, std::pair{"HOME", home}})
        if (value) setenv(name, value->c_str(), 1);
}
#else
TEST(UserDirs, DataHomeIsTheLocalAppDataFolder) {
    const auto d = user_data_home();
    ASSERT_TRUE(d);
    EXPECT_TRUE(fs::is_directory(*d)) << d->string();
}
#endif

// The program's own file: an absolute path to this test executable, whatever
// folder the test runs in (an installed program finds its tables from it).
TEST(ProgramFile, NamesThisExecutableAbsolutely) {
    const auto file = program_file();
    ASSERT_TRUE(file) << file.error().what;
    EXPECT_TRUE(file->is_absolute()) << file->string();
    EXPECT_TRUE(fs::is_regular_file(*file)) << file->string();
    EXPECT_TRUE(file->filename().string().starts_with("platform_tests")) << file->string();
}

