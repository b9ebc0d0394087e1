// SPDX-License-Identifier: GPL-3.0-or-later
#include "sheet_preview.hpp"

#include <QAccessible>
#include <QAccessibleWidget>
#include <QKeyEvent>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QPixmap>
#include <QRadialGradient>
#include <algorithm>
#include <cmath>

#include "text_units.hpp"

namespace tactus::gui {
namespace {

struct Palette {
    QColor paper, front, back, conflict, cursor, text;
};

Palette palette_for(bool high_contrast) {
    if (high_contrast)
        return {Qt::black, QColor(255, 255, 0), Qt::white, QColor(255, 0, 255), QColor(0, 255, 255), Qt::white};
    return {QColor(253, 252, 247), QColor(40, 40, 40), QColor(110, 110, 150), QColor(200, 0, 0),
            QColor(0, 90, 200), QColor(60, 60, 60)};
}

QString cell_text(document::Cell c) { return QString::fromStdString(document::dot_numbers(c)); }

// One dot drawn once per size and look, then blitted: a sheet holds thousands of
// dots and the preview repaints on every keystroke.
QPixmap dot_sprite(double radius, bool raised, const Palette& pal, bool high_contrast) {
    const int size = static_cast<int>(std::ceil(2 * radius + 4));
    QPixmap pm(size, size);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    const QPointF c(size / 2.0, size / 2.0);
    if (raised) {
        p.setPen(Qt::NoPen);
        if (high_contrast) {
            p.setBrush(pal.front);
        } else {
            QRadialGradient grad(c - QPointF(radius / 3, radius / 3), radius * 1.2);  // lit from the top left
            grad.setColorAt(0, QColor(170, 170, 170));
            grad.setColorAt(1, pal.front);
            p.setBrush(grad);
        }
        p.drawEllipse(c, radius, radius);
    } else {
        p.setPen(QPen(pal.back, std::max(1.0, radius * 0.35)));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(c, radius * 0.9, radius * 0.9);
    }
    return pm;
}

}  // namespace

void paint_sheet(QPainter& p, const layout::Sheet& sheet, const SheetGeometry& g, const PaintOptions& o,
                 double s) {
    const auto pal = palette_for(o.high_contrast);
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(QRectF(0, 0, g.paper_width_mm() * s, g.paper_height_mm() * s), pal.paper);
    const double r = g.dot_diameter_mm() / 2 * s;

    // Heading line so a sighted proofreader knows which sheet and sides they see.
    p.setPen(pal.text);
    QFont f = p.font();
    f.setPixelSize(std::max(8, static_cast<int>(4.0 * s)));
    p.setFont(f);
    const auto label = [](const layout::Page* page) {
        return page ? QString::number(page->braille_number) : QStringLiteral("-");
    };
    const QString side = o.mode == SideMode::front ? QObject::tr("front")
                         : o.mode == SideMode::back ? QObject::tr("back, as read after turning the sheet")
                                                    : QObject::tr("front and back");
    p.drawText(QPointF(g.profile.paper.margin_left_mm * s, 10.0 * s),
               QObject::tr("Sheet %1 (%2) - pages %3 / %4")
                   .arg(sheet.number)
                   .arg(side, label(sheet.front), label(sheet.back)));

    const auto blit = [&p](const QPixmap& sprite, double x, double y) {
        p.drawPixmap(QPointF(x - sprite.width() / 2.0, y - sprite.height() / 2.0), sprite);
    };
    if (o.mode == SideMode::both && sheet.back) {
        // Recessed: the back's dots are pits seen from the front, drawn hollow.
        const auto pit = dot_sprite(r, false, pal, o.high_contrast);
        for (const auto& d : back_dots(*sheet.back, g)) blit(pit, d.x_mm * s, d.y_mm * s);
    }
    const layout::Page* shown = o.mode == SideMode::back ? sheet.back : sheet.front;
    if (shown) {
        const auto bump = dot_sprite(r, true, pal, o.high_contrast);
        for (const auto& d : front_dots(*shown, g)) blit(bump, d.x_mm * s, d.y_mm * s);
    }
    if (o.mode == SideMode::both) {
        p.setPen(QPen(pal.conflict, std::max(1.5, 0.4 * s)));
        p.setBrush(Qt::NoBrush);
        for (const auto& c : find_conflicts(sheet, g)) {
            const QPointF m((c.front.place.paper_x_mm + c.back.place.paper_x_mm) / 2 * s,
                            (c.front.place.paper_y_mm + c.back.place.paper_y_mm) / 2 * s);
            p.drawEllipse(m, 2.2 * r, 2.2 * r);
        }
    }
    if (o.cursor_line >= 0 && o.cursor_cell >= 0) {
        const bool mirrored = o.cursor_on_back && o.mode == SideMode::both;
        const auto origin = cell_origin(o.cursor_line, o.cursor_cell, mirrored, g);
        const double w = g.dot_pitch_mm() + g.dot_diameter_mm() + 0.6;
        const double h = 2 * g.dot_pitch_mm() + g.dot_diameter_mm() + 0.6;
        const double left = mirrored ? origin.x_mm - g.dot_pitch_mm() - (g.dot_diameter_mm() + 0.6) / 2
                                     : origin.x_mm - (g.dot_diameter_mm() + 0.6) / 2;
        p.setPen(QPen(pal.cursor, std::max(2.0, 0.45 * s)));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(left * s, (origin.y_mm - (g.dot_diameter_mm() + 0.6) / 2) * s, w * s, h * s));
    }
    p.restore();
}

