// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ready-made braille with a PEF's structure (its sections, volumes, their
// grids and its dc: metadata: LiveLayout::braille_structure) leaves the
// editor as PEF wherever a file carries the document on to someone else: the
// autosave the app recovers after a crash, a job sent to a CUPS queue.
// Markdown (the editor's lines) keeps its rows and pages but none of the
// rest. The one rule both ask.
#include <optional>
#include <string>

#include "common/result.hpp"
#include "edit/live_layout.hpp"

namespace tactus::edit {

// The document as PEF when its lines are ready-made braille (only braille
// rows and braille page breaks) with a PEF's structure: its own pages, on
// each section's own grid, volumes, duplex and metadata, however large (the
// printer's page is asked about where it is embossed); `title` names it only
// when it has no dc: metadata of its own. Nothing when it is not that (print
// text typed into it, or braille without a PEF's structure): it travels as
// the editor's own file.
std::optional<Result<std::string>> structured_braille_pef(const LiveLayout& layout, const std::string& title);

}  // namespace tactus::edit
