// SPDX-License-Identifier: GPL-3.0-or-later
// The pure parts of the CUPS backend and filter: tactus: URIs, discovery
// lines and IEEE 1284 device IDs, job options (with the real liblouis
// tables), and what the backend reports to cupsd for each spool state.
#include <gtest/gtest.h>

#include <random>

#include "backend_status.hpp"
#include "cups_options.hpp"
#include "cups_uri.hpp"
#include "discovery.hpp"
#include "job_options.hpp"

namespace tactus::cups {
namespace {

using spool::JobState;
using spool::SheetProgress;

TEST(CupsUri, DeviceStringsRoundTrip) {
    for (const std::string d : {"serial:/dev/ttyUSB0?baud=57600&parity=none&flow=rtscts", "pty:/dev/pts/3?baud=230400",
                                "hid:10c4:ea80:0001A2", "lpt:/dev/parport0", "sim?baud=115200&seed=7"}) {
        const auto uri = uri_from_device(d);
        EXPECT_EQ(uri, "tactus:" + d);  // nothing to escape in ordinary device strings
        const auto back = device_from_uri(uri);
        ASSERT_TRUE(back) << back.error().to_string();
        EXPECT_EQ(*back, d);
    }
}

TEST(CupsUri, OddCharactersAreEscapedAndComeBack) {
    // Property: any path of printable and non-ASCII bytes survives the trip.
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> byte(0x20, 0xFF), len(1, 40);
    for (int i = 0; i < 500; ++i) {
        std::string path = "/dev/serial/by-id/";
        for (int n = len(rng); n > 0; --n) {
            const char c = static_cast<char>(byte(rng));
            if (c != '?' && c != '&' && c != '=') path += c;  // device-string delimiters
        }
        const std::string device = "serial:" + path;
        const auto uri = uri_from_device(device);
        for (const char c : uri.substr(7))
            EXPECT_TRUE(c > 0x20 && c < 0x7F && c != ' ' && c != '"' && c != '#') << uri;
        const auto back = device_from_uri(uri);
        ASSERT_TRUE(back) << uri << ": " << back.error().to_string();
        EXPECT_EQ(*back, device);
    }
}

TEST(CupsUri, BadUrisSayWhatIsWrong) {
    auto e = device_from_uri("usb://Tactus/Embosser");
    ASSERT_FALSE(e);
    EXPECT_NE(e.error().message.find("not a tactus: URI"), std::string::npos);
    e = device_from_uri("tactus://serial/dev/ttyUSB0");
    ASSERT_FALSE(e);
    EXPECT_NE(e.error().message.find("without \"//\""), std::string::npos);
    e = device_from_uri("tactus:serial:/dev/tty%G1");
    ASSERT_FALSE(e);
    EXPECT_NE(e.error().message.find("bad %-escape at character 23"), std::string::npos) << e.error().message;
    e = device_from_uri("tactus:serial:/dev/tty%4");
    ASSERT_FALSE(e);
    e = device_from_uri("tactus:");
    ASSERT_FALSE(e);
    e = device_from_uri("tactus:floppy:/dev/fd0");
    ASSERT_FALSE(e);  // the transport's own parser refuses the kind
    EXPECT_EQ(e.error().where.rfind("tactus:floppy:/dev/fd0", 0), 0u) << e.error().to_string();
}

TEST(CupsDiscovery, LineCarriesUriMakeModelInfoAndDeviceId) {
    transport::PortInfo p;
    p.device = "serial:/dev/ttyUSB0";
    p.kind = "usb-serial";
    p.description = "FT232R USB UART";
    p.vid = 0x0403;
    p.pid = 0x6001;
    p.serial_number = "A50285BI";
    EXPECT_EQ(discovery_line(p),
              "direct tactus:serial:/dev/ttyUSB0 \"Tactus Braille Embosser\" \"Tactus embosser on FT232R USB UART "
              "(0403:6001)\" \"MFG:Tactus;MDL:Braille Embosser;CMD:TACTUS;CLS:PRINTER;DES:Tactus embosser on "
              "FT232R USB UART (0403 6001);SN:A50285BI;\" \"\"");
    p.kind = "native";
    p.vid.reset();
    p.serial_number.clear();
    p.description = "ttyS0 \"16550A\"; COM1";
    const auto line = discovery_line(p);
    EXPECT_EQ(line.rfind("serial tactus:serial:/dev/ttyUSB0 ", 0), 0u) << line;
    // Quotes cannot end a field early; ';' and ':' cannot split the device ID.
    EXPECT_NE(line.find("\"Tactus embosser on ttyS0  16550A ; COM1\""), std::string::npos) << line;
    EXPECT_NE(device_id(p).find("DES:Tactus embosser on ttyS0  16550A   COM1;"), std::string::npos) << device_id(p);
}

TEST(CupsOptions, LibcupsParsesBooleansAndQuotes) {
    const auto o = parse_cups_options("interpoint noeight-dot braille-table=en-ueb-g2 job-uuid='urn:uuid:1 2'");
    EXPECT_EQ(o.at("interpoint"), "true");
    EXPECT_EQ(o.at("eight-dot"), "false");
    EXPECT_EQ(o.at("braille-table"), "en-ueb-g2");
    EXPECT_EQ(o.at("job-uuid"), "urn:uuid:1 2");
}

TEST(CupsJobOptions, TablesAreNamedWithOrWithoutTheirExtension) {
    EXPECT_EQ(braille_table("en-ueb-g2").value_or("?"), "en-ueb-g2.ctb");
    EXPECT_EQ(braille_table("de-g0").value_or("?"), "de-g0.utb");
    EXPECT_EQ(braille_table("en-ueb-g1.ctb").value_or("?"), "en-ueb-g1.ctb");
    EXPECT_EQ(braille_table("en-ueb-g1,en-ueb-g2").value_or("?"), "en-ueb-g1.ctb,en-ueb-g2.ctb");
    for (const char* bad : {"no-such-table", "", "../../etc/passwd", "/usr/share/liblouis/tables/en-ueb-g2.ctb"}) {
        const auto r = braille_table(bad);
        ASSERT_FALSE(r) << bad;
        EXPECT_EQ(r.error().where, "option braille-table");
    }
}

TEST(CupsJobOptions, TheProfileGivesThePageFormatAndOptionsMayOnlyNarrowIt) {
    const auto machine = profile::default_profile();  // 27 x 24, interpoint
    auto o = pipeline_options({}, machine);
    ASSERT_TRUE(o) << o.error().to_string();
    EXPECT_EQ(o->layout.geometry.cells_per_line, machine.geometry.cells_per_line);
    EXPECT_EQ(o->layout.geometry.lines_per_page, machine.geometry.lines_per_page);
    EXPECT_EQ(o->layout.geometry.interpoint, machine.geometry.interpoint);
    EXPECT_EQ(o->tables, translate::kDefaultTable);

    o = pipeline_options({{"braille-table", "en-ueb-g1"}, {"interpoint", "true"}, {"cells-per-line", "20"},
                          {"lines-per-page", "20"}, {"braille-page-numbers", "none"}, {"print-page-indicators", "no"}},
                         machine);
    ASSERT_TRUE(o) << o.error().to_string();
    EXPECT_EQ(o->tables, "en-ueb-g1.ctb");
    EXPECT_EQ(o->layout.geometry.cells_per_line, 20);
    EXPECT_EQ(o->layout.geometry.lines_per_page, 20);
    EXPECT_TRUE(o->layout.geometry.interpoint);
    EXPECT_EQ(o->layout.page_numbers, layout::PageNumberPosition::none);
    EXPECT_FALSE(o->layout.print_page_indicators);

    struct Bad {
        CupsOptions options;
        const char* where;
        const char* says;
    };
    for (const auto& b : {Bad{{{"interpoint", "false"}}, "option interpoint", "set up for interpoint"},
                          Bad{{{"interpoint", "maybe"}}, "option interpoint", "not true or false"},
                          Bad{{{"cells-per-line", "30"}}, "option cells-per-line", "from 4 to 27"},
                          Bad{{{"lines-per-page", "x"}}, "option lines-per-page", "not a whole number"},
                          Bad{{{"braille-page-numbers", "left"}}, "option braille-page-numbers", ""},
                          Bad{{{"braille-table", "xx"}}, "option braille-table", "not an installed braille table"}}) {
        const auto r = pipeline_options(b.options, machine);
        ASSERT_FALSE(r) << b.where;
        EXPECT_EQ(r.error().where.rfind(b.where, 0), 0u) << r.error().to_string();
        EXPECT_NE(r.error().message.find(b.says), std::string::npos) << r.error().to_string();
    }
    // CUPS's own options are not ours to refuse.
    EXPECT_TRUE(pipeline_options({{"number-up", "1"}, {"job-uuid", "urn:uuid:x"}, {"finishings", "3"}}, machine));
}

TEST(CupsJobOptions, MimeTypesMapToImporters) {
    using import::SourceFormat;
    EXPECT_EQ(source_format("text/plain").value(), SourceFormat::text);
    EXPECT_EQ(source_format("text/markdown").value(), SourceFormat::markdown);
    EXPECT_EQ(source_format("application/vnd.openxmlformats-officedocument.wordprocessingml.document").value(),
              SourceFormat::docx);
    EXPECT_EQ(source_format("application/vnd.oasis.opendocument.text").value(), SourceFormat::odt);
    EXPECT_EQ(source_format("application/x-brf").value(), SourceFormat::brf);
    EXPECT_EQ(source_format("application/x-pef+xml").value(), SourceFormat::pef);
    const auto r = source_format("image/png");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("cannot lay out image/png"), std::string::npos);
}

std::vector<SheetProgress> sheets(std::initializer_list<std::pair<std::size_t, std::size_t>> done_total) {
    std::vector<SheetProgress> out;
    for (const auto& [done, total] : done_total) out.push_back({out.size() + 1, total, done, 0});
    return out;
}

TEST(CupsStatus, EachSheetCountsOnceAndProgressFollowsTheSheetInTheMachine) {
    StatusReporter r;
    JobView v{JobState::running, "", sheets({{0, 4}, {0, 4}}), 2, "", 0};
    EXPECT_EQ(r.update(v), (std::vector<std::string>{"ATTR: job-media-progress=0", "INFO: Embossing sheet 1 of 2"}));
    v.progress = sheets({{2, 4}, {0, 4}});
    EXPECT_EQ(r.update(v), (std::vector<std::string>{"ATTR: job-media-progress=50"}));
    v.progress = sheets({{4, 4}, {1, 4}});
    EXPECT_EQ(r.update(v), (std::vector<std::string>{"PAGE: 1 1", "ATTR: job-media-progress=25",
                                                      "INFO: Embossing sheet 2 of 2"}));
    EXPECT_TRUE(r.update(v).empty());  // nothing changed, nothing said
    // A sheet spoiled and embossed again is still one sheet for CUPS.
    v.progress = sheets({{4, 4}, {4, 4}});
    v.state = JobState::completed;
    EXPECT_EQ(r.update(v), (std::vector<std::string>{"PAGE: 2 1", "INFO: Embossed all 2 sheet(s)"}));
    v.progress[1].passes_done = 0;
    v.progress[1].spoiled = 1;
    (void)r.update(v);
    v.progress[1].passes_done = 4;
    for (const auto& line : r.update(v)) EXPECT_NE(line.rfind("PAGE:", 0), 0u) << line;
    EXPECT_EQ(r.sheets_reported(), 2u);
}

TEST(CupsStatus, SheetsEmbossedBeforeARestartAreNotCountedAgain) {
    StatusReporter r(sheets({{4, 4}, {0, 4}}));
    const auto lines = r.update({JobState::running, "", sheets({{4, 4}, {4, 4}}), 2, "", 0});
    EXPECT_EQ(std::count(lines.begin(), lines.end(), "PAGE: 2 1"), 1);
    EXPECT_EQ(std::count(lines.begin(), lines.end(), "PAGE: 1 1"), 0);
}

TEST(CupsStatus, PaperOutAndOfflineSetAndClearPrinterStateReasons) {
    StatusReporter r;
    JobView v{JobState::paused, "paper out at sheet 2: load paper", sheets({{4, 4}, {0, 4}}), 2, "", 0};
    auto lines = r.update(v);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "STATE: +media-empty-error"), lines.end());
    EXPECT_NE(std::find(lines.begin(), lines.end(), "INFO: Paper out at sheet 2: load paper"), lines.end());
    v.state = JobState::running;
    v.reason.clear();
    v.last_note = "connection lost (device disconnected): reconnecting";
    lines = r.update(v);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "STATE: -media-empty-error"), lines.end());
    EXPECT_NE(std::find(lines.begin(), lines.end(), "STATE: +offline-report"), lines.end());
    EXPECT_EQ(r.clear(), (std::vector<std::string>{"STATE: -offline-report"}));
    EXPECT_TRUE(r.clear().empty());
}

TEST(CupsStatus, PaperOutIsSeenInTheLinksNoteWhenThePauseReasonIsGeneric) {
    // What the runner records: paused on "controller fault", then the note.
    StatusReporter r;
    const auto lines = r.update({JobState::paused, "controller fault", sheets({{4, 4}, {1, 4}}), 2,
                                 "paper out at sheet 2 (pass 61 of the job): load paper", 0});
    EXPECT_NE(std::find(lines.begin(), lines.end(), "STATE: +media-empty-error"), lines.end());
    EXPECT_NE(std::find(lines.begin(), lines.end(), "INFO: Paper out at sheet 2 (pass 61 of the job): load paper"),
              lines.end());
}

TEST(CupsStatus, WaitingBehindLocalJobsIsSaid) {
    StatusReporter r;
    const auto lines = r.update({JobState::queued, "", sheets({{0, 4}}), 1, "", 2});
    EXPECT_NE(std::find(lines.begin(), lines.end(), "INFO: Waiting: the embosser has 2 other job(s) to finish first"),
              lines.end());
}

}  // namespace
}  // namespace tactus::cups