SheetPreview::SheetPreview(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("sheetPreview"));
    setFocusPolicy(Qt::StrongFocus);
    setAccessibleName(tr("Interpoint preview"));
    setAccessibleDescription(tr("Arrow keys move between cells; Page Up and Page Down change sheet"));
    options_.cursor_line = 0;
    options_.cursor_cell = 0;
    geometry_ = sheet_geometry(profile::default_profile());
}

std::size_t SheetPreview::sheet_count() const { return doc_ ? std::max<std::size_t>(1, doc_->sheet_count()) : 0; }

double SheetPreview::px_per_mm() const { return 3.0 * zoom_; }

QSize SheetPreview::sizeHint() const {
    return {static_cast<int>(geometry_.paper_width_mm() * px_per_mm()),
            static_cast<int>(geometry_.paper_height_mm() * px_per_mm())};
}

void SheetPreview::set_document(const layout::PagedDocument* doc) {
    doc_ = doc;
    sheet_ = std::clamp<std::size_t>(sheet_, 1, std::max<std::size_t>(1, sheet_count()));
    refresh();
}

void SheetPreview::set_graphic_summary(const QString& summary) {
    graphic_summary_ = summary;
    cursor_changed();
}

std::size_t SheetPreview::shown_dot_count() const {
    if (!doc_ || doc_->pages.empty()) return 0;
    const auto sheet = doc_->sheet(sheet_);
    std::size_t n = 0;
    if (const auto* front = options_.mode == SideMode::back ? sheet.back : sheet.front) n += front_dots(*front, geometry_).size();
    if (options_.mode == SideMode::both && sheet.back) n += back_dots(*sheet.back, geometry_).size();
    return n;
}

void SheetPreview::set_geometry(const SheetGeometry& g) {
    geometry_ = g;
    updateGeometry();
    resize(sizeHint());
    refresh();
}

void SheetPreview::refresh() {
    conflicts_.clear();
    if (doc_ && sheet_count() > 0) conflicts_ = find_conflicts(doc_->sheet(sheet_), geometry_);
    update();
}

void SheetPreview::set_sheet(std::size_t sheet) {
    if (!doc_) return;
    sheet = std::clamp<std::size_t>(sheet, 1, std::max<std::size_t>(1, sheet_count()));
    if (sheet == sheet_) return;
    sheet_ = sheet;
    refresh();
    Q_EMIT sheet_changed(sheet_, sheet_count());
    cursor_changed();
}

void SheetPreview::next_sheet() { set_sheet(sheet_ + 1); }
void SheetPreview::previous_sheet() { set_sheet(sheet_ > 1 ? sheet_ - 1 : 1); }

void SheetPreview::set_mode(SideMode mode) {
    options_.mode = mode;
    if (mode == SideMode::back) options_.cursor_on_back = true;
    if (mode == SideMode::front) options_.cursor_on_back = false;
    update();
    cursor_changed();
}

void SheetPreview::set_high_contrast(bool on) {
    options_.high_contrast = on;
    update();
}

