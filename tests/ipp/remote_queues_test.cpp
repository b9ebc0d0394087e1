// SPDX-License-Identifier: GPL-3.0-or-later
// What counts as a Tactus queue on a CUPS server (the picker's filter). The
// listing itself runs against a real cupsd in tests/cups/ipp_e2e_test.cpp.
#include "ipp/remote_queues.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>

namespace tactus::ipp {
namespace {

TEST(RemoteQueues, ATactusQueueRunsTheBackendOrWasMadeFromThePpd) {
    EXPECT_TRUE(is_tactus_queue("tactus:serial:/dev/ttyUSB0?baud=57600", ""));
    EXPECT_TRUE(
        is_tactus_queue("", "Tactus Braille Embosser"));  // device-uri hidden from this client
    EXPECT_FALSE(is_tactus_queue("ipp://laser.local/ipp/print", "HP LaserJet"));
    EXPECT_FALSE(is_tactus_queue("socket://10.0.0.9", "Local Raw Printer"));
    EXPECT_FALSE(is_tactus_queue("usb://Tactus", ""));  // a name is not the backend
}

TEST(RemoteQueues, AServerThatIsNotThereIsADeviceError) {
    // Port 1 on loopback: nothing listens there.
    const auto q = tactus_queues("127.0.0.1", 1);
    ASSERT_FALSE(q);
    EXPECT_EQ(q.error().kind, ErrorKind::device);
    EXPECT_EQ(q.error().where, "127.0.0.1:1");
}

TEST(RemoteQueues, WithNoCupsServerThePickersListIsADeviceErrorNamingIt) {
    // libcups reads CUPS_SERVER once per thread: a thread of its own sees this one.
    ::setenv("CUPS_SERVER", "127.0.0.1:1", 1);
    Result<std::vector<RemoteQueue>> q = std::vector<RemoteQueue>{};
    std::thread([&] { q = visible_tactus_queues(std::chrono::milliseconds(0)); }).join();
    ::unsetenv("CUPS_SERVER");
    ASSERT_FALSE(q);
    EXPECT_EQ(q.error().kind, ErrorKind::device);
    EXPECT_EQ(q.error().where, "127.0.0.1:1");
}

}  // namespace
}  // namespace tactus::ipp
