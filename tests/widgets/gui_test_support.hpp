// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers shared by the GUI tests: core/edit's fixtures, and the sample
// documents' paths as QString.
#include <QString>

#include "../common/edit_fixtures.hpp"

namespace tactus::test {

inline QString sample(const char* name) { return QString::fromStdString(sample_path(name)); }

}  // namespace tactus::test