void SheetPreview::set_zoom(double zoom) {
    zoom_ = std::clamp(zoom, 0.25, 8.0);
    updateGeometry();
    resize(sizeHint());
    update();
}

std::size_t SheetPreview::cursor_page() const {
    if (!doc_ || doc_->pages.empty()) return static_cast<std::size_t>(-1);
    const auto s = doc_->sheet(sheet_);
    const layout::Page* p = options_.cursor_on_back ? s.back : s.front;
    if (!p) p = s.front;
    return static_cast<std::size_t>(p - doc_->pages.data());
}

const layout::Page* SheetPreview::cursor_side_page() const {
    if (!doc_ || doc_->pages.empty()) return nullptr;
    const auto s = doc_->sheet(sheet_);
    return options_.cursor_on_back ? s.back : s.front;
}

void SheetPreview::show_position(std::size_t page, int line, int cell) {
    if (!doc_ || page >= doc_->pages.size()) return;
    const auto sheet = doc_->geometry.sheet_of_page(page);
    options_.cursor_on_back = doc_->geometry.page_is_back(page);
    if (options_.mode == SideMode::front && options_.cursor_on_back) options_.mode = SideMode::both;
    if (options_.mode == SideMode::back && !options_.cursor_on_back) options_.mode = SideMode::both;
    options_.cursor_line = line;
    options_.cursor_cell = cell;
    if (sheet != sheet_) {
        sheet_ = sheet;
        refresh();
        Q_EMIT sheet_changed(sheet_, sheet_count());
    }
    update();
    cursor_changed();
}

QString SheetPreview::cursor_description() const {
    const layout::Page* page = cursor_side_page();
    const QString where = tr("Sheet %1 %2, line %3, cell %4")
                              .arg(sheet_)
                              .arg(options_.cursor_on_back ? tr("back") : tr("front"))
                              .arg(options_.cursor_line + 1)
                              .arg(options_.cursor_cell + 1);
    if (!page) return where + tr(": no page");
    if (!page->graphic.empty()) {
        // A graphic has no cells to walk: the side, and what the graphic is.
        const auto what = graphic_summary_.isEmpty()
                              ? tr("Graphic: %n dot(s).", nullptr, static_cast<int>(page->graphic.size()))
                              : QString(graphic_summary_).replace(QLatin1Char('\n'), QLatin1Char(' '));
        return tr("Sheet %1 %2: %3", "a sheet, its side, what its graphic is")
            .arg(sheet_)
            .arg(options_.cursor_on_back ? tr("back") : tr("front"), what);
    }
    const auto l = static_cast<std::size_t>(options_.cursor_line);
    const auto c = static_cast<std::size_t>(options_.cursor_cell);
    if (l >= page->lines.size() || c >= page->lines[l].size() || page->lines[l][c].blank())
        return where + tr(": blank");
    const auto& line = page->lines[l];
    QString text = tr("%1: %2", "a cell's place and its dots").arg(where, tr("dots %1").arg(cell_text(line[c])));
    if (print_word_) {
        const auto interpoint = doc_ && doc_->geometry.interpoint;
        const std::size_t index = interpoint ? 2 * (sheet_ - 1) + (options_.cursor_on_back ? 1 : 0) : sheet_ - 1;
        if (const auto word = print_word_(index, options_.cursor_line, options_.cursor_cell); !word.isEmpty())
            return text + tr(", in the word \u201c%1\u201d").arg(word);
    }
    if (back_translate_) {
        std::size_t a = c, b = c;
        while (a > 0 && !line[a - 1].blank()) --a;
        while (b + 1 < line.size() && !line[b + 1].blank()) ++b;
        const document::BrailleLine word(line.begin() + static_cast<std::ptrdiff_t>(a),
                               line.begin() + static_cast<std::ptrdiff_t>(b + 1));
        text += tr(", in the word \u201c%1\u201d").arg(back_translate_(word));
    }
    return text;
}

QString SheetPreview::summary() const {
    if (!doc_) return tr("No document");
    QString s = tr("Sheet %1 of %2").arg(sheet_).arg(sheet_count());
    if (!conflicts_.empty())
        s += tr("; %n front and back dots too close", nullptr, static_cast<int>(conflicts_.size()));
    return s;
}

