// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A ZIP package built in memory (libzip), for the office writers: DOCX and
// ODT are ZIP packages of XML parts. Parts are stored in the order given (ODF
// wants its `mimetype` first and uncompressed), each with the same fixed
// modification time, so the same document always gives the same bytes.
#include <string>
#include <vector>

#include "common/result.hpp"

namespace tactus::exporter {

struct ZipPart {
    std::string name;   // path inside the package, "word/document.xml"
    std::string bytes;
    bool stored = false;  // uncompressed (ODF's mimetype), else deflated
};

Result<std::string> zip_package(const std::vector<ZipPart>& parts);

}  // namespace tactus::exporter
