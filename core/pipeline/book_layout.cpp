// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/book_layout.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>

#include "common/utf8.hpp"
#include "layout/paginator.hpp"
#include "pipeline/book_choice.hpp"
#include "pipeline/translation_workers.hpp"
#include "translate/translated_document.hpp"
#include "common/try.hpp"

namespace tactus::pipeline {
namespace {

using document::BlockKind;
using document::BrailleLine;
using document::Cell;

constexpr Cell kGuideDot{0x10};  // dot 5: the contents' guide dots (§2.10)

std::string metadata(const document::Document& doc, std::string_view name) {
    for (const auto& m : doc.metadata)
        if (m.name == name) return m.value;
    return {};
}

struct Heading {
    std::size_t block = 0;
    int level = 0;
    BrailleLine cells;
    std::string print_page;
    int braille_page = 0;
    std::size_t volume = 0;
};

class BookMaker {
public:
    BookMaker(const document::Document& doc, const layout::LayoutOptions& layout, const BookOptions& book,
              const translate::Translator& translator, unsigned workers, const BookProgress& progress)
        : doc_(doc), layout_(layout), book_(book), translator_(translator), workers_(workers), progress_(progress) {
        body_ = layout_;
        if (book_.running_heads) body_.top_margin += 1;  // line 1 holds the running head (§1.8)
    }

    // Nullopt when progress_ stopped it.
    Result<std::optional<BookLayout>> make() {
        // First pass, as the blocks come from translation: where each block
        // falls, to choose the volume breaks.
        std::vector<std::size_t> start_page;
        std::size_t total_pages = 0;
        {
            layout::Paginator p(body_, [this](int n) { return number(n); });
            TACTUS_TRY_VOID(translate_all([&](translate::TranslatedBlock b) {
                start_page.push_back(p.pages_closed());
                p.add(b);
                blocks_.push_back(std::move(b));
            }));
            if (stopped_) return std::optional<BookLayout>{};
            total_pages = std::move(p).finish().pages.size();
            if (error_) return std::unexpected(*error_);
        }
        const auto splits = volume_starts(start_page, total_pages);

        // Second pass: each volume's body on its own, page numbers going on.
        BookLayout out;
        out.pages.geometry = layout_.geometry;
        int next_number = layout_.first_page_number;
        std::vector<std::vector<layout::Page>> bodies;
        std::vector<std::string> warnings;
        std::string print_page;
        for (std::size_t v = 0; v < splits.size(); ++v) {
            const auto begin = splits[v];
            const auto end = v + 1 < splits.size() ? splits[v + 1] : blocks_.size();
            auto opts = body_;
            opts.first_page_number = next_number;
            layout::Paginator p(opts, [this](int n) { return number(n); });
            for (std::size_t i = begin; i < end; ++i) {
                const auto& src = doc_.blocks[i];
                if (src.kind == BlockKind::print_page_break) print_page = src.label;
                p.add(blocks_[i]);
                if (src.kind == BlockKind::heading && src.level <= book_.contents_depth) {
                    Heading h;
                    h.block = i;
                    h.level = src.level;
                    h.cells = blocks_[i].cells;
                    h.print_page = print_page;
                    h.braille_page = next_number + static_cast<int>(p.pages_closed());
                    h.volume = v;
                    headings_.push_back(std::move(h));
                }
            }
            auto laid = std::move(p).finish();
            if (error_) return std::unexpected(*error_);
            warnings.insert(warnings.end(), laid.warnings.begin(), laid.warnings.end());
            next_number += static_cast<int>(laid.pages.size());
            if (book_.running_heads) add_running_heads(laid.pages);
            // The next volume starts on a new sheet: a blank back after an odd count.
            if (layout_.geometry.interpoint && laid.pages.size() % 2 == 1 && v + 1 < splits.size()) {
                laid.pages.push_back(blank_page());
                laid.pages.back().braille_number = next_number++;
            }
            bodies.push_back(std::move(laid.pages));
        }

        for (std::size_t v = 0; v < bodies.size(); ++v) {
            std::size_t title_pages = 0;
            TACTUS_TRY(prelims, preliminary_pages(v, bodies.size(), title_pages));
            VolumeRange range;
            range.first_page = out.pages.pages.size();
            range.contents_first_page = range.first_page + title_pages;
            layout::PageSection volume_section;
            volume_section.first_page = range.first_page;
            volume_section.duplex = layout_.geometry.interpoint;
            volume_section.starts_volume = true;
            if (!prelims.empty()) {
                out.pages.sections.push_back(volume_section);
                append(out.pages.pages, std::move(prelims));
            }
            range.body_first_page = out.pages.pages.size();
            layout::PageSection body_section = volume_section;
            body_section.first_page = range.body_first_page;
            body_section.starts_volume = range.body_first_page == range.first_page;
            out.pages.sections.push_back(body_section);
            append(out.pages.pages, std::move(bodies[v]));
            range.end_page = out.pages.pages.size();
            out.volumes.push_back(range);
        }
        out.pages.warnings = std::move(warnings);
        return out;
    }

private:
    // Each block of the body translated, in document order, to `take`.
    Result<void> translate_all(const std::function<void(translate::TranslatedBlock)>& take) {
        const auto room = [this](const document::Block& b) { return layout::word_room(body_, b.kind, b.level); };
        const auto total = doc_.blocks.size();
        std::size_t done = 0;
        const auto told = [&] {
            stopped_ = progress_ && progress_(++done, total);
            return stopped_;
        };
        if (workers_ > 1 && TranslationWorkers::available()) {
            TACTUS_TRY(pool, TranslationWorkers::start(doc_, translator_, workers_, 64, room));
            for (;;) {
                TACTUS_TRY(block, pool.next());
                if (!block) return {};
                take(std::move(*block));
                if (told()) return {};
            }
        }
        for (const auto& b : doc_.blocks) {
            auto tb = translate::translate_block(b, translator_, room(b));
            if (!tb) return std::unexpected(located(tb.error(), doc_.source_name));
            take(std::move(*tb));
            if (told()) return {};
        }
        return {};
    }

