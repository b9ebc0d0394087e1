// SPDX-License-Identifier: GPL-3.0-or-later
// tactus-cli tables: the braille tables installed, by language.
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "translate/catalogue.hpp"

namespace tactus::cli {

void add_tables_command(CLI::App& app) {
    auto json = std::make_shared<bool>(false);
    auto all = std::make_shared<bool>(false);
    auto* cmd = app.add_subcommand("tables", "List the braille translation tables by language");
    cmd->add_flag("--json", *json, "Machine-readable output");
    cmd->add_flag("--all", *all, "Also list tables Tactus is not tested with");
    cmd->callback([json, all] {
        const auto tables = translate::table_catalogue();
        if (*json) {
            auto out = nlohmann::json::array();
            for (const auto& t : tables) {
                if (!*all && !t.recommended) continue;
                out.push_back({{"table", t.file}, {"language", t.language},
                               {"language_tag", t.language_tag}, {"name", t.name},
                               {"grade", t.grade}, {"recommended", t.recommended}});
            }
            std::cout << out.dump(2) << '\n';
            return;
        }
        std::size_t hidden = 0;
        for (const auto& t : tables) {
            if (!*all && !t.recommended) {
                ++hidden;
                continue;
            }
            std::cout << std::left << std::setw(16) << t.file << "  " << std::setw(26)
                      << t.language << "  " << t.name << '\n';
        }
        if (hidden > 0)
            std::cout << "(" << hidden << " more installed tables: tactus-cli tables --all)\n";
    });
}

}  // namespace tactus::cli
