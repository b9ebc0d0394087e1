// SPDX-License-Identifier: GPL-3.0-or-later
// Motion, vibration and profile views against core's plan and estimate: the
// preview puts dots where the planner strikes them, the motion curves pass
// through every strike at rest and within the limits, shapes compare as physics
// says, the vibration table agrees with the report, bad profile values are named.
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTableWidget>
#include <QtTest>
#include <cmath>

#include "announcer.hpp"
#include "editor_widget.hpp"
#include "gui_test_support.hpp"
#include "edit/live_layout.hpp"
#include "main_window.hpp"
#include "motion_model.hpp"
#include "motion_view.hpp"
#include "plan/geometry.hpp"
#include "preview_panel.hpp"
#include "profile/profile_json.hpp"
#include "profile_editor.hpp"
#include "sheet_geometry.hpp"
#include "vibration_view.hpp"

using namespace tactus;
using namespace tactus::gui;

namespace {

layout::PagedDocument welcome_pages() {
    auto l = edit::LiveLayout::create("en-ueb-g2.ctb", {});
    l->reset(test::sample_lines("welcome.md"));
    return l->paged();
}

}  // namespace

class MotionViewsTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void preview_dots_are_where_the_planner_strikes() {
        for (auto mirror : {profile::BackMirror::x, profile::BackMirror::y, profile::BackMirror::none}) {
            auto p = profile::default_profile();
            p.geometry.back_mirror = mirror;
            const auto g = sheet_geometry(p);
            layout::Page page;
            page.lines.assign(3, document::BrailleLine(5, document::Cell{0x3F}));
            const auto front = front_dots(page, g);
            const auto back = back_dots(page, g);
            QCOMPARE(front.size(), std::size_t{3 * 5 * 6});
            for (std::size_t i = 0; i < front.size(); ++i) {
                const auto f = plan::dot_place(p, plan::Side::front, front[i].line, front[i].cell, front[i].dot);
                const auto b = plan::dot_place(p, plan::Side::back, back[i].line, back[i].cell, back[i].dot);
                QVERIFY(std::abs(f.paper_x_mm - front[i].x_mm) < 1e-9 && std::abs(f.paper_y_mm - front[i].y_mm) < 1e-9);
                QVERIFY(std::abs(b.paper_x_mm - back[i].x_mm) < 1e-9 && std::abs(b.paper_y_mm - back[i].y_mm) < 1e-9);
            }
        }
    }

    void curves_stop_at_every_strike_within_the_limits() {
        const auto p = profile::default_profile();
        const auto plan = plan_document(welcome_pages(), p, 5);
        QVERIFY2(!plan->error, plan->error ? plan->error->to_string().c_str() : "");
        QVERIFY(!plan->sheets.empty());
        const double step_mm = 1.0 / p.carriage.steps_per_mm;
        int checked = 0;
        for (const auto& pass : plan->sheets.front().passes) {
            const auto c = pass_curves(pass, *plan->planner);
            QCOMPARE(c.strike_t.size(), pass.strikes.size());
            for (std::size_t i = 0; i < c.strike_t.size(); ++i) {
                // At the strike instant the carriage is where the plan says and at rest.
                const auto it = std::lower_bound(c.t.begin(), c.t.end(), c.strike_t[i] - 1e-12);
                const auto k = static_cast<std::size_t>(it - c.t.begin());
                QVERIFY(k < c.t.size());
                QVERIFY(std::abs(c.pos[k] - pass.strikes[i].carriage_step * step_mm) < step_mm);
                QVERIFY(std::abs(c.vel[k]) < 1e-6);
                ++checked;
            }
            for (std::size_t k = 0; k < c.t.size(); ++k) {
                QVERIFY(std::abs(c.vel[k]) <= p.carriage.v_max_mm_s * 1.0001);
                QVERIFY(std::abs(c.acc[k]) <= p.carriage.a_max_mm_s2 * 1.0001);
            }
            // The same strikes with one shape: no jerk limit is fastest; the
            // time-optimal jerk-limited move beats the smoothstep S-curve.
            const auto trap = pass_curves_with(pass, p, profile::ProfileShape::trapezoid);
            const auto jerk = pass_curves_with(pass, p, profile::ProfileShape::jerk);
            const auto scurve = pass_curves_with(pass, p, profile::ProfileShape::scurve);
            QVERIFY(trap.duration_s <= jerk.duration_s + 1e-12);
            QVERIFY(jerk.duration_s <= scurve.duration_s + 1e-12);
            QVERIFY(pass.duration_s >= pass.lower_bound_s - 1e-9);
        }
        QVERIFY(checked > 100);
    }

    void motion_view_lists_shapes_and_strikes() {
        MotionView view;
        view.set_plan(plan_document(welcome_pages(), profile::default_profile(), 2));
        view.select(1, 2);
        QCOMPARE(view.shape_table()->rowCount(), 4);
        const auto& pass = view.plan()->sheets[0].passes[1];
        QCOMPARE(view.strike_table()->rowCount(), static_cast<int>(pass.strikes.size()));
        QVERIFY(view.summary().contains(QStringLiteral("sheet 1, pass 2")));
    }

    void vibration_table_matches_the_report() {
        VibrationView view;
        auto p = profile::default_profile();
        view.set_profile(p);
        QCOMPARE(view.metrics()->item(0, 3)->text() == QStringLiteral("pass"), view.report().overshoot_ok);
        p.dynamics.damping_ratio = 0.05;  // a barely damped belt rings
        view.set_profile(p);
        QVERIFY(!view.report().overshoot_ok);
        QCOMPARE(view.metrics()->item(0, 3)->text(), QStringLiteral("FAIL"));
        view.set_plan(plan_document(welcome_pages(), profile::default_profile(), 1));
        QVERIFY(view.residual_summary().contains(QStringLiteral("worst case")));
    }

    void out_of_range_value_is_named_and_not_used() {
        MainWindow w;
        QVERIFY(w.open_file_now(test::sample("welcome.md")));
        auto* editor = w.profile_editor();
        QSignalSpy changed(editor, &ProfileEditor::profile_changed);
        auto* speed = editor->field(QStringLiteral("carriage.v_max_mm_s"));
        QVERIFY(speed);
        // 9000 mm/s at 80 steps/mm is more steps per second than the 89C52 can time.
        speed->selectAll();
        QTest::keyClicks(speed, "9000");
        QVERIFY(editor->error().contains(QStringLiteral("Carriage top speed")));
        QVERIFY(w.announcer()->message().contains(QStringLiteral("Carriage top speed")));
        // Typing passes through 9, 90 and 900 mm/s, all valid: the views follow those,
        // then keep 900 when 9000 is refused.
        QCOMPARE(changed.size(), 3);
        QCOMPARE(editor->profile().carriage.v_max_mm_s, 900.0);
        QCOMPARE(changed.last().first().value<profile::PrinterProfile>().carriage.v_max_mm_s, 900.0);
        // Back in range: the preview and plan follow.
        speed->selectAll();
        QTest::keyClicks(speed, "200");
        QVERIFY(editor->error().isEmpty());
        QCOMPARE(editor->profile().carriage.v_max_mm_s, 200.0);
        auto* offset = editor->field(QStringLiteral("geometry.back_offset_x_mm"));
        offset->setValue(0.5);
        QCOMPARE(w.preview_panel()->preview()->geometry().profile.geometry.back_offset_x_mm, 0.5);
        const auto plan = w.plan_now();
        QCOMPARE(plan->profile.carriage.v_max_mm_s, 200.0);
        QCOMPARE(plan->profile.geometry.back_offset_x_mm, 0.5);
    }

    // The graphic section's spacings: spin boxes named with their unit, held
    // to core's bounds (which follow the dot pitch and each other), saved and
    // loaded back.
    void graphic_spacings_are_checked_saved_and_loaded() {
        ProfileEditor editor;
        const QStringList names{QStringLiteral("graphic.line_dot_spacing_mm"), QStringLiteral("graphic.dotted_dot_spacing_mm"),
                                QStringLiteral("graphic.dash_gap_mm"), QStringLiteral("graphic.texture_pitch_mm"),
                                QStringLiteral("graphic.texture_dot_spacing_mm")};
        for (const auto& n : names) {
            auto* box = editor.field(n);
            QVERIFY2(box, qPrintable(n));
            QVERIFY2(box->accessibleName().endsWith(QStringLiteral(" in mm")), qPrintable(box->accessibleName()));
            QVERIFY(box->accessibleDescription().contains(n));
        }
        auto* line = editor.field(names[0]);
        QCOMPARE(line->value(), profile::default_profile().graphic.line_dot_spacing_mm);
        // Half a millimetre is closer than 0.6 dot pitches (1.5 mm at 2.5 mm): refused, the last valid kept.
        line->setValue(0.5);
        QVERIFY2(editor.error().contains(QStringLiteral("Dot spacing along a solid line in mm")), qPrintable(editor.error()));
        QVERIFY(line->accessibleDescription().startsWith(QStringLiteral("Invalid: ")));
        QCOMPARE(editor.profile().graphic.line_dot_spacing_mm, 1.5);
        // A dotted line must stay 1.5 line spacings apart: 2.5 mm solid needs 3.75 mm dotted.
        line->setValue(2.5);
        QVERIFY2(editor.error().contains(QStringLiteral("Dot spacing along a dotted line")), qPrintable(editor.error()));
        editor.field(names[1])->setValue(4.0);
        editor.field(names[2])->setValue(6.0);
        editor.field(names[3])->setValue(7.5);
        editor.field(names[4])->setValue(3.25);
        QVERIFY2(editor.error().isEmpty(), qPrintable(editor.error()));
        const auto want = editor.profile().graphic;
        QCOMPARE(want.line_dot_spacing_mm, 2.5);
        QCOMPARE(want.texture_dot_spacing_mm, 3.25);
        QTemporaryDir dir;
        const auto path = dir.filePath(QStringLiteral("graphic.json"));
        QVERIFY(editor.save(path));
        const auto saved = profile::load_profile(path.toStdString());
        QVERIFY(saved);
        QCOMPARE(saved->graphic, want);
        ProfileEditor other;
        QVERIFY(other.load(path));
        QCOMPARE(other.profile().graphic, want);
        QCOMPARE(other.field(names[3])->value(), 7.5);
    }
};

QTEST_MAIN(MotionViewsTest)
#include "motion_views_test.moc"
