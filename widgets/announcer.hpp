// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Spoken messages for screen readers: progress, faults, results. Qt 6.4 has no
// announcement event, so the announcer is an accessible object with the
// Notification role; each message changes its name and fires ObjectShow, which
// AT-SPI screen readers (Orca) speak as a live notification.
#include <QString>
#include <QWidget>

namespace tactus::gui {

class Announcer : public QWidget {
    Q_OBJECT
public:
    explicit Announcer(QWidget* parent = nullptr);
    [[nodiscard]] const QString& message() const { return message_; }
    [[nodiscard]] int count() const { return count_; }

public Q_SLOTS:
    void announce(const QString& message);

Q_SIGNALS:
    void announced(const QString& message);

private:
    QString message_;
    int count_ = 0;
};

// Registers the accessible interfaces of Tactus's custom widgets. Call once,
// after QApplication exists.
void install_accessibility();

}  // namespace tactus::gui
