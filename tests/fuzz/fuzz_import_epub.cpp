// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the EPUB importer (see import_fuzz.hpp for what must hold).
#include "import_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzz_import(data, size, tactus::import::SourceFormat::epub);
}