    BrailleLine number(int n) {
        if (auto it = numbers_.find(n); it != numbers_.end()) return it->second;
        const auto digits = std::to_string(n);
        auto cells = translator_.translate(std::u32string(digits.begin(), digits.end()));
        if (!cells) {
            error_ = cells.error();
            return {};
        }
        return numbers_.emplace(n, std::move(*cells)).first->second;
    }

    // Transcriber-generated pages are numbered t1, t2, ..., front matter p1,
    // p2, ... (Braille Formats 2016 §2.2, §1.15), in the book's code.
    BrailleLine prelim_number(char prefix, int n) {
        const auto text = prefix + std::to_string(n);
        auto cells = translator_.translate(std::u32string(text.begin(), text.end()));
        if (!cells) {
            error_ = cells.error();
            return {};
        }
        return std::move(*cells);
    }

    Result<BrailleLine> braille(std::string_view utf8) {
        TACTUS_TRY(text, utf8_to_utf32(utf8));
        return translator_.translate(text);
    }

    // The blocks where volumes start: a volume ends at the last chapter or
    // section heading that keeps it within the target; a chapter longer than a
    // volume is divided at the block where the target is reached (§1.6).
    std::vector<std::size_t> volume_starts(const std::vector<std::size_t>& start_page, std::size_t total_pages) const {
        std::vector<std::size_t> starts{0};
        const std::size_t room = volume_body_room(book_, layout_.geometry);
        if (total_pages <= room) return starts;
        while (true) {
            const auto first = starts.back();
            const auto from = start_page[first];
            if (total_pages - from <= room) break;
            std::optional<std::size_t> best;
            for (std::size_t i = first + 1; i < blocks_.size(); ++i) {
                if (start_page[i] - from > room) break;
                const auto& b = doc_.blocks[i];
                if (b.kind == BlockKind::heading && b.level <= book_.split_level && start_page[i] > from) best = i;
            }
            if (!best) {
                // No heading in reach: the first block on the page past the target.
                for (std::size_t i = first + 1; i < blocks_.size(); ++i)
                    if (start_page[i] - from >= room && !document::is_table_kind(doc_.blocks[i].kind)) {
                        best = i;
                        break;
                    }
            }
            if (!best) break;
            starts.push_back(*best);
        }
        return starts;
    }

