// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pictures in the editor's Markdown lines. A picture a document holds (a DOCX
// or ODT picture, a Markdown image, one inserted) is a mark in its line,
// "![description](name)", where its description stands in the text; the
// description is its transcriber's note and the name the key of its bytes in
// the editor's pictures (LiveLayout::pictures). Lines stay text, so editing,
// undo and the cursor map work on them as on any line, and the document the
// lines stand for (LiveLayout::document) has each picture's bytes again, for
// the writers to save and layout to emboss.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "document/document.hpp"

namespace tactus::edit {

// The pictures an editor holds, by the name their marks give.
using PictureStore = std::map<std::string, document::Image, std::less<>>;

// A name a mark can hold as it is (letters, digits, "._-/"; any other
// character becomes "_"), never empty.
std::string picture_name(std::string_view name);

// "![description](name)": the description escaped as Markdown text (one
// line), the name as picture_name gives it.
std::string picture_mark(std::string_view description, std::string_view name);

// Puts the document's pictures in `store` and names each by its key there:
// its own name made markable, numbered on ("image1-2.png") when the store
// holds other bytes under it already.
void store_pictures(document::Document& document, PictureStore& store);

// Names each picture by its place in the document and its type
// ("picture1.png", "picture2.svg"): for a document whose pictures are parts
// of a package (DOCX, ODT, EPUB), which the writers name anew, so that its
// lines read the same after it is saved and opened again. A Markdown file's
// pictures keep their names: they are its files.
void number_pictures(document::Document& document);

// Adds one picture under a free name made from `name`; returns that name.
std::string store_picture(document::Image image, PictureStore& store);

// A block's pictures as the lines name them, with their bytes from `store`.
// A name the store lacks is left out, its name added to `missing`.
void fill_pictures(document::Block& block, const PictureStore& store, std::vector<std::string>& missing);

// The block with each picture that has a description (its transcriber's
// notes and pictures paired in order, as the writers pair them:
// exporter::office::BlockPictures) written as its mark: `write` renders the
// block with the marks' places held by characters no writer escapes, which
// are then replaced by the marks. Pictures left without a description are
// marked at the block's end, with an empty description.
std::vector<std::string> render_with_picture_marks(
    const document::Document& document, std::vector<std::string> (*write)(const document::Document&));

// A picture file a Markdown file needs beside it: where, and its bytes.
struct PictureFile {
    std::filesystem::path path;
    std::string bytes;
};

// The picture files a Markdown file named `file` needs beside it and lacks
// (none for another format):
// each picture by the name its mark gives, in the file's folder. Saving
// writes them with the file, so it keeps every picture (a DOCX's, an
// inserted one); a Markdown file's own are there already. A name that would
// leave the folder is none of them (pictures_lost counts it).
std::vector<PictureFile> picture_files(const document::Document& document, const std::filesystem::path& file);

// The document's pictures a print file named `file` would not keep: a DOCX
// or ODT keeps them all, a Markdown file those it has or gets beside it
// (picture_files; not one whose name a different file beside it holds
// already), a text file none (it keeps their descriptions).
std::size_t pictures_lost(const document::Document& document, const std::filesystem::path& file);

}  // namespace tactus::edit
