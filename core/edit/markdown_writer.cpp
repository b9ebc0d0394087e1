// SPDX-License-Identifier: GPL-3.0-or-later
#include "edit/markdown_writer.hpp"

namespace tactus::edit {

std::string to_markdown(std::span<const std::string> editor_lines) {
    std::string out;
    for (const auto& line : editor_lines) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank: no block
        if (!out.empty()) out += "\n\n";
        out += line;
    }
    out += '\n';
    return out;
}

}  // namespace tactus::edit
