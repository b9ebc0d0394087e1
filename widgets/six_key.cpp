// SPDX-License-Identifier: GPL-3.0-or-later
#include "six_key.hpp"

#include <Qt>
#include <algorithm>

namespace tactus::gui {

SixKeyChord::Mapping SixKeyChord::default_mapping() {
    return {Qt::Key_F, Qt::Key_D, Qt::Key_S, Qt::Key_J, Qt::Key_K, Qt::Key_L};
}

void SixKeyChord::set_mapping(const Mapping& mapping) {
    mapping_ = mapping;
    cancel();
}

bool SixKeyChord::is_chord_key(int key) const {
    return std::ranges::find(mapping_, key) != mapping_.end();
}

bool SixKeyChord::press(int key, bool auto_repeat) {
    const auto it = std::ranges::find(mapping_, key);
    if (it == mapping_.end()) return false;
    if (auto_repeat) return true;
    held_.insert(key);
    dots_ = static_cast<std::uint8_t>(dots_ | (1u << (it - mapping_.begin())));
    return true;
}

std::optional<document::Cell> SixKeyChord::release(int key, bool auto_repeat) {
    if (auto_repeat || !held_.erase(key) || !held_.empty()) return std::nullopt;
    const document::Cell cell{dots_};
    dots_ = 0;
    return cell;
}

void SixKeyChord::cancel() {
    held_.clear();
    dots_ = 0;
}

}  // namespace tactus::gui
