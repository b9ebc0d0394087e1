// SPDX-License-Identifier: GPL-3.0-or-later
// The rules the CLI and the app share when they follow a job on a CUPS
// queue: which statuses are news, and what an ended job's reason is. The
// jobs themselves run against a real cupsd in tests/cups.
#include "ipp/remote_job.hpp"

#include <gtest/gtest.h>

namespace tactus::ipp {
namespace {

RemoteJobStatus status(RemoteJobState state, int sheets, int progress, std::string message = {},
                       std::string reasons = {}) {
    RemoteJobStatus s;
    s.id = 7;
    s.state = state;
    s.sheets_completed = sheets;
    s.media_progress = progress;
    s.message = std::move(message);
    s.reasons = std::move(reasons);
    return s;
}

TEST(RemoteJob, NewsIsAnotherStateSheetMessageOrTenthOfTheSheet) {
    const auto shown = status(RemoteJobState::processing, 1, 40, "Embossing sheet 2 of 3");
    EXPECT_TRUE(worth_telling(std::nullopt, shown));
    EXPECT_FALSE(worth_telling(shown, status(RemoteJobState::processing, 1, 47, "Embossing sheet 2 of 3")));
    EXPECT_TRUE(worth_telling(shown, status(RemoteJobState::processing, 1, 50, "Embossing sheet 2 of 3")));
    EXPECT_TRUE(worth_telling(shown, status(RemoteJobState::processing, 2, 40, "Embossing sheet 2 of 3")));
    EXPECT_TRUE(worth_telling(shown, status(RemoteJobState::processing, 1, 40, "Paper out at sheet 2: load paper")));
    EXPECT_TRUE(worth_telling(shown, status(RemoteJobState::completed, 1, 40, "Embossing sheet 2 of 3")));
}

TEST(RemoteJob, AJobAUserCancelledEndsWithoutItsStaleProgressMessage) {
    EXPECT_EQ(status(RemoteJobState::cancelled, 0, 30, "Embossing sheet 1 of 2", "job-canceled-by-user").why_ended(),
              "");
    // A filter that refused the document: CUPS cancels the job, its ERROR: line says why.
    const auto refused = "option braille-table: 'x' is not an installed braille table";
    EXPECT_EQ(status(RemoteJobState::cancelled, 0, -1, refused, "job-canceled-at-device").why_ended(), refused);
    EXPECT_EQ(status(RemoteJobState::aborted, 1, -1, "hammer fault", "job-aborted-by-system").why_ended(),
              "hammer fault");
}

}  // namespace
}  // namespace tactus::ipp
