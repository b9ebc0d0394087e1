// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Unsaved work kept against a crash: while the document has changes, a copy
// is written every autosave/seconds (30 by default) into the app's data
// folder, with a JSON file beside it saying what it is a copy of and which
// Tactus wrote it. A copy no running Tactus owns is offered back at the next
// start.
#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>
#include <optional>

class QWidget;

namespace tactus::gui {

struct Recovery {
    QString autosave_path;  // the autosaved copy: the editor's lines (.md), or PEF for structured braille (.pef)
    QString document_path;  // what it was a copy of ("" when untitled)
    QString table;
    QDateTime saved_at;
    QString line_ending;  // a text file's ("\r\n", ...): it is saved with it again
    QString encoding;     // a text file's ("BIG5", ...): it is saved in it again
    bool byte_order_mark = false;
};

// What the JSON beside a copy records, to reopen it as it was.
struct AutosaveMeta {
    QString document_path;  // "" when untitled
    QString name;           // the file the document came from
    QString table;
    QString line_ending;
    QString encoding;
    bool byte_order_mark = false;
};

class Autosave : public QObject {
    Q_OBJECT
public:
    explicit Autosave(QObject* parent = nullptr);

    // Starts the timer at the autosave/seconds setting; `due` follows each time.
    void start();
    // Writes this window's copy, as PEF or as the editor's lines (the copy in
    // the other format is removed), then its JSON. False when either cannot
    // be written; `error` says why when it is the copy (the JSON is written
    // again with the next autosave).
    bool write(const QByteArray& bytes, bool as_pef, const AutosaveMeta& meta, QString* error);
    // Removes this window's copy: the work is saved or deliberately closed.
    void remove();
    [[nodiscard]] QString path() const { return path_; }

    // Copies that no running Tactus owns, newest first.
    [[nodiscard]] static QList<Recovery> pending();
    // Removes a copy and its JSON (recovered, or declined for good).
    static void discard(const Recovery& r);
    // Asks about each pending copy: the first the user recovers is returned;
    // one declined for good is discarded, one not recovered now is asked about
    // at the next start.
    static std::optional<Recovery> ask(QWidget* parent);

Q_SIGNALS:
    void due();

private:
    QString path_;
    QTimer timer_;
};

}  // namespace tactus::gui
