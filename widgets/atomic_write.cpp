// SPDX-License-Identifier: GPL-3.0-or-later
#include "atomic_write.hpp"

#include <QDir>
#include <QObject>

#include <filesystem>
#include <string_view>

#include "common/file_io.hpp"

namespace tactus::gui {

bool write_atomically(const QString& path, const QByteArray& bytes, QString* error) {
    const std::filesystem::path file(path.toStdU16String());
    const auto written =
        write_file_atomic(file, std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (written) return true;
    const auto& e = written.error();
    const auto why = e.where.empty() || std::filesystem::path(e.where) == file ? e.message : e.to_string();
    *error = QObject::tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), QString::fromStdString(why));
    return false;
}

}  // namespace tactus::gui
