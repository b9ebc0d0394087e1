// SPDX-License-Identifier: GPL-3.0-or-later
#include "translate/louis.hpp"

#include <liblouis/liblouis.h>

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
#ifdef TACTUS_LOUIS_DATA_PATH
        lou_setDataPath(TACTUS_LOUIS_DATA_PATH);
#endif
    });
}

}  // namespace tactus::translate::louis
