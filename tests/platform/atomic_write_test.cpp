// SPDX-License-Identifier: GPL-3.0-or-later
// write_file_atomic through a symbolic link and over a file with its own
// permissions: the link stays a link to the new bytes, the permissions stay.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <unistd.h>

#include "common/file_io.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

class AtomicWrite : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("tactus-atomic-" + std::to_string(getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "shared");
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

std::string contents_of(const fs::path& p) {
    auto r = read_file(p);
    return r ? *r : "<unreadable: " + r.error().message + ">";
}

TEST_F(AtomicWrite, AWriteThroughASymbolicLinkKeepsTheLinkAndWritesItsTarget) {
    const auto target = dir_ / "shared" / "lesson.md";
    const auto link = dir_ / "lesson.md";
    ASSERT_TRUE(write_file_atomic(target, "old"));
    fs::create_symlink(target, link);
    ASSERT_TRUE(write_file_atomic(link, "new"));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(contents_of(target), "new");
    EXPECT_EQ(contents_of(link), "new");
    // The streamed form as well, through a link to a link.
    const auto link2 = dir_ / "again.md";
    fs::create_symlink(link, link2);
    ASSERT_TRUE(write_file_atomic(link2, [](std::ostream& out) -> Result<void> {
        out << "streamed";
        return {};
    }));
    EXPECT_TRUE(fs::is_symlink(link2));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(contents_of(target), "streamed");
    // Nothing left beside either: no temporary file in the link's folder or the target's.
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_ / "shared")) ++entries;
    EXPECT_EQ(entries, 1U);
}

TEST_F(AtomicWrite, ADanglingLinkIsReplacedByTheFile) {
    const auto link = dir_ / "gone.md";
    fs::create_symlink(dir_ / "nowhere" / "gone.md", link);
    ASSERT_TRUE(write_file_atomic(link, "here"));
    EXPECT_FALSE(fs::is_symlink(link));
    EXPECT_EQ(contents_of(link), "here");
}

TEST_F(AtomicWrite, TheReplacedFileKeepsItsPermissions) {
    const auto file = dir_ / "private.md";
    ASSERT_TRUE(write_file_atomic(file, "old"));
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
    ASSERT_TRUE(write_file_atomic(file, "new"));
    EXPECT_EQ(fs::status(file).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    fs::permissions(file, fs::perms::owner_all | fs::perms::group_read, fs::perm_options::replace);
    ASSERT_TRUE(write_file_atomic(file, [](std::ostream& out) -> Result<void> {
        out << "streamed";
        return {};
    }));
    EXPECT_EQ(fs::status(file).permissions() & fs::perms::all, fs::perms::owner_all | fs::perms::group_read);
    EXPECT_EQ(contents_of(file), "streamed");
}

}  // namespace
}  // namespace tactus
