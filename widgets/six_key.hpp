// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Perkins-style six-key entry on a computer keyboard: keys are held together as a
// chord and the cell is committed when the last key is released. Auto-repeat is
// ignored (a held chord is one cell). The default keys are S D F J K L for dots
// 3 2 1 4 5 6, the layout braille teachers know; the mapping is configurable.
#include <array>
#include <optional>
#include <set>

#include "document/cell.hpp"

namespace tactus::gui {

class SixKeyChord {
public:
    // keys[i] is the Qt key code for dot i + 1.
    using Mapping = std::array<int, 6>;
    static Mapping default_mapping();

    explicit SixKeyChord(Mapping mapping = default_mapping()) : mapping_(mapping) {}
    void set_mapping(const Mapping& mapping);
    [[nodiscard]] const Mapping& mapping() const { return mapping_; }

    // True when the key belongs to the chord (the caller swallows the event).
    [[nodiscard]] bool is_chord_key(int key) const;
    bool press(int key, bool auto_repeat);
    // The committed cell when this release ends the chord.
    std::optional<document::Cell> release(int key, bool auto_repeat);
    // Focus lost mid-chord: forget it rather than commit half a cell.
    void cancel();
    [[nodiscard]] bool active() const { return !held_.empty(); }

private:
    Mapping mapping_;
    std::set<int> held_;
    std::uint8_t dots_ = 0;
};

}  // namespace tactus::gui
