// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opening and re-laying documents off the GUI thread: import, render the editor
// lines, translate and paginate, with progress and cancel through QFuture.
#include <QFuture>
#include <QString>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit/live_layout.hpp"

namespace tactus::gui {

struct LoadResult {
    std::optional<edit::LiveLayout> layout;
    std::optional<Error> error;  // unreadable file, unknown encoding, bad table...
    QString path;
    bool cancelled = false;
};
using LoadResultPtr = std::shared_ptr<LoadResult>;

// Imports `path` (any core format) and lays it out with `tables`.
QFuture<LoadResultPtr> load_file(const QString& path, const std::string& tables, const layout::LayoutOptions& options);
// Lays out lines already in the editor (a new table on a big book), with the
// braille structure they carry (LiveLayout::braille_structure).
QFuture<LoadResultPtr> lay_out_lines(std::vector<std::string> lines, const std::string& tables,
                                     const layout::LayoutOptions& options, edit::Dialect dialect,
                                     edit::BrailleStructure structure = {});

// The same work, on the calling thread (tests, the benchmark and the CLI-style paths).
LoadResultPtr load_file_now(const QString& path, const std::string& tables, const layout::LayoutOptions& options);

}  // namespace tactus::gui
