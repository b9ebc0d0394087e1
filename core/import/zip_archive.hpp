// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Read-only access to a ZIP package held in memory (libzip), for DOCX.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "common/result.hpp"

struct zip;

namespace tactus::import::detail {

class ZipArchive {
public:
    // `bytes` must outlive the archive: libzip reads it in place.
    static Result<ZipArchive> open(std::string_view bytes);

    [[nodiscard]] bool contains(const std::string& part) const;
    // Refuses parts whose uncompressed size exceeds `max_bytes` (zip bombs)
    // and reports corrupt data (CRC, truncated deflate stream) by part name.
    Result<std::string> read(const std::string& part, std::size_t max_bytes) const;

private:
    struct Closer {
        void operator()(zip* z) const;
    };
    explicit ZipArchive(zip* z) : zip_(z) {}
    std::unique_ptr<zip, Closer> zip_;
};

}  // namespace tactus::import::detail
