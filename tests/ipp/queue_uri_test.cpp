// SPDX-License-Identifier: GPL-3.0-or-later
// The address of a CUPS queue, as `tactus-cli emboss --device` takes it.
#include "ipp/queue_uri.hpp"

#include <gtest/gtest.h>

namespace tactus::ipp {
namespace {

TEST(QueueUri, SplitsHostPortAndQueue) {
    const auto q = parse_queue_uri("ipp://school-server:8631/printers/Embosser");
    ASSERT_TRUE(q) << q.error().to_string();
    EXPECT_EQ(q->host, "school-server");
    EXPECT_EQ(q->port, 8631);
    EXPECT_EQ(q->resource, "/printers/Embosser");
    EXPECT_FALSE(q->tls);
    EXPECT_EQ(q->uri, "ipp://school-server:8631/printers/Embosser");
}

TEST(QueueUri, DefaultPortIsIppsAndClassesAreQueuesToo) {
    const auto q = parse_queue_uri("ipps://10.0.0.7/classes/AllEmbossers");
    ASSERT_TRUE(q) << q.error().to_string();
    EXPECT_EQ(q->port, 631);
    EXPECT_TRUE(q->tls);
    EXPECT_EQ(q->resource, "/classes/AllEmbossers");
    const auto v6 = parse_queue_uri("ipp://[::1]:631/printers/E");
    ASSERT_TRUE(v6) << v6.error().to_string();
    EXPECT_EQ(v6->host, "::1");
}

TEST(QueueUri, RefusesWhatNamesNoQueueWithAUsageError) {
    for (const char* bad : {"ipp://host", "ipp://host/", "ipp://host/printers/",
                            "ipp://host/jobs/3", "ipp://host/printers/A/B", "ipp:///printers/A",
                            "sim", "pty:/dev/pts/3", "http://host/printers/A"}) {
        const auto q = parse_queue_uri(bad);
        ASSERT_FALSE(q) << bad;
        EXPECT_EQ(q.error().kind, ErrorKind::usage) << bad;
        EXPECT_EQ(q.error().where, bad);
    }
}

TEST(QueueUri, OnlyIppSchemesAreQueues) {
    EXPECT_TRUE(is_queue_uri("ipp://h/printers/E"));
    EXPECT_TRUE(is_queue_uri("ipps://h/printers/E"));
    EXPECT_FALSE(is_queue_uri("sim"));
    EXPECT_FALSE(is_queue_uri("serial:/dev/ttyUSB0"));
    EXPECT_FALSE(is_queue_uri("tactus:sim"));
}

}  // namespace
}  // namespace tactus::ipp
