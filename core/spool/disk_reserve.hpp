// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Spare room beside the spool database. When the disk fills mid-job the runner
// can no longer record passes, and with no room at all it could not record why
// it stopped either: the job would stay "running" with nobody running it. The
// reserve is a file of zeros held while a printer is served; given back to the
// disk, it makes room for that one last write (the job paused, with "disk
// full" as its reason), then is taken again when there is room.
#include <cstddef>
#include <filesystem>

namespace tactus::spool {

class DiskReserve {
public:
    // Enough for SQLite's write-ahead log to take one state change and its
    // event (a few 4 KiB pages each) with room to spare.
    static constexpr std::size_t kDefaultBytes = 256 * 1024;

    DiskReserve() = default;
    DiskReserve(std::filesystem::path path, std::size_t bytes = kDefaultBytes);
    ~DiskReserve();
    DiskReserve(DiskReserve&& other) noexcept;
    DiskReserve& operator=(DiskReserve&& other) noexcept;
    DiskReserve(const DiskReserve&) = delete;
    DiskReserve& operator=(const DiskReserve&) = delete;

    // Writes the file in full; false (and no file) when the disk has no room.
    bool hold();
    // Gives the room back; true when there was a reserve to give.
    bool release();
    [[nodiscard]] bool held() const { return held_; }
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::size_t bytes_ = 0;
    bool held_ = false;
};

}  // namespace tactus::spool
