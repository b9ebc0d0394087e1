// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The rules of a plain text file's lines, in one place: the text importer
// (text_import.cpp) reads a file by them, and the editor's text dialect
// (edit/live_layout.cpp), which shows a .txt as its lines, makes the same
// paragraphs of them.
#include <string>
#include <string_view>
#include <vector>

namespace tactus::import {

// A blank line separates paragraphs: nothing but spaces, tabs and vertical tabs
// ("" too). A form feed is not blank: it is a print page break.
bool is_blank_text_line(std::string_view line);

// Calls fn(line, number) for each line of `utf8` (ended by LF, CRLF or a lone
// CR, the end left out; numbers from 1) until fn returns false. A line end at
// the end of the text starts no further line.
template <typename Fn>
void for_each_text_line(std::string_view utf8, Fn&& fn) {
    std::size_t start = 0;
    int number = 1;
    while (start < utf8.size()) {
        auto end = utf8.find_first_of("\r\n", start);
        if (end == std::string_view::npos) end = utf8.size();
        if (!fn(utf8.substr(start, end - start), number++)) return;
        if (end < utf8.size() && utf8[end] == '\r' && end + 1 < utf8.size() && utf8[end + 1] == '\n') ++end;
        start = end + 1;
    }
}

// The text as the lines an editor shows, so that joining them with one line
// end gives the text back: a text ending with a line end has an empty last
// line ("a\n" -> {"a", ""}; "" -> {""}).
std::vector<std::string> split_text_lines(std::string_view utf8);

// The line end a text is written with: its first one ("\n", "\r\n" or "\r");
// "\n" when it has none. A text with mixed line ends is written with its first.
std::string line_ending_of(std::string_view utf8);

// A text with no blank line between any two of its lines of text (a
// verse-per-line Bible, a word list, a poem) has no paragraph marks but its
// line ends, so each line is a paragraph; otherwise the lines of a paragraph
// run on until a blank line. Fed the lines in order; found() once a blank line
// has separated two lines of text.
class ParagraphBreaks {
public:
    // Returns found().
    bool line(std::string_view line);
    [[nodiscard]] bool found() const { return found_; }

private:
    bool seen_text_ = false;
    bool blank_after_text_ = false;
    bool found_ = false;
};

}  // namespace tactus::import
