// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/louis.hpp"

#include <liblouis/liblouis.h>

#include "platform/program_file.hpp"

namespace tactus::translate::louis {
namespace {

std::string& log_buffer() {
    static std::string buffer;
    return buffer;
}

void on_log(logLevels level, const char* message) {
    if (level < LOU_LOG_WARN || message == nullptr) return;
    auto& b = log_buffer();
    if (b.size() > 4096) return;  // a broken table can log thousands of lines
    if (!b.empty()) b += "; ";
    b += message;
}

}  // namespace

std::mutex& lock() {
    static std::mutex m;
    return m;
}

std::string take_log() {
    std::string out;
    out.swap(log_buffer());
    return out;
}

void install_log_capture() {
    static std::once_flag once;
    std::call_once(once, [] {
        std::lock_guard guard(lock());
        lou_registerLogCallback(on_log);
        lou_setLogLevel(LOU_LOG_WARN);
#ifdef TACTUS_LOUIS_TABLES_BESIDE_PROGRAM
        // liblouis searches its data path (the folder holding liblouis/tables)
        // before the program's folder: it gets the one chosen by tables_dir().
        lou_setDataPath(tables_dir().parent_path().parent_path().string().c_str());
#endif
    });
}

const std::filesystem::path& tables_dir() {
    static const std::filesystem::path dir = [] {
#ifdef TACTUS_LOUIS_TABLES_BESIDE_PROGRAM
        // An installed program finds its own tables wherever it was installed.
        if (const auto program = platform::program_file()) {
            const auto beside = program->parent_path() / TACTUS_LOUIS_TABLES_BESIDE_PROGRAM;
            std::error_code ec;
            if (std::filesystem::is_regular_file(beside / "unicode.dis", ec)) return beside;
        }
#endif
        return std::filesystem::path(TACTUS_LOUIS_DATADIR);
    }();
    return dir;
}

}  // namespace tactus::translate::louis
