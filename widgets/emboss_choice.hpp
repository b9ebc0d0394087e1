// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What Ctrl+P embosses, on the printer panel: the whole document, one volume
// of a book, or a range of braille pages named as the pages number them
// ("3-10", "5-", "p1-p2"; pipeline::parse_page_range, the CLI's --pages rule).
// The choice is said as it is made ("Pages 3 to 10: 4 sheets", on Enter or on
// leaving the range; typing a range chooses it), and a range that names no
// page says why.
#include <QString>
#include <QWidget>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "common/result.hpp"
#include "layout/page.hpp"
#include "pipeline/book_layout.hpp"

class QComboBox;
class QLabel;
class QLineEdit;

namespace tactus::gui {

class EmbossChoice : public QWidget {
    Q_OBJECT
public:
    explicit EmbossChoice(QWidget* parent = nullptr);

    // The pages Ctrl+P would send: their labels (pipeline::page_labels), the
    // book's volumes (none: a document in one), and the page geometry (for
    // the sheet count said).
    void set_pages(std::vector<std::string> labels, std::vector<pipeline::VolumeRange> volumes,
                   const layout::PageGeometry& geometry);

    // 0: the whole document; 1..N: that volume; N+1: a page range.
    void choose_whole();
    void choose_volume(std::size_t volume);  // 0-based
    void choose_range(const QString& range);

    // The chosen pages as 1-based page indices, first and last inclusive
    // ({0, 0}: all), or why the range names no pages.
    [[nodiscard]] Result<std::pair<std::size_t, std::size_t>> chosen() const;
    // What the choice says ("Whole document: 40 sheets", "Volume 2 of 3: ...").
    [[nodiscard]] QString summary() const;

Q_SIGNALS:
    void changed();
    // The choice the user just made, to be heard ("Pages 3 to 10: 4 sheets").
    void said(const QString& text);

private:
    void update_choices();
    void update_summary();

    std::vector<std::string> labels_;
    std::vector<pipeline::VolumeRange> volumes_;
    layout::PageGeometry geometry_;
    QComboBox* scope_;
    QLineEdit* range_;
    QLabel* summary_;
    QString said_range_;  // the range last said
};

}  // namespace tactus::gui
