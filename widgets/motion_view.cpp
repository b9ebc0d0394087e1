// SPDX-License-Identifier: GPL-3.0-or-later
#include "fit_columns.hpp"
#include "motion_view.hpp"
#include "status_label.hpp"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QScatterSeries>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <tuple>

namespace tactus::gui {
namespace {

const std::vector<double>& pick(const Curves& c, int q) {
    switch (q) {
        case 1: return c.vel;
        case 2: return c.acc;
        case 3: return c.jerk;
        default: return c.pos;
    }
}

QLineSeries* series_of(const Curves& c, int q, const QString& name) {
    auto* s = new QLineSeries;
    s->setName(name);
    const auto& y = pick(c, q);
    QList<QPointF> points;
    points.reserve(static_cast<qsizetype>(c.t.size()));
    for (std::size_t i = 0; i < c.t.size(); ++i) points.append({c.t[i] * 1000.0, y[i]});
    s->replace(points);
    return s;
}

QString percent_over(double value, double bound) {
    return bound > 0 ? QStringLiteral("%1%2 %").arg(value >= bound ? QStringLiteral("+") : QString())
                           .arg((value / bound - 1) * 100, 0, 'f', 1)
                     : QStringLiteral("-");
}

}  // namespace

QString format_duration(double s) {
    if (s < 60) return QObject::tr("%1 s").arg(s, 0, 'f', s < 1 ? 3 : 1);
    const int minutes = static_cast<int>(s / 60);
    if (minutes < 60) return QObject::tr("%1 min %2 s").arg(minutes).arg(s - minutes * 60, 0, 'f', 0);
    return QObject::tr("%1 h %2 min").arg(minutes / 60).arg(minutes % 60);
}

MotionView::MotionView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("motionView"));
    sheet_ = new QSpinBox(this);
    sheet_->setAccessibleName(tr("Sheet"));
    pass_ = new QSpinBox(this);
    pass_->setAccessibleName(tr("Pass"));
    quantity_ = new QComboBox(this);
    quantity_->setAccessibleName(tr("Quantity"));
    quantity_->addItems({tr("Position (mm)"), tr("Velocity (mm/s)"), tr("Acceleration (mm/s\u00b2)"),
                         tr("Jerk (mm/s\u00b3)")});
    compare_ = new QCheckBox(tr("Compare prof&ile shapes"), this);
    compare_->setChecked(true);
    auto* controls = new QHBoxLayout;
    auto* form = new QFormLayout;
    form->addRow(tr("&Sheet:"), sheet_);
    form->addRow(tr("P&ass:"), pass_);
    form->addRow(tr("Sho&w:"), quantity_);
    controls->addLayout(form);
    controls->addWidget(compare_);
    controls->addStretch();

    chart_view_ = new QChartView(new QChart, this);
    chart_view_->setObjectName(QStringLiteral("motionChart"));
    chart_view_->setAccessibleName(tr("Carriage motion chart"));
    chart_view_->setFocusPolicy(Qt::StrongFocus);
    chart_view_->setRenderHint(QPainter::Antialiasing);
    chart_view_->setMinimumHeight(220);
    chart_view_->viewport()->setAccessibleName(chart_view_->accessibleName());
    // Beside the plot the legend has a line per series; below it, the four
    // names shared one line and "Jerk-limited (7 segments)" was elided.
    chart_view_->chart()->legend()->setAlignment(Qt::AlignRight);
    times_ = new QLabel(this);
    times_->setObjectName(QStringLiteral("motionTimes"));
    expose_status(times_, tr("Time estimates"));
    times_->setWordWrap(true);
    times_->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);

    shapes_ = new QTableWidget(0, 3, this);
    shapes_->setObjectName(QStringLiteral("shapeTable"));
    shapes_->setAccessibleName(tr("Profile shapes on this pass"));
    shapes_->setHorizontalHeaderLabels({tr("Profile shape"), tr("Pass time"), tr("Versus lower bound")});
    shapes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    shapes_->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    fit_columns_to_headings(shapes_);
    strikes_ = new QTableWidget(0, 4, this);
    strikes_->setObjectName(QStringLiteral("strikeTable"));
    strikes_->setAccessibleName(tr("Strikes of this pass"));
    strikes_->setHorizontalHeaderLabels({tr("Time (ms)"), tr("Carriage (mm)"), tr("Side"), tr("Residual (\u00b5m)")});
    strikes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    strikes_->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    fit_columns_to_headings(strikes_);

    // One above the other: side by side, a dock of 1280 px could not give
    // both tables the width their headings and cells need.
    auto* tables = new QSplitter(Qt::Vertical, this);
    tables->addWidget(shapes_);
    tables->addWidget(strikes_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(times_);
    layout->addWidget(chart_view_, 3);
    layout->addWidget(tables, 2);

    connect(sheet_, &QSpinBox::valueChanged, this, [this] { refresh(); });
    connect(pass_, &QSpinBox::valueChanged, this, [this] { refresh(); });
    connect(quantity_, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    connect(compare_, &QCheckBox::toggled, this, [this] { refresh(); });
    refresh();
}

void MotionView::set_plan(DocumentPlanPtr plan) {
    plan_ = std::move(plan);
    const int sheets = plan_ ? static_cast<int>(plan_->sheets.size()) : 0;
    sheet_->setRange(sheets ? 1 : 0, sheets);
    refresh();
}

void MotionView::select(int sheet, int pass) {
    sheet_->setValue(sheet);
    pass_->setValue(pass);
    refresh();
}

QString MotionView::summary() const { return chart_view_->accessibleDescription(); }

void MotionView::refresh() {
    auto* chart = chart_view_->chart();
    chart->removeAllSeries();
    for (auto* axis : chart->axes()) chart->removeAxis(axis);
    shapes_->setRowCount(0);
    strikes_->setRowCount(0);
    if (!plan_ || plan_->error || plan_->sheets.empty()) {
        const auto why = plan_ && plan_->error ? QString::fromStdString(plan_->error->to_string()) : tr("No plan yet");
        times_->setText(why);
        chart_view_->setAccessibleDescription(why);
        return;
    }
    const auto& sheet = plan_->sheets[static_cast<std::size_t>(std::max(1, sheet_->value()) - 1)];
    pass_->setRange(sheet.passes.empty() ? 0 : 1, static_cast<int>(sheet.passes.size()));
    const auto& totals = plan_->totals;
    QString times = tr("Sheet %1: %2 (lower bound %3, %4). Document, %5 sheets: %6 (lower bound %7, %8).")
                        .arg(sheet.index)
                        .arg(format_duration(sheet.duration_s), format_duration(sheet.lower_bound_s),
                             percent_over(sheet.duration_s, sheet.lower_bound_s))
                        .arg(plan_->sheet_count)
                        .arg(format_duration(totals.duration_s), format_duration(totals.lower_bound_s),
                             percent_over(totals.duration_s, totals.lower_bound_s));
    if (sheet.passes.empty()) {
        times_->setText(times + QLatin1Char(' ') + tr("This sheet is blank."));
        return;
    }
    const auto& pass = sheet.passes[static_cast<std::size_t>(std::max(1, pass_->value()) - 1)];
    times += QLatin1Char(' ') + tr("Pass %1 (%2, %3 strikes): %4, lower bound %5.")
                                    .arg(pass_->value())
                                    .arg(pass.side == plan::Side::front ? tr("front") : tr("back"))
                                    .arg(pass.strikes.size())
                                    .arg(format_duration(pass.duration_s), format_duration(pass.lower_bound_s));
    times_->setText(times);

    const int q = quantity_->currentIndex();
    const auto tuned = pass_curves(pass, *plan_->planner);
    auto* main = series_of(tuned, q, tr("Planned (auto-tuned)"));
    main->setPen(QPen(QColor(0, 70, 160), 2.5));
    chart->addSeries(main);
    auto* marks = new QScatterSeries;
    marks->setName(tr("Strikes"));
    marks->setMarkerSize(9);
    marks->setColor(QColor(200, 0, 0));
    marks->setBorderColor(QColor(200, 0, 0));
    const auto& y = pick(tuned, q);
    for (double t : tuned.strike_t) {
        // Mark the value at the strike instant (the last sample at or before it).
        const auto it = std::upper_bound(tuned.t.begin(), tuned.t.end(), t);
        const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - tuned.t.begin() - 1));
        marks->append(t * 1000.0, y[i]);
    }
    chart->addSeries(marks);
    const std::tuple<profile::ProfileShape, QString, QColor> shapes[] = {
        {profile::ProfileShape::trapezoid, tr("Trapezoid"), QColor(230, 120, 0)},
        {profile::ProfileShape::scurve, tr("S-curve (smoothstep)"), QColor(0, 140, 70)},
        {profile::ProfileShape::jerk, tr("Jerk-limited (7 segments)"), QColor(140, 0, 160)}};
    const auto add_row = [&](const QString& name, double seconds) {
        const int r = shapes_->rowCount();
        shapes_->insertRow(r);
        shapes_->setItem(r, 0, new QTableWidgetItem(name));
        shapes_->setItem(r, 1, new QTableWidgetItem(format_duration(seconds)));
        shapes_->setItem(r, 2, new QTableWidgetItem(percent_over(seconds, pass.lower_bound_s)));
    };
    add_row(tr("Planned (auto-tuned)"), pass.duration_s);
    for (const auto& [shape, name, colour] : shapes) {
        const auto curves = pass_curves_with(pass, plan_->profile, shape);
        add_row(name, curves.duration_s + pass.feed.duration_s);  // the paper feed comes with every pass
        if (compare_->isChecked()) {
            auto* s = series_of(curves, q, name);
            s->setPen(QPen(colour, 1.5, Qt::DashLine));
            chart->addSeries(s);
        }
    }
    chart->createDefaultAxes();
    if (auto h = chart->axes(Qt::Horizontal); !h.isEmpty()) h.front()->setTitleText(tr("Time (ms)"));
    if (auto v = chart->axes(Qt::Vertical); !v.isEmpty()) v.front()->setTitleText(quantity_->currentText());
    chart->setTitle(tr("Sheet %1, pass %2").arg(sheet.index).arg(pass_->value()));

    for (const auto& s : pass.strikes) {
        const int r = strikes_->rowCount();
        strikes_->insertRow(r);
        strikes_->setItem(r, 0, new QTableWidgetItem(QString::number(tuned.strike_t[static_cast<std::size_t>(r)] * 1000, 'f', 2)));
        strikes_->setItem(r, 1, new QTableWidgetItem(QString::number(s.carriage_step / plan_->profile.carriage.steps_per_mm, 'f', 2)));
        strikes_->setItem(r, 2, new QTableWidgetItem(s.side == plan::Side::front ? tr("front") : tr("back")));
        strikes_->setItem(r, 3, new QTableWidgetItem(QString::number(s.residual_um, 'f', 2)));
    }
    const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
    chart_view_->setAccessibleDescription(
        tr("%1 against time for sheet %2, pass %3: %4 strikes over %5; from %6 to %7. The strike table lists the same data.")
            .arg(quantity_->currentText())
            .arg(sheet.index)
            .arg(pass_->value())
            .arg(pass.strikes.size())
            .arg(format_duration(tuned.duration_s))
            .arg(*lo, 0, 'g', 4)
            .arg(*hi, 0, 'g', 4));
}

}  // namespace tactus::gui
