// SPDX-License-Identifier: GPL-3.0-or-later
#include "autosave.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>

#include "atomic_write.hpp"
#include "platform/process_info.hpp"

namespace tactus::gui {

namespace {

QString autosave_dir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/autosave");
}

}  // namespace

Autosave::Autosave(QObject* parent) : QObject(parent) { connect(&timer_, &QTimer::timeout, this, &Autosave::due); }

void Autosave::start() {
    timer_.setInterval(QSettings().value(QStringLiteral("autosave/seconds"), 30).toInt() * 1000);
    timer_.start();
}

bool Autosave::write(const QByteArray& bytes, bool as_pef, const AutosaveMeta& meta, QString* error) {
    QDir().mkpath(autosave_dir());
    if (path_.isEmpty())
        path_ = autosave_dir() + QStringLiteral("/%1-%2.md")
                                     .arg(static_cast<qint64>(platform::current_process_id()))
                                     .arg(QDateTime::currentMSecsSinceEpoch());
    const auto info = QFileInfo(path_);
    const auto path = info.path() + QLatin1Char('/') + info.completeBaseName() +
                      (as_pef ? QStringLiteral(".pef") : QStringLiteral(".md"));
    if (path != path_) {
        remove();  // the copy in the other format
        path_ = path;
    }
    if (!write_atomically(path_, bytes, error)) return false;
    const QJsonObject json{{QStringLiteral("pid"), static_cast<qint64>(platform::current_process_id())},
                           {QStringLiteral("path"), meta.document_path},
                           {QStringLiteral("name"), meta.name},
                           {QStringLiteral("table"), meta.table},
                           {QStringLiteral("line_ending"), meta.line_ending},
                           {QStringLiteral("encoding"), meta.encoding},
                           {QStringLiteral("byte_order_mark"), meta.byte_order_mark},
                           {QStringLiteral("time"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)}};
    QString json_error;  // not said: the next autosave writes it again
    return write_atomically(path_ + QStringLiteral(".json"), QJsonDocument(json).toJson(), &json_error);
}

void Autosave::remove() {
    if (path_.isEmpty()) return;
    QFile::remove(path_);
    QFile::remove(path_ + QStringLiteral(".json"));
    path_.clear();
}

QList<Recovery> Autosave::pending() {
    QList<Recovery> out;
    const QDir dir(autosave_dir());
    for (const auto& info :
         dir.entryInfoList({QStringLiteral("*.md.json"), QStringLiteral("*.pef.json")}, QDir::Files, QDir::Time)) {
        QFile f(info.absoluteFilePath());
        if (!f.open(QIODevice::ReadOnly)) continue;
        const auto meta = QJsonDocument::fromJson(f.readAll()).object();
        const auto pid = meta.value(QStringLiteral("pid")).toInteger();
        if (pid == platform::current_process_id() || platform::process_alive(pid)) continue;  // that Tactus is still running
        Recovery r;
        r.autosave_path = info.absoluteFilePath().chopped(5);
        if (!QFileInfo::exists(r.autosave_path)) continue;
        r.document_path = meta.value(QStringLiteral("path")).toString();
        r.table = meta.value(QStringLiteral("table")).toString();
        r.line_ending = meta.value(QStringLiteral("line_ending")).toString();
        r.encoding = meta.value(QStringLiteral("encoding")).toString();
        r.byte_order_mark = meta.value(QStringLiteral("byte_order_mark")).toBool();
        r.saved_at = QDateTime::fromString(meta.value(QStringLiteral("time")).toString(), Qt::ISODate);
        out << r;
    }
    return out;
}

void Autosave::discard(const Recovery& r) {
    QFile::remove(r.autosave_path);
    QFile::remove(r.autosave_path + QStringLiteral(".json"));
}

std::optional<Recovery> Autosave::ask(QWidget* parent) {
    for (const auto& r : pending()) {
        const auto name = r.document_path.isEmpty() ? tr("an untitled document") : QFileInfo(r.document_path).fileName();
        const auto answer = QMessageBox::question(
            parent, tr("Recover unsaved work"),
            tr("Tactus closed without saving %1 (autosaved %2). Recover it?")
                .arg(name, QLocale().toString(r.saved_at.toLocalTime(), QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::No | QMessageBox::Discard);
        if (answer == QMessageBox::Yes) return r;
        if (answer == QMessageBox::Discard) discard(r);
    }
    return std::nullopt;
}

}  // namespace tactus::gui
