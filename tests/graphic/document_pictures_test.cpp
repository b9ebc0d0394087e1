// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures inside documents (pandoc's own test files): the import keeps their
// bytes as the package holds them; laid out with pictures as graphics, each
// is a graphic page on a sheet of its own whose dots are the ones the same
// picture gets as a drawing file, its back empty; without the option the
// braille is what it always was (golden BRF made before pictures were kept).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "../common/firmware_tables_fixture.hpp"
#include "../common/process.hpp"
#include "common/file_io.hpp"
#include "graphic/drawing_file.hpp"
#include "import/import.hpp"
#include "import/zip_archive.hpp"
#include "pipeline/pipeline.hpp"
#include "plan/planner.hpp"
#include "profile/page_geometry.hpp"
#include "profile/profile.hpp"
#include "translate/catalogue.hpp"

namespace tactus {
namespace {

const std::string kData = std::string(TACTUS_TEST_DATA) + "/import";
const std::string kInline = kData + "/public/pandoc-inline_images.docx";
const std::string kVml = kData + "/public/pandoc-image_vml.docx";
const std::string kOdt = kData + "/public/pandoc-image.odt";
const std::string kEmf = kData + "/public/pandoc-image_with_textbox_caption.docx";
const std::string kMarkdown = kData + "/pictures/pictures.md";

document::Document import_pictures(const std::string& path, bool images = true) {
    import::ImportOptions o;
    o.images = images;
    auto doc = import::import_file(path, o);
    EXPECT_TRUE(doc) << doc.error().to_string();
    return doc ? std::move(*doc) : document::Document{};
}

std::vector<const document::Image*> images_of(const document::Document& doc) {
    std::vector<const document::Image*> out;
    for (const auto& b : doc.blocks)
        for (const auto& i : b.images) out.push_back(&i);
    return out;
}

std::string package_part(const std::string& path, const std::string& part) {
    const auto bytes = read_file(path, std::size_t{1} << 26);
    EXPECT_TRUE(bytes);
    auto zip = import::detail::ZipArchive::open(*bytes);
    EXPECT_TRUE(zip);
    auto out = zip->read(part, std::size_t{1} << 26);
    EXPECT_TRUE(out) << part;
    return out ? *out : std::string{};
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& part) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

TEST(DocumentPictures, DocxKeepsEachPicturesBytesAsThePackageHoldsThemAndItsDescription) {
    const auto doc = import_pictures(kInline);
    const auto images = images_of(doc);
    ASSERT_EQ(images.size(), 2U);
    EXPECT_EQ(images[0]->name, "word/media/image1.jpg");
    EXPECT_EQ(images[1]->name, "word/media/image2.jpg");
    for (const auto* i : images) {
        EXPECT_EQ(i->media_type, "image/jpeg");
        EXPECT_EQ(i->bytes, package_part(kInline, i->name));
    }
    // The description is still the block's transcriber's note.
    const auto& first = *std::find_if(doc.blocks.begin(), doc.blocks.end(),
                                      [](const document::Block& b) { return !b.images.empty(); });
    EXPECT_TRUE(std::any_of(first.spans.begin(), first.spans.end(), [](const document::Span& s) {
        return s.transcriber_note && s.text == "This one is green and looks like Sideshow Bob.";
    }));
    // Without the option: the same document, no bytes.
    auto without = import_pictures(kInline, false);
    EXPECT_TRUE(images_of(without).empty());
    auto stripped = doc;
    for (auto& b : stripped.blocks) b.images.clear();
    EXPECT_EQ(stripped, without);
}

TEST(DocumentPictures, VmlAndOdtPicturesKeepTheirPartsAndAnUndescribedOneIsNamed) {
    const auto vml = import_pictures(kVml);
    ASSERT_EQ(images_of(vml).size(), 1U);
    EXPECT_EQ(images_of(vml)[0]->name, "word/media/image4.jpeg");
    EXPECT_EQ(images_of(vml)[0]->bytes, package_part(kVml, "word/media/image4.jpeg"));
    EXPECT_TRUE(has_warning(vml.warnings, "a graphic without a caption")) << vml.warnings.size();

    const auto odt = import_pictures(kOdt);
    ASSERT_EQ(images_of(odt).size(), 1U);
    const std::string part = "Pictures/10000000000000FA000000FAD6A15225.jpg";
    EXPECT_EQ(images_of(odt)[0]->name, part);
    EXPECT_EQ(images_of(odt)[0]->bytes, package_part(kOdt, part));
}

TEST(DocumentPictures, AnEmfPictureStaysItsDescriptionWithAWarningNamingIt) {
    const auto doc = import_pictures(kEmf);
    EXPECT_TRUE(images_of(doc).empty());
    EXPECT_TRUE(has_warning(doc.warnings, "word/media/image1.emf: not PNG, JPEG or SVG")) << doc.warnings.size();
}

TEST(DocumentPictures, MarkdownReadsPicturesBesideItAndRefusesOnesOutsideItsFolder) {
    const auto doc = import_pictures(kMarkdown);
    const auto images = images_of(doc);
    ASSERT_EQ(images.size(), 1U);
    EXPECT_EQ(images[0]->name, "movie.jpg");
    EXPECT_EQ(images[0]->bytes, *read_file(kData + "/pictures/movie.jpg", std::size_t{1} << 20));
    EXPECT_TRUE(has_warning(doc.warnings, "line 5: picture ../pictures_outside.png: outside the document's folder"));
    // Named without a folder (`tactus-cli layout pictures.md` in its folder): the working directory is its folder.
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(kData + "/pictures");
    const auto here = import_pictures("pictures.md");
    std::filesystem::current_path(cwd);
    EXPECT_EQ(images_of(here).size(), 1U);
}

TEST(DocumentPictures, EpubAndHtmlKeepTheirImgPicturesAndNameAGif) {
    const std::string epub = kData + "/public/pandoc-img_no_cover.epub";
    const auto book = import_pictures(epub);
    const auto in_book = images_of(book);
    ASSERT_EQ(in_book.size(), 2U);
    EXPECT_EQ(in_book[0]->name, "EPUB/img/check.png");
    EXPECT_EQ(in_book[0]->media_type, "image/png");
    EXPECT_EQ(in_book[1]->name, "EPUB/img/check.jpg");
    for (const auto* i : in_book) EXPECT_EQ(i->bytes, package_part(epub, i->name));
    EXPECT_TRUE(has_warning(book.warnings, "picture ../img/check.gif: not PNG, JPEG or SVG"));

    const auto page = import_pictures(kData + "/pictures/pandoc-html-reader.html");
    const auto in_page = images_of(page);
    ASSERT_EQ(in_page.size(), 2U);
    EXPECT_EQ(in_page[0]->name, "lalune.jpg");
    EXPECT_EQ(in_page[0]->bytes, *read_file(kData + "/pictures/lalune.jpg", std::size_t{1} << 20));
    EXPECT_EQ(in_page[1]->name, "movie.jpg");
    EXPECT_TRUE(images_of(import_pictures(kData + "/pictures/pandoc-html-reader.html", false)).empty());
}

// Laid out for the default machine as the CLI does, pictures as graphics.
layout::PagedDocument lay_out_with_graphics(const document::Document& doc, const profile::PrinterProfile& prof) {
    pipeline::PipelineOptions o;
    o.layout.geometry = profile::page_geometry(prof);
    o.translation_workers = 1;
    auto table = std::make_shared<translate::Translator>(*translate::Translator::open(o.tables));
    o.graphic_pages = [&prof, table, geometry = o.layout.geometry](const document::Image& image)
        -> Result<layout::PagedDocument> {
        auto laid = graphic::lay_out_picture(image, prof, geometry, *table);
        if (!laid) return std::unexpected(laid.error());
        return std::move(laid->document);
    };
    auto paged = pipeline::lay_out(doc, o);
    EXPECT_TRUE(paged) << paged.error().to_string();
    return paged ? std::move(*paged) : layout::PagedDocument{};
}

TEST(DocumentPictures, EachPictureIsAGraphicPageOnASheetOfItsOwnWithTheDrawingFilesDots) {
    const auto prof = profile::default_profile();
    ASSERT_TRUE(prof.geometry.interpoint);
    const auto doc = import_pictures(kInline);
    const auto paged = lay_out_with_graphics(doc, prof);
    const auto images = images_of(doc);
    std::vector<std::size_t> graphic_pages;
    for (std::size_t i = 0; i < paged.pages.size(); ++i)
        if (!paged.pages[i].graphic.empty()) graphic_pages.push_back(i);
    ASSERT_EQ(graphic_pages.size(), images.size());
    const auto table = translate::Translator::open(translate::kDefaultTable);
    ASSERT_TRUE(table);
    const auto dir = std::filesystem::temp_directory_path() / ("tactus-pictures-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    for (std::size_t k = 0; k < images.size(); ++k) {
        const auto at = graphic_pages[k];
        // A front, its back empty: no dots, no braille.
        EXPECT_FALSE(paged.geometry.page_is_back(at)) << "page " << at + 1;
        ASSERT_LT(at + 1, paged.pages.size());
        const auto& back = paged.pages[at + 1];
        EXPECT_TRUE(back.graphic.empty());
        EXPECT_TRUE(std::all_of(back.lines.begin(), back.lines.end(), [](const auto& l) {
            return std::all_of(l.begin(), l.end(), [](document::Cell c) { return c == document::Cell{}; });
        }));
        // The same picture as a file of its own.
        const auto file = dir / std::filesystem::path(images[k]->name).filename();
        ASSERT_TRUE(write_file_atomic(file, images[k]->bytes));
        const auto alone = graphic::lay_out_drawing_file(file, graphic::DrawingKind::picture, prof,
                                                         paged.geometry, *table);
        ASSERT_TRUE(alone) << alone.error().to_string();
        EXPECT_EQ(paged.pages[at].graphic, alone->document.pages[0].graphic);
        EXPECT_EQ(paged.pages[at].braille_number, static_cast<int>(at) + 1);
    }
    std::filesystem::remove_all(dir);
    // The text before each picture holds its description; text goes on after.
    EXPECT_GT(graphic_pages[0], 0U);
    EXPECT_FALSE(paged.pages[graphic_pages[1] - 2].lines.empty());

    // Planned for the reference firmware: the graphic's sheet strikes its dots, all on the front.
    plan::PlanOptions po;
    po.firmware = test::firmware_tables();
    const auto job = plan::plan_job(paged, prof, po);
    ASSERT_TRUE(job) << job.error().to_string();
    const auto sheet = paged.geometry.sheet_of_page(graphic_pages[0]);
    std::size_t strikes = 0;
    for (const auto& p : job->sheets[sheet - 1].passes)
        for (const auto& s : p.strikes) {
            EXPECT_EQ(s.side, plan::Side::front);
            ++strikes;
        }
    EXPECT_EQ(strikes, paged.pages[graphic_pages[0]].graphic.size());
}

TEST(DocumentPictures, APictureThatCannotBeReadStaysItsDescriptionWithAWarning) {
    const auto prof = profile::default_profile();
    document::Document doc;
    document::Block block;
    block.spans.push_back({.text = "A map of the island", .transcriber_note = true});
    // A PNG signature, then nothing a PNG reader can use.
    block.images.push_back({std::string("\x89PNG\r\n\x1a\nnot a picture", 22), "image/png", "media/map.png"});
    doc.blocks.push_back(block);
    const auto paged = lay_out_with_graphics(doc, prof);
    ASSERT_FALSE(paged.pages.empty());
    for (const auto& p : paged.pages) EXPECT_TRUE(p.graphic.empty());
    EXPECT_EQ(paged.pages.size(), 1U);  // the description's page, nothing after it
    EXPECT_TRUE(has_warning(paged.warnings, "picture media/map.png: ")) << paged.warnings.size();
    EXPECT_TRUE(has_warning(paged.warnings, "its description stays"));
    // The description is laid out as without the picture.
    auto plain = doc;
    plain.blocks[0].images.clear();
    pipeline::PipelineOptions o;
    o.layout.geometry = profile::page_geometry(prof);
    const auto without = pipeline::lay_out(plain, o);
    ASSERT_TRUE(without);
    EXPECT_EQ(paged.pages[0].lines, without->pages[0].lines);
}

TEST(DocumentPictures, WithoutTheOptionTheBrailleIsWhatItWas) {
    for (const auto& [source, golden] : {std::pair<std::string, std::string>{kInline, "pandoc-inline_images.brf"},
                                         {kVml, "pandoc-image_vml.brf"},
                                         {kMarkdown, "pictures.brf"}}) {
        for (const std::vector<std::string>& extra :
             {std::vector<std::string>{}, std::vector<std::string>{"--images", "descriptions"}}) {
            std::vector<std::string> args{"layout", "--to", "brf", source};
            args.insert(args.end(), extra.begin(), extra.end());
            const auto r = test::run_captured(test::cli(args));
            ASSERT_EQ(r.exit_code, 0) << r.err;
            EXPECT_EQ(r.out, *read_file(kData + "/pictures/golden/" + golden, std::size_t{1} << 20)) << source;
        }
    }
}

TEST(DocumentPictures, TheCliNamesTheGraphicPagesAndEmbossesThem) {
    const auto layout = test::run_merged(test::cli({"layout", "--images", "graphics", "--summary", kInline}));
    ASSERT_EQ(layout.exit_code, 0) << layout.out;
    EXPECT_NE(layout.out.find("on 2 graphic pages (braille pages 3, 7)"), std::string::npos) << layout.out;
    const auto text_only = test::run_merged(test::cli({"layout", "--summary", kInline}));
    EXPECT_EQ(text_only.out.find("graphic:"), std::string::npos) << text_only.out;
    const auto emboss =
        test::run_merged(test::cli({"emboss", "--images", "graphics", "--device", "sim?speed=max", kInline}));
    ASSERT_EQ(emboss.exit_code, 0) << emboss.out;
    EXPECT_NE(emboss.out.find("embossed"), std::string::npos) << emboss.out;
    EXPECT_NE(emboss.out.find("(sheet 4)"), std::string::npos) << emboss.out;  // the second picture's sheet
    const auto bad = test::run_merged(test::cli({"layout", "--images", "pictures", "--summary", kInline}));
    EXPECT_EQ(bad.exit_code, 2) << bad.out;
}

}  // namespace
}  // namespace tactus