void SheetPreview::cursor_changed() {
    const auto text = cursor_description();
    if (QAccessible::isActive()) {
        QAccessibleEvent desc(this, QAccessible::DescriptionChanged);
        QAccessible::updateAccessibility(&desc);
        QAccessibleTextCursorEvent caret(this, options_.cursor_cell);
        QAccessible::updateAccessibility(&caret);
    }
    Q_EMIT cursor_moved(text);
}

void SheetPreview::move_cursor(int dline, int dcell) {
    const auto& g = doc_ ? doc_->geometry : layout::PageGeometry{};
    options_.cursor_line = std::clamp(options_.cursor_line + dline, 0, g.lines_per_page - 1);
    options_.cursor_cell = std::clamp(options_.cursor_cell + dcell, 0, g.cells_per_line - 1);
    update();
    cursor_changed();
}

void SheetPreview::keyPressEvent(QKeyEvent* e) {
    const auto& g = doc_ ? doc_->geometry : layout::PageGeometry{};
    switch (e->key()) {
        case Qt::Key_Left: move_cursor(0, -1); break;
        case Qt::Key_Right: move_cursor(0, 1); break;
        case Qt::Key_Up: move_cursor(-1, 0); break;
        case Qt::Key_Down: move_cursor(1, 0); break;
        case Qt::Key_Home: move_cursor(0, -g.cells_per_line); break;
        case Qt::Key_End: move_cursor(0, g.cells_per_line); break;
        case Qt::Key_PageDown: next_sheet(); break;
        case Qt::Key_PageUp: previous_sheet(); break;
        case Qt::Key_Plus: case Qt::Key_Equal: zoom_in(); break;
        case Qt::Key_Minus: zoom_out(); break;
        case Qt::Key_Space:
            // Space turns the cursor to the other side of the sheet.
            if (doc_ && doc_->geometry.interpoint) {
                options_.cursor_on_back = !options_.cursor_on_back;
                if (options_.mode != SideMode::both)
                    options_.mode = options_.cursor_on_back ? SideMode::back : SideMode::front;
                update();
                cursor_changed();
            }
            break;
        default: QWidget::keyPressEvent(e); return;
    }
    e->accept();
}

void SheetPreview::mousePressEvent(QMouseEvent* e) {
    setFocus(Qt::MouseFocusReason);
    const double s = px_per_mm();
    const bool mirrored = options_.cursor_on_back && options_.mode == SideMode::both;
    const auto at = plan::cell_at(geometry_.profile, mirrored ? plan::Side::back : plan::Side::front,
                                  e->position().x() / s, e->position().y() / s);
    options_.cursor_line = std::max(0, at.line);
    options_.cursor_cell = std::max(0, at.cell);
    move_cursor(0, 0);
}

void SheetPreview::focusInEvent(QFocusEvent* e) {
    QWidget::focusInEvent(e);
    update();
    // Only the accessible description and caret: the screen reader reads them with
    // the focus. Announcing the cell too said it twice and, when the focus came
    // back after a dialog, replaced the dialog's result before it was heard.
    if (QAccessible::isActive()) {
        QAccessibleEvent desc(this, QAccessible::DescriptionChanged);
        QAccessible::updateAccessibility(&desc);
        QAccessibleTextCursorEvent caret(this, options_.cursor_cell);
        QAccessible::updateAccessibility(&caret);
    }
}

void SheetPreview::focusOutEvent(QFocusEvent* e) {
    QWidget::focusOutEvent(e);
    update();
}

void SheetPreview::paintEvent(QPaintEvent*) {
    QPainter p(this);
    if (!doc_ || doc_->pages.empty()) {
        p.fillRect(rect(), palette().window());
        p.drawText(rect(), Qt::AlignCenter, tr("No document"));
        return;
    }
    auto shown = options_;
    // A graphic's side has no cells: no cell cursor on it.
    if (const auto* page = cursor_side_page(); page && !page->graphic.empty()) shown.cursor_line = shown.cursor_cell = -1;
    paint_sheet(p, doc_->sheet(sheet_), geometry_, shown, px_per_mm());
    if (hasFocus()) {
        // A visible focus frame for keyboard users, beyond the cell cursor.
        p.setPen(QPen(palette().highlight(), 3));
        p.drawRect(rect().adjusted(1, 1, -2, -2));
    }
}

