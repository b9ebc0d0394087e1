// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Styles > Language...: the language a passage of the print text is marked
// in, chosen from those Tactus has a braille table for
// (translate::passage_languages), or the document's own. A passage so marked
// is translated with its language's table (docs/editor.md, "Languages").
#include <QString>
#include <optional>

class QWidget;

namespace tactus::gui {

struct LanguageChoice {
    QString tag;             // BCP 47; "" = the document's own language
    bool paragraph = false;  // the whole paragraph, not the selection or word
};

// Asks for a language, `current` (a tag, "" = the document's own) chosen at
// first; nullopt when cancelled.
std::optional<LanguageChoice> ask_language(QWidget* parent, const QString& current);

// A tag's name in the interface language ("zh-TW" -> "Chinese (Taiwan)",
// "中文（台灣）" in a Chinese interface); "" for "".
QString language_name(const QString& tag);

// What the status bar shows and a screen reader hears for the language at
// the cursor: "Language: Chinese (Taiwan)"; "" for the document's own.
QString language_status(const QString& tag);

// What is said when a language is set: "Language: Chinese (Taiwan)" or
// "Language: document default".
QString language_set_text(const QString& tag);

}  // namespace tactus::gui
