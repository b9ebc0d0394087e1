// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers shared by the GUI tests: core/edit's fixtures, and the sample
// documents' paths as QString.
#include <QElapsedTimer>
#include <QSettings>
#include <QString>
#include <string>
#include <QTest>

#include "../common/edit_fixtures.hpp"

namespace tactus::test {

inline QString sample(const char* name) { return QString::fromStdString(sample_path(name)); }

// A spool file of its own for each test (TACTUS_SPOOL_DB, in `dir`), and no
// remembered embosser: each test starts on the built-in simulator.
inline std::string fresh_spool(const QString& dir) {
    static int n = 0;
    const auto db = (dir + QStringLiteral("/spool-%1.db").arg(++n)).toStdString();
    qputenv("TACTUS_SPOOL_DB", QByteArray::fromStdString(db));
    QSettings().clear();
    return db;
}

// Processes events until `pred` holds; false after `ms` (a bound, not a timing assert).
template <typename Pred>
bool wait_until(Pred pred, int ms = 120000) {
    QElapsedTimer t;
    t.start();
    while (!pred()) {
        if (t.elapsed() > ms) return false;
        QTest::qWait(20);
    }
    return true;
}

}  // namespace tactus::test
