// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared test material: documents whose every page is recognisably different,
// and scratch folders for real database files.
#include <filesystem>
#include <random>
#include <string>

#include "layout/page.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"

namespace tactus::spool::test {

// `pages` pages of 3 lines; page p's cells spell p, so a mix-up shows.
inline layout::PagedDocument make_document(std::size_t pages, bool interpoint) {
    layout::PagedDocument doc;
    doc.geometry.interpoint = interpoint;
    for (std::size_t p = 1; p <= pages; ++p) {
        layout::Page page;
        page.braille_number = static_cast<int>(p);
        for (std::size_t l = 0; l < 3; ++l) {
            document::BrailleLine line;
            for (std::size_t c = 0; c < 10; ++c)
                line.push_back(document::Cell{static_cast<std::uint8_t>(((p * 7 + l * 3 + c) % 63) + 1)});
            page.lines.push_back(std::move(line));
        }
        doc.pages.push_back(std::move(page));
    }
    return doc;
}

// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        std::random_device rd;
        path_ = std::filesystem::temp_directory_path() /
                ("tactus-spool-" + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

inline JobSubmission submission(const std::string& printer, std::size_t pages,
                                std::size_t copies = 1, int priority = 0) {
    const layout::PagedDocument doc = make_document(pages, true);
    JobSubmission s;
    s.printer = printer;
    s.title = "book of " + std::to_string(pages) + " pages";
    s.document = to_snapshot(doc);
    s.sheets_per_copy = doc.sheet_count();
    s.copies = copies;
    s.priority = priority;
    s.user = "teacher";
    return s;
}

}  // namespace tactus::spool::test