    void add_running_heads(std::vector<layout::Page>& pages) {
        auto head = braille(book_title());
        if (!head || head->empty()) return;
        const int width = layout_.geometry.cells_per_line - layout_.left_margin - layout_.right_margin;
        auto cells = *head;
        if (static_cast<int>(cells.size()) > width) cells.resize(static_cast<std::size_t>(width));
        const auto row = static_cast<std::size_t>(layout_.top_margin);
        BrailleLine line(static_cast<std::size_t>(layout_.left_margin + (width - static_cast<int>(cells.size())) / 2), Cell{});
        line.insert(line.end(), cells.begin(), cells.end());
        // Every body page after the volume's first (§1.8).
        for (std::size_t i = 1; i < pages.size(); ++i)
            if (row < pages[i].lines.size() && pages[i].lines[row].empty()) pages[i].lines[row] = line;
    }

    std::string book_title() const { return !book_.title.empty() ? book_.title : metadata(doc_, "title"); }

    // `title_pages`: how many of them are the title part (t-numbered, with its blank back).
    Result<std::vector<layout::Page>> preliminary_pages(std::size_t volume, std::size_t volumes,
                                                        std::size_t& title_pages) {
        std::vector<translate::TranslatedBlock> blocks;
        const auto line = [&](std::string_view text, BlockKind kind = BlockKind::heading, int level = 1) -> Result<void> {
            if (text.empty()) return {};
            document::Block b;
            b.kind = kind;
            b.level = level;
            b.spans.push_back(document::Span{std::string(text)});
            TACTUS_TRY(tb, translate::translate_block(b, translator_, layout::word_room(layout_, kind, level)));
            blocks.push_back(std::move(tb));
            return {};
        };
        if (book_.title_page) {
            // The title page (§2.3): title, author, transcriber, publisher and
            // year, the volume (§1.6); each line centred.
            const auto author = !book_.author.empty() ? book_.author : metadata(doc_, "creator");
            const auto publisher = !book_.publisher.empty() ? book_.publisher : metadata(doc_, "publisher");
            auto year = !book_.year.empty() ? book_.year : metadata(doc_, "date");
            if (year.size() > 4 && year[4] == '-') year = year.substr(0, 4);
            for (const auto& text : {book_title(), author.empty() ? std::string{} : "by " + author,
                                     book_.transcriber.empty() ? std::string{} : "Transcribed by " + book_.transcriber,
                                     publisher, year})
                TACTUS_TRY_VOID(line(text));
            if (volumes > 1)
                if (auto ok = line("Volume " + std::to_string(volume + 1) + " of " + std::to_string(volumes)); !ok)
                    return std::unexpected(ok.error());
        }
        std::vector<translate::TranslatedBlock> title_blocks = std::move(blocks);
        blocks.clear();
        if (book_.contents) {
            // The contents (§2.10): the whole book's in the first volume, each
            // later volume's own in it; an entry's print page, then its braille
            // page at the right margin, after guide dots.
            std::vector<const Heading*> entries;
            for (const auto& h : headings_)
                if (volume == 0 || h.volume == volume) entries.push_back(&h);
            if (!entries.empty()) {
                TACTUS_TRY_VOID(line("Contents"));
                for (const auto* h : entries) {
                    translate::TranslatedBlock b;
                    b.kind = BlockKind::braille;
                    TACTUS_TRY(lines, contents_entry(*h));
                    b.lines = std::move(lines);
                    blocks.push_back(std::move(b));
                }
            }
        }
        std::vector<layout::Page> pages;
        bool contents = false;
        for (const auto& [prefix, part] : {std::pair{'t', &title_blocks}, std::pair{'p', &blocks}}) {
            if (part->empty()) continue;
            // Each part starts on a new sheet, so its numbering matches the sheet's side.
            if (layout_.geometry.interpoint && pages.size() % 2 == 1) pages.push_back(blank_page());
            if (prefix == 'p') {
                title_pages = pages.size();
                contents = true;
            }
            layout::Paginator p(layout_, [this, prefix](int n) { return prelim_number(prefix, n); });
            for (const auto& b : *part) p.add(b);
            append(pages, std::move(p).finish().pages);
            if (error_) return std::unexpected(*error_);
        }
        if (pages.empty()) return pages;
        // The body starts on a new sheet: a blank back after an odd count.
        if (layout_.geometry.interpoint && pages.size() % 2 == 1) pages.push_back(blank_page());
        if (!contents) title_pages = pages.size();
        return pages;
    }

