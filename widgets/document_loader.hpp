// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opening and re-laying documents off the GUI thread: import, render the editor
// lines, translate and paginate, with progress and cancel through QFuture.
#include <QFuture>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit/live_layout.hpp"
#include "layout/page.hpp"
#include "profile/profile.hpp"

namespace tactus::gui {

// A tactile graphic as the app holds it: its pages, laid out by the core
// function the CLI calls (graphic::lay_out_drawing_file), and what it is.
struct GraphicView {
    layout::PagedDocument paged;
    QString title;        // the drawing's <title>, else the file's name
    QString description;  // its <desc>
    QStringList labels;   // its <text>s, in order
    std::size_t dots = 0; // on all its pages, as `tactus-cli layout --summary` counts them
    // "Graphic: <title>. <description>" with its labels and dots: what the
    // print pane shows and the preview's accessible text says.
    [[nodiscard]] QString summary() const;
};

struct LoadResult {
    // For a graphic: the print pane's read-only lines saying what it is.
    std::optional<edit::LiveLayout> layout;
    std::optional<GraphicView> graphic;
    std::optional<Error> error;  // unreadable file, unknown encoding, bad table...
    QString path;
    bool cancelled = false;
};
using LoadResultPtr = std::shared_ptr<LoadResult>;

// Imports `path` (any core format) and lays it out with `tables`; a drawing
// (.svg, .png, .jpg) is laid out as a graphic on `machine`'s page.
QFuture<LoadResultPtr> load_file(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                                 const profile::PrinterProfile& machine = profile::default_profile());
// Lays out lines already in the editor (a new table on a big book), with the
// braille structure they carry (LiveLayout::braille_structure).
QFuture<LoadResultPtr> lay_out_lines(std::vector<std::string> lines, const std::string& tables,
                                     const layout::LayoutOptions& options, edit::Dialect dialect,
                                     edit::BrailleStructure structure = {});

// The same work, on the calling thread (tests, the benchmark and the CLI-style paths).
LoadResultPtr load_file_now(const QString& path, const std::string& tables, const layout::LayoutOptions& options,
                            const profile::PrinterProfile& machine = profile::default_profile());

}  // namespace tactus::gui
