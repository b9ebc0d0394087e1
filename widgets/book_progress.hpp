// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The book layout's progress in the status bar: a bar and a Cancel button,
// shown while BookView lays the book out in the background. The screen reader
// hears it as the app's other long jobs: steps by ProgressSteps' rule (a
// tenth at most every few seconds), and only when the layout lasts (a book
// laid out again after each edit must not chatter). The end is said when a
// step was ("Book: 2 volumes, 105 sheets"), and a document just opened as a
// book is said opened then, with the book's count ("Opened x.epub: 2
// volumes, 105 sheets"): one message, not two that cut each other off.
#include <QElapsedTimer>
#include <QWidget>
#include <functional>
#include <memory>
#include <optional>
#include <string>

class QProgressBar;
class QToolButton;

namespace tactus::gui {

class Announcer;
class BookView;
class ProgressSteps;

class BookProgress : public QWidget {
    Q_OBJECT
public:
    // `say_end`: how the end is said (the window's report: shown and announced).
    BookProgress(BookView* book, Announcer* announcer, std::function<void(const QString&)> say_end,
                 QWidget* parent = nullptr);
    ~BookProgress() override;
    // A step is said only after the layout has run this long (ms).
    void set_quiet_start(int ms) { quiet_ms_ = ms; }
    [[nodiscard]] QToolButton* cancel_button() const { return cancel_; }
    // A document was opened and its book is being laid out: said open when
    // the book is ready, with the book's count; `plain` (the editor's count)
    // if it is not laid out.
    void opened(const QString& file_name, const QString& plain, const QString& suffix);
    // Another document replaces it before its book is said.
    void forget_opened() { opened_.reset(); }

private:
    void on_started();
    void on_progress(int percent);
    void on_ended(bool done);

    BookView* book_;
    Announcer* announcer_;
    QProgressBar* bar_;
    QToolButton* cancel_;
    std::unique_ptr<ProgressSteps> steps_;
    QElapsedTimer running_;
    int quiet_ms_ = 1000;
    bool spoke_ = false;
    std::function<void(const QString&)> say_end_;
    struct Opened {
        QString file_name, plain, suffix;
    };
    std::optional<Opened> opened_;
};

}  // namespace tactus::gui
