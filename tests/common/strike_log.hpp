// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reads the strike log `tactus-cli sim --strike-log` writes (one JSON object
// per line), for the C++ simulated controller and the firmware in s51 alike.
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "controller/sim_controller.hpp"

namespace tactus::test {

inline std::vector<controller::LoggedStrike> read_strike_log(const std::string& path) {
    std::vector<controller::LoggedStrike> log;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        const auto j = nlohmann::json::parse(line);
        controller::LoggedStrike s;
        s.sheet = j["sheet"];
        s.side = j["side"] == "front" ? plan::Side::front : plan::Side::back;
        s.hammer = j["hammer"] == "convex" ? plan::Hammer::convex : plan::Hammer::concave;
        s.carriage_step = j["carriage_step"];
        s.feed_step = j["feed_step"];
        s.time_s = j["time_s"];
        s.x_mm = j["x_mm"];
        s.y_mm = j["y_mm"];
        log.push_back(s);
    }
    return log;
}

}  // namespace tactus::test
