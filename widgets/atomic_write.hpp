// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Core's atomic write (common/file_io, the rule the CLI follows too) for the
// window's files: saves, exports and autosaves.
#include <QByteArray>
#include <QString>

namespace tactus::gui {

// Writes `bytes` to `path` whole or not at all. False with `error` set to what
// the user is told: the file, then what failed, and where when that is not
// the file itself (the temporary copy beside it).
bool write_atomically(const QString& path, const QByteArray& bytes, QString* error);

}  // namespace tactus::gui