// The preview reads like a one-line text whose characters are the cells of the
// cursor's line (Unicode braille), so a screen reader speaks the cell the caret is
// on; the description carries dot numbers and the word in print.
class AccessibleSheetPreview : public QAccessibleWidget, public QAccessibleTextInterface {
public:
    explicit AccessibleSheetPreview(SheetPreview* w) : QAccessibleWidget(w, QAccessible::Graphic) {}
    SheetPreview* preview() const { return static_cast<SheetPreview*>(widget()); }

    void* interface_cast(QAccessible::InterfaceType t) override {
        if (t == QAccessible::TextInterface) return static_cast<QAccessibleTextInterface*>(this);
        return QAccessibleWidget::interface_cast(t);
    }
    QString text(QAccessible::Text t) const override {
        if (t == QAccessible::Description) return preview()->cursor_description();
        if (t == QAccessible::Value) return preview()->summary();
        return QAccessibleWidget::text(t);
    }

    QString line_text() const {
        const auto* w = preview();
        const auto page = w->cursor_page();
        const auto* doc = doc_of(w);
        if (!doc || page >= doc->pages.size()) return {};
        const auto l = static_cast<std::size_t>(std::max(0, w->cursor_line()));
        const auto& lines = doc->pages[page].lines;
        if (l >= lines.size()) return {};
        auto line = lines[l];
        line.resize(static_cast<std::size_t>(doc->geometry.cells_per_line));
        return QString::fromStdString(document::to_unicode_text(line));
    }
    static const layout::PagedDocument* doc_of(const SheetPreview* w) { return w->document(); }

    // QAccessibleTextInterface
    void selection(int, int* start, int* end) const override { *start = *end = 0; }
    int selectionCount() const override { return 0; }
    void addSelection(int, int) override {}
    void removeSelection(int) override {}
    void setSelection(int, int, int) override {}
    int cursorPosition() const override { return std::max(0, preview()->cursor_cell()); }
    void setCursorPosition(int position) override {
        preview()->show_position(preview()->cursor_page(), preview()->cursor_line(), position);
    }
    QString text(int start, int end) const override { return line_text().mid(start, end - start); }
    int characterCount() const override { return static_cast<int>(line_text().size()); }
    QRect characterRect(int) const override { return rect(); }
    int offsetAtPoint(const QPoint&) const override { return cursorPosition(); }
    void scrollToSubstring(int, int) override {}
    QString attributes(int offset, int* start, int* end) const override {
        *start = offset;
        *end = offset + 1;
        return {};
    }
    // Qt's fallback for these loops for ever on a line of braille cells.
    QString textAtOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_at_offset(line_text(), offset, b, start, end);
    }
    QString textBeforeOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_before_offset(line_text(), offset, b, start, end);
    }
    QString textAfterOffset(int offset, QAccessible::TextBoundaryType b, int* start, int* end) const override {
        return text_after_offset(line_text(), offset, b, start, end);
    }
};

const layout::PagedDocument* SheetPreview::document() const { return doc_; }

QAccessibleInterface* make_accessible_sheet_preview(SheetPreview* preview) {
    return new AccessibleSheetPreview(preview);
}

bool print_to_pdf(const layout::PagedDocument& doc, const SheetGeometry& g, SideMode mode,
                  const QString& path, QString* error) {
    QPdfWriter pdf(path);
    pdf.setTitle(QObject::tr("Tactus interpoint proof"));
    pdf.setCreator(QStringLiteral("Tactus"));
    pdf.setResolution(300);
    pdf.setPageSize(QPageSize(QSizeF(g.paper_width_mm(), g.paper_height_mm()), QPageSize::Millimeter));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter);
    QPainter p;
    if (!p.begin(&pdf)) {
        if (error) *error = QObject::tr("Cannot write %1").arg(path);
        return false;
    }
    const double s = 300.0 / 25.4;
    PaintOptions o;
    o.mode = mode;
    for (std::size_t n = 1; n <= std::max<std::size_t>(1, doc.sheet_count()); ++n) {
        if (n > 1) pdf.newPage();
        paint_sheet(p, doc.sheet(n), g, o, s);
    }
    if (!p.end()) {
        if (error) *error = QObject::tr("Cannot finish %1").arg(path);
        return false;
    }
    return true;
}

}  // namespace tactus::gui
