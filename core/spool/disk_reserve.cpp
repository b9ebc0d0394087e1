// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/disk_reserve.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <system_error>
#include <utility>

namespace tactus::spool {

DiskReserve::DiskReserve(std::filesystem::path path, std::size_t bytes)
    : path_(std::move(path)), bytes_(bytes) {}

DiskReserve::~DiskReserve() { release(); }

DiskReserve::DiskReserve(DiskReserve&& other) noexcept
    : path_(std::move(other.path_)), bytes_(other.bytes_), held_(std::exchange(other.held_, false)) {}

DiskReserve& DiskReserve::operator=(DiskReserve&& other) noexcept {
    if (this != &other) {
        release();
        path_ = std::move(other.path_);
        bytes_ = other.bytes_;
        held_ = std::exchange(other.held_, false);
    }
    return *this;
}

bool DiskReserve::hold() {
    if (held_) return true;
    if (path_.empty() || bytes_ == 0) return false;
    {
        // Zeros written out, not a sparse file or a bare length: only written
        // blocks are the disk's room taken, and only they come back.
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        static constexpr std::array<char, 64 * 1024> kZeros{};
        for (std::size_t left = bytes_; out && left > 0;) {
            const auto n = std::min(left, kZeros.size());
            out.write(kZeros.data(), static_cast<std::streamsize>(n));
            left -= n;
        }
        out.close();  // a full disk may refuse only here, when the buffer is written
        if (out) {
            held_ = true;
            return true;
        }
    }
    std::error_code ec;
    std::filesystem::remove(path_, ec);
    return false;
}

bool DiskReserve::release() {
    if (!held_) return false;
    held_ = false;
    std::error_code ec;
    return std::filesystem::remove(path_, ec);
}

}  // namespace tactus::spool
