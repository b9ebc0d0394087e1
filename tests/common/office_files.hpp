// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The real DOCX and ODT files the test data holds (public test suites, the
// constructs made with LibreOffice and python-docx, the lessons), in name
// order: the corpus every round trip of office documents runs over.
#include <algorithm>
#include <filesystem>
#include <vector>

namespace tactus::test {

inline std::vector<std::filesystem::path> real_office_files(const std::filesystem::path& data) {
    std::vector<std::filesystem::path> out;
    for (const auto* dir : {"import/public", "import/constructs", "import"})
        for (const auto& e : std::filesystem::directory_iterator(data / dir)) {
            const auto ext = e.path().extension();
            if (ext == ".docx" || ext == ".odt") out.push_back(e.path());
        }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace tactus::test