    Result<std::vector<BrailleLine>> contents_entry(const Heading& h) {
        const int width = layout_.geometry.cells_per_line - layout_.left_margin - layout_.right_margin;
        BrailleLine numbers;
        if (!h.print_page.empty()) {
            TACTUS_TRY(print, braille(h.print_page));
            numbers = print;
            numbers.push_back(Cell{});
        }
        const auto page = number(h.braille_page);
        numbers.insert(numbers.end(), page.begin(), page.end());
        const int indent = (std::clamp(h.level, 1, 6) - 1) * 2;
        // Text lines: wrapped at blanks, runover two cells further in.
        std::vector<BrailleLine> out;
        BrailleLine text = h.cells;
        while (!text.empty() && text.back().blank()) text.pop_back();
        const int last_room = width - static_cast<int>(numbers.size()) - 3;
        int first = indent;
        while (true) {
            const int room = std::max(4, (static_cast<int>(text.size()) + first <= last_room ? last_room : width) - first);
            if (static_cast<int>(text.size()) <= room && first + static_cast<int>(text.size()) <= last_room) break;
            std::size_t cut = std::min(text.size(), static_cast<std::size_t>(room));
            std::size_t blank = cut;
            while (blank > 0 && !text[blank - 1].blank()) --blank;
            if (blank > 1) cut = blank - 1;
            BrailleLine l(static_cast<std::size_t>(first), Cell{});
            l.insert(l.end(), text.begin(), text.begin() + static_cast<std::ptrdiff_t>(cut));
            out.push_back(std::move(l));
            std::size_t next = cut;
            while (next < text.size() && text[next].blank()) ++next;
            text.erase(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(next));
            first = indent + 2;
            if (text.empty()) break;
        }
        BrailleLine l(static_cast<std::size_t>(first), Cell{});
        l.insert(l.end(), text.begin(), text.end());
        const int dots_from = static_cast<int>(l.size()) + 1;
        const int numbers_at = width - static_cast<int>(numbers.size());
        l.push_back(Cell{});
        for (int c = dots_from; c < numbers_at - 1; ++c) l.push_back(kGuideDot);
        while (static_cast<int>(l.size()) < numbers_at) l.push_back(Cell{});
        l.insert(l.end(), numbers.begin(), numbers.end());
        if (static_cast<int>(l.size()) > width) l.resize(static_cast<std::size_t>(width));
        out.push_back(std::move(l));
        return out;
    }

    // A blank back for the embosser (Page::filler): the next part starts a sheet.
    [[nodiscard]] layout::Page blank_page() const {
        layout::Page blank;
        blank.lines.assign(static_cast<std::size_t>(layout_.geometry.lines_per_page), BrailleLine{});
        blank.filler = true;
        return blank;
    }

    static void append(std::vector<layout::Page>& to, std::vector<layout::Page> pages) {
        for (auto& p : pages) to.push_back(std::move(p));
    }

    const document::Document& doc_;
    layout::LayoutOptions layout_;
    layout::LayoutOptions body_;
    BookOptions book_;
    const translate::Translator& translator_;
    unsigned workers_;
    std::vector<translate::TranslatedBlock> blocks_;
    std::vector<Heading> headings_;
    std::map<int, BrailleLine> numbers_;
    std::optional<Error> error_;
    const BookProgress& progress_;
    bool stopped_ = false;
};

}  // namespace

Result<BookLayout> lay_out_book(const document::Document& document, const layout::LayoutOptions& layout,
                                const BookOptions& book, const translate::Translator& translator,
                                unsigned translation_workers) {
    auto laid = lay_out_book(document, layout, book, translator, BookProgress{}, translation_workers);
    if (!laid) return std::unexpected(laid.error());
    if (!laid->has_value()) return fail(ErrorKind::internal, "the book layout stopped with nothing to stop it");
    return std::move(laid->value());
}

Result<std::optional<BookLayout>> lay_out_book(const document::Document& document, const layout::LayoutOptions& layout,
                                               const BookOptions& book, const translate::Translator& translator,
                                               const BookProgress& progress, unsigned translation_workers) {
    if (book.sheets_per_volume < 2) return fail(ErrorKind::usage, "sheets per volume must be at least 2", "sheets-per-volume");
    return BookMaker(document, layout, book, translator, translation_workers, progress).make();
}

}  // namespace tactus::pipeline
