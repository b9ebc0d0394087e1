// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The picture a description stands on when the document keeps no picture for
// it (a transcriber's note from a picture of a type a graphic cannot be made
// of, a ruby guide, a document opened without pictures): DOCX keeps an image's
// description on its wp:docPr, ODT in its draw:frame, so the DOCX and ODT
// writers need a picture to hang it on. The importers know it and keep the
// description, not the picture, so saving and opening again adds no graphic.
#include <string_view>

namespace tactus::document {

// A 1x1 transparent PNG.
inline std::string_view placeholder_png() {
    static constexpr char png[] =
        "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00\x00\x01\x08\x06"
        "\x00\x00\x00\x1f\x15\xc4\x89\x00\x00\x00\x0b\x49\x44\x41\x54\x78\xda\x63\x60\x00\x02\x00\x00\x05\x00\x01"
        "\xe9\xfa\xdc\xd8\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82";
    return {png, sizeof png - 1};
}

}  // namespace tactus::document
