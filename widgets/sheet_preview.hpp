// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The interpoint sheet view: front dots raised (filled), back dots as embossed on
// the reverse (mirrored, offset, drawn hollow), a keyboard cell cursor that a
// screen reader hears as dot numbers and text, and warnings where a front and a
// back dot come closer than the profile allows.
#include <QString>
#include <QWidget>
#include <functional>

#include "layout/page.hpp"
#include "sheet_geometry.hpp"

class QAccessibleInterface;
class QPainter;

namespace tactus::gui {

enum class SideMode { front, back, both };

struct PaintOptions {
    SideMode mode = SideMode::both;
    bool high_contrast = false;
    int cursor_line = -1;  // on the cursor's side; -1: no cursor
    int cursor_cell = -1;
    bool cursor_on_back = false;
};

// Draws one sheet at `px_per_mm` on a painter (widget, PDF or image).
void paint_sheet(QPainter& p, const layout::Sheet& sheet, const SheetGeometry& g, const PaintOptions& o,
                 double px_per_mm);

class SheetPreview : public QWidget {
    Q_OBJECT
public:
    explicit SheetPreview(QWidget* parent = nullptr);

    // The document is borrowed: the owner calls set_document again after every change.
    void set_document(const layout::PagedDocument* doc);
    void set_geometry(const SheetGeometry& g);
    // What the graphic is (GraphicView::summary), said for a page that holds
    // a graphic's dots instead of its cells; empty for a text document.
    void set_graphic_summary(const QString& summary);
    // Dots drawn on the side shown (front, back, or the front with the back's
    // pits): the cells' and the graphic's, as a sighted reader counts them.
    [[nodiscard]] std::size_t shown_dot_count() const;
    void set_back_translator(std::function<QString(const document::BrailleLine&)> f) { back_translate_ = std::move(f); }
    // The print word that produced the cell at (page index, line, cell); the
    // back-translation is only the fallback when it gives nothing.
    void set_print_word(std::function<QString(std::size_t page, int line, int cell)> f) { print_word_ = std::move(f); }

    [[nodiscard]] std::size_t sheet() const { return sheet_; }
    [[nodiscard]] std::size_t sheet_count() const;
    [[nodiscard]] SideMode mode() const { return options_.mode; }
    [[nodiscard]] bool high_contrast() const { return options_.high_contrast; }
    [[nodiscard]] double zoom() const { return zoom_; }
    [[nodiscard]] const SheetGeometry& geometry() const { return geometry_; }
    [[nodiscard]] std::size_t conflict_count() const { return conflicts_.size(); }
    // The page the cell cursor is on (index into pages), or npos without pages.
    [[nodiscard]] std::size_t cursor_page() const;
    [[nodiscard]] int cursor_line() const { return options_.cursor_line; }
    [[nodiscard]] int cursor_cell() const { return options_.cursor_cell; }
    // What a screen reader hears for the cell under the cursor.
    [[nodiscard]] QString cursor_description() const;
    [[nodiscard]] QString summary() const;
    [[nodiscard]] const layout::PagedDocument* document() const;

    QSize sizeHint() const override;

public Q_SLOTS:
    void set_sheet(std::size_t sheet);
    void next_sheet();
    void previous_sheet();
    void set_mode(tactus::gui::SideMode mode);
    void set_high_contrast(bool on);
    void set_zoom(double zoom);
    void zoom_in() { set_zoom(zoom_ * 1.25); }
    void zoom_out() { set_zoom(zoom_ / 1.25); }
    // Moves the cell cursor to a page position (from the editor's cursor).
    void show_position(std::size_t page, int line, int cell);

Q_SIGNALS:
    void sheet_changed(std::size_t sheet, std::size_t count);
    void cursor_moved(const QString& description);

protected:
    void paintEvent(QPaintEvent*) override;
    void keyPressEvent(QKeyEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void focusInEvent(QFocusEvent*) override;
    void focusOutEvent(QFocusEvent*) override;

private:
    [[nodiscard]] double px_per_mm() const;
    [[nodiscard]] const layout::Page* cursor_side_page() const;
    void move_cursor(int dline, int dcell);
    void cursor_changed();
    void refresh();

    const layout::PagedDocument* doc_ = nullptr;
    QString graphic_summary_;
    SheetGeometry geometry_;
    PaintOptions options_;
    std::size_t sheet_ = 1;
    double zoom_ = 1.0;
    std::vector<DotConflict> conflicts_;
    std::function<QString(const document::BrailleLine&)> back_translate_;
    std::function<QString(std::size_t, int, int)> print_word_;
};

QAccessibleInterface* make_accessible_sheet_preview(SheetPreview* preview);

// Every sheet of the document, one PDF page each, as the preview shows it.
bool print_to_pdf(const layout::PagedDocument& doc, const SheetGeometry& g, SideMode mode,
                  const QString& path, QString* error);

}  // namespace tactus::gui
