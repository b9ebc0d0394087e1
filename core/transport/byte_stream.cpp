// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport/byte_stream.hpp"

#include <thread>

namespace tactus::transport {

double ByteStream::now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void ByteStream::sleep(std::chrono::microseconds duration) {
    std::this_thread::sleep_for(duration);
}

}  // namespace tactus::transport
