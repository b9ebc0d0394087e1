// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// PEF validity as the standard defines it: the RELAX NG schema (checked with
// xmllint, a real validator) plus the two schematron rules the schema cannot
// express: a page's rows fit the page, and no row is longer than `cols`.
#include <pugixml.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/utf8.hpp"

inline std::string validate_pef_schema(const std::string& pef) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("tactus-pef-" + std::to_string(std::hash<std::string>{}(pef)) + ".pef");
    std::ofstream(path, std::ios::binary) << pef;
    const std::string cmd = "xmllint --noout --relaxng '" TACTUS_TEST_DATA
                            "/schemas/pef-2008-1.rng' '" + path.string() + "' 2>&1";
    std::string output;
    if (FILE* p = ::popen(cmd.c_str(), "r")) {
        char buf[512];
        while (std::fgets(buf, sizeof buf, p)) output += buf;
        const int rc = ::pclose(p);
        std::filesystem::remove(path);
        return rc == 0 ? std::string{} : output;
    }
    return "cannot run xmllint";
}

// Empty string when both schematron rules hold; otherwise the first violation.
inline std::string check_pef_schematron(const std::string& pef) {
    pugi::xml_document doc;
    if (!doc.load_string(pef.c_str())) return "not XML";
    for (auto volume : doc.select_nodes("//*[local-name()='volume']")) {
        const auto cols = volume.node().attribute("cols").as_int();
        const auto rows = volume.node().attribute("rows").as_int();
        const auto rowgap = volume.node().attribute("rowgap").as_int();
        int page_no = 0;
        for (auto page : volume.node().select_nodes(".//*[local-name()='page']")) {
            ++page_no;
            int height = 0;  // in dot rows: 4 per row (a cell) plus the gaps
            int row_no = 0;
            for (auto row : page.node().children("row")) {
                ++row_no;
                const auto cells = tactus::utf8_to_utf32(row.text().as_string());
                if (!cells) return "invalid UTF-8 in a row";
                if (static_cast<int>(cells->size()) > cols)
                    return "page " + std::to_string(page_no) + " row " + std::to_string(row_no) +
                           " longer than cols";
                height += 4 + (row_no > 1 ? rowgap : 0);
            }
            if (height > rows * 4 + (rows - 1) * rowgap)
                return "page " + std::to_string(page_no) + " has more rows than fit";
        }
    }
    return {};
}
