// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The front half of the pipeline in one call: import -> translate -> layout.
// Translation (liblouis, one thread at a time) and layout run concurrently:
// a translator thread hands finished blocks to the paginator on the caller's
// thread through a bounded queue.
#include <filesystem>
#include <string>

#include "common/result.hpp"
#include "document/document.hpp"
#include "import/import.hpp"
#include "layout/layout_options.hpp"
#include "layout/page.hpp"
#include "translate/catalogue.hpp"

namespace tactus {

struct PipelineOptions {
    ImportOptions import;
    std::string tables = kDefaultTable;
    LayoutOptions layout;
};

Result<PagedDocument> lay_out(const Document& document, const PipelineOptions& options);
Result<PagedDocument> lay_out_file(const std::filesystem::path& path,
                                   const PipelineOptions& options);

}  // namespace tactus
