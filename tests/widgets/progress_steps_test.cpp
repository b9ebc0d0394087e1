// SPDX-License-Identifier: GPL-3.0-or-later
// Embossing progress reaches the screen reader in steps, never per strike or
// per pass: a simulated job reporting every pass of hundreds of sheets moves the
// bar a bounded number of times and speaks at most every few seconds.
#include <QtTest>

#include "progress_steps.hpp"

using namespace tactus::gui;
using namespace std::chrono_literals;

namespace {

struct Counts {
    int bar = 0;
    int spoken = 0;
    std::vector<ProgressSteps::Step> said;
};

// Runs a job of `sheets` sheets with `passes` passes each, reporting every pass,
// `seconds_per_pass` apart on a made-up clock.
Counts run(std::size_t sheets, std::size_t passes, std::chrono::milliseconds per_pass) {
    ProgressSteps steps(sheets);
    Counts c;
    auto now = ProgressSteps::Clock::time_point{};
    const auto total = sheets * passes;
    for (std::size_t done = 1; done <= total; ++done) {
        now += per_pass;
        const auto sheet = std::min(sheets, done / passes + 1);
        if (auto s = steps.update(done, total, sheet)) {
            ++c.bar;
            if (steps.speak(now)) {
                ++c.spoken;
                c.said.push_back(*s);
            }
        }
    }
    return c;
}

}  // namespace

class ProgressStepsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void one_sheet_moves_the_bar_by_tenths_and_says_nothing_before_the_end() {
        const auto c = run(1, 120, 50ms);
        QCOMPARE(c.bar, 11);  // 0 %, 10 %, ..., 100 %
        QCOMPARE(c.spoken, 0);  // "Embossing ..." and "Embossed ..." are the job's own messages
    }

    void few_sheets_speak_each_new_sheet() {
        const auto c = run(3, 200, 50ms);  // 10 s a sheet
        QCOMPARE(c.spoken, 2);  // sheet 2 of 3, sheet 3 of 3
        QCOMPARE(c.said[0].sheet, std::size_t{2});
        QCOMPARE(c.said[1].sheet, std::size_t{3});
        QVERIFY(c.said[0].by_sheet);
        QVERIFY(c.bar <= 11 + 3);
    }

    void many_sheets_speak_every_tenth_and_move_the_bar_once_a_sheet() {
        const auto c = run(317, 40, 20ms);  // 0.8 s a sheet, 254 s in all
        QVERIFY(c.bar >= 317 && c.bar <= 317 + 11);  // each sheet, and the tenths that fall inside one
        QCOMPARE(c.spoken, 9);  // 10 %, 20 %, ..., 90 %; the end is the job's own message
        for (std::size_t i = 0; i < c.said.size(); ++i) {
            QCOMPARE(c.said[i].percent / 10, static_cast<int>(i + 1));
            QVERIFY(!c.said[i].by_sheet);
        }
    }

    void a_slow_job_is_heard_at_least_every_heartbeat() {
        // The plan's own speed: three sheets of about 147 s, a pass a second.
        ProgressSteps steps(3, 3s, 30s);
        auto now = ProgressSteps::Clock::time_point{};
        const std::size_t passes = 147, total = 3 * passes;
        auto last_said = now;
        std::chrono::milliseconds longest{0};
        int said = 0;
        for (std::size_t done = 1; done < total; ++done) {
            now += 1s;
            const auto sheet = done / passes + 1;
            const auto step = steps.update(done, total, sheet);
            bool spoken = step && steps.speak(now);
            if (!spoken) {
                if (const auto beat = steps.overdue(now)) {
                    spoken = true;
                    QVERIFY(beat->percent > 0 && beat->percent < 100);
                    QCOMPARE(beat->sheet, std::min<std::size_t>(sheet, 3));
                }
            }
            if (spoken) {
                longest = std::max(longest, std::chrono::duration_cast<std::chrono::milliseconds>(now - last_said));
                last_said = now;
                ++said;
            }
        }
        QVERIFY2(longest <= 31s, qPrintable(QStringLiteral("%1 ms of silence").arg(longest.count())));
        QVERIFY(said >= 14 && said <= 16);  // 441 s: one every 30 s, no more
        // Paused: nothing moves, nothing is said however long it lasts.
        (void)steps.overdue(now + 31s);
        QVERIFY(!steps.overdue(now + 10min));
    }

    void speech_waits_for_the_gap_then_says_the_latest_step() {
        // A fast job: every tenth passes in less than the 3 s gap.
        const auto c = run(100, 10, 1ms);  // 1 s in all
        QCOMPARE(c.spoken, 1);  // the first tenth; the rest fall in the gap, the end has its own message
        ProgressSteps steps(20, 3s);
        auto t = ProgressSteps::Clock::time_point{};
        QVERIFY(steps.update(2, 20, 2));  // 10 %
        QVERIFY(steps.speak(t));
        QVERIFY(steps.update(4, 20, 4));  // 20 %, 1 s later: too soon
        QVERIFY(!steps.speak(t + 1s));
        QVERIFY(steps.update(6, 20, 6));  // 30 %, 4 s after the last spoken: said
        QVERIFY(steps.speak(t + 4s));
        QCOMPARE(steps.shown_percent(), 30);
        QVERIFY(!steps.speak(t + 10s));  // nothing new
    }

    void repeated_or_backward_reports_do_not_move_the_bar() {
        ProgressSteps steps(2);
        QVERIFY(steps.update(0, 100, 1));
        QVERIFY(!steps.update(0, 100, 1));
        QVERIFY(!steps.update(5, 100, 1));
        QVERIFY(steps.update(10, 100, 1));
        QVERIFY(!steps.update(9, 100, 1));
        QVERIFY(!steps.update(0, 0, 1));  // no total yet: 0 %
    }
};

QTEST_GUILESS_MAIN(ProgressStepsTest)
#include "progress_steps_test.moc"
