// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs that are not what they seem: special files, packages other readers
// open despite a flaw, structures nested far deeper than any document needs.
// Each gives a document or a clear error, never a hang or a crash.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "import_test_util.hpp"

using namespace tactus;
using tactus::test::import_data;
using tactus::test::import_data_file;
using tactus::test::import_data_file_error;

namespace fs = std::filesystem;

// A named pipe nobody writes to: refused at once (reading it would wait for ever).
TEST(HostileInput, NamedPipeWithoutWriterIsRefused) {
    const auto fifo = fs::temp_directory_path() / ("tactus-fifo-" + std::to_string(::getpid()) + ".md");
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto doc = import::import_file(fifo);
    fs::remove(fifo);
    ASSERT_FALSE(doc);
    EXPECT_EQ(doc.error().where, fifo.string());
    EXPECT_NE(doc.error().message.find("named pipe"), std::string::npos) << doc.error().message;
}

TEST(HostileInput, DirectoryAndDeviceAreRefused) {
    const auto dir = import::import_file(fs::temp_directory_path());
    ASSERT_FALSE(dir);
    EXPECT_NE(dir.error().message.find("directory"), std::string::npos) << dir.error().message;
    // A device gives bytes without end: refused before anything is read.
    const auto device = import::import_file("/dev/zero");
    ASSERT_FALSE(device);
    EXPECT_NE(device.error().message.find("device"), std::string::npos) << device.error().message;
}

// unzip -t, Python's zipfile and Word read it; only libzip's strict
// header-against-directory check refused it.
TEST(HostileInput, ZipWithLocalHeaderDifferingFromDirectoryOpens) {
    const auto flawed = import_data_file("inconsistent_header.docx");
    const auto clean = import_data_file("lesson.docx");
    ASSERT_FALSE(clean.blocks.empty());
    EXPECT_EQ(flawed.blocks, clean.blocks);
}

// 5,000 nested tables or content controls: a clear error naming the part and
// line, not a crash when the importer's recursion runs out of stack.
TEST(HostileInput, DeeplyNestedDocxIsRefused) {
    for (const char* name : {"deep_tables.docx", "deep_controls.docx"}) {
        const auto e = import_data_file_error(name);
        EXPECT_NE(e.message.find("nested more than 256 levels"), std::string::npos) << name << ": " << e.message;
        EXPECT_TRUE(e.where.starts_with(import_data(name).string() + ":word/document.xml:2:")) << e.where;
    }
}
