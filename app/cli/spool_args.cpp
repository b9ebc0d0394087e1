// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool_args.hpp"

#include <ctime>

#include "command.hpp"
#include "platform/clock.hpp"
#include "spool/db_path.hpp"

namespace tactus::cli {

spool::Spool open_spool(const std::string& db, bool create, bool read_only_ok) {
    const auto path = require(spool::spool_path(db), exit_usage);
    return require(spool::Spool::open(path, {.create = create, .read_only_ok = read_only_ok}));
}

std::string local_time(double seconds) {
    const auto t = static_cast<std::time_t>(seconds);
    const std::tm tm = platform::local_time(t);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", &tm);
    return buf;
}

}  // namespace tactus::cli
