// SPDX-License-Identifier: GPL-3.0-or-later
// A newcomer's printer (spool/printer_setup.hpp), on a real database file: set
// up once per device, named after it, found again; a name already taken by
// another device gets a suffix; a malformed device string is refused. And the
// page -> sheet rule of "resume from page".
#include <gtest/gtest.h>

#include "spool/printer_setup.hpp"
#include "spool/printing.hpp"
#include "spool_fixtures.hpp"

namespace tactus::spool {
namespace {

TEST(PrinterSetup, NamesComeFromTheDevice) {
    EXPECT_EQ(printer_name_for_device("serial:/dev/ttyUSB0?baud=9600"), "ttyUSB0");
    EXPECT_EQ(printer_name_for_device("pty:/dev/pts/3"), "pts-3");
    EXPECT_EQ(printer_name_for_device("hid:10c4:ea80"), "hid-10c4-ea80");
    EXPECT_EQ(printer_name_for_device("sim"), "sim");
    EXPECT_EQ(printer_name_for_device("lpt:/dev/parport0"), "parport0");
}

TEST(PrinterSetup, OnePrinterPerDeviceSetUpOnFirstUse) {
    test::TempDir dir;
    auto s = Spool::open(dir / "spool.db");
    ASSERT_TRUE(s);
    bool created = false;
    auto p = printer_for_device(*s, "pty:/dev/pts/3", "{}", &created);
    ASSERT_TRUE(p) << p.error().to_string();
    EXPECT_TRUE(created);
    EXPECT_EQ(p->name, "pts-3");
    auto again = printer_for_device(*s, "pty:/dev/pts/3", "{}", &created);
    ASSERT_TRUE(again);
    EXPECT_FALSE(created);
    EXPECT_EQ(again->id, p->id);
    // Another device with the same name: a suffix, not the first printer.
    auto other = printer_for_device(*s, "pty:/dev/pts/3?baud=9600", "{}", &created);
    ASSERT_TRUE(other);
    EXPECT_TRUE(created);
    EXPECT_EQ(other->name, "pts-3-2");
    auto bad = printer_for_device(*s, "serial:/dev/ttyUSB0?baud=fast", "{}", &created);
    ASSERT_FALSE(bad);
    EXPECT_FALSE(created);
    EXPECT_NE(bad.error().to_string().find("baud"), std::string::npos) << bad.error().to_string();
    EXPECT_EQ(s->printers()->size(), 2u);
}

TEST(PrinterSetup, ResumeFromPageFindsTheSheetOrSaysThePageIsNotThere) {
    const auto interpoint = test::make_document(9, true);
    EXPECT_EQ(*sheet_of_page(interpoint, 1), 1u);
    EXPECT_EQ(*sheet_of_page(interpoint, 4), 2u);
    EXPECT_EQ(*sheet_of_page(interpoint, 5), 3u);
    EXPECT_EQ(*sheet_of_page(interpoint, 9), 5u);
    const auto single = test::make_document(9, false);
    EXPECT_EQ(*sheet_of_page(single, 5), 5u);
    for (std::size_t page : {std::size_t{0}, std::size_t{10}}) {
        auto r = sheet_of_page(interpoint, page);
        ASSERT_FALSE(r);
        EXPECT_NE(r.error().message.find("has 9 braille pages"), std::string::npos) << r.error().message;
    }
}

}  // namespace
}  // namespace tactus::spool
