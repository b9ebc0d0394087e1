// SPDX-License-Identifier: GPL-3.0-or-later
#include "fit_columns.hpp"
#include "vibration_view.hpp"
#include "status_label.hpp"

#include <QBarCategoryAxis>
#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

namespace tactus::gui {

VibrationView::VibrationView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("vibrationView"));
    metrics_ = new QTableWidget(0, 4, this);
    metrics_->setObjectName(QStringLiteral("vibrationMetrics"));
    metrics_->setAccessibleName(tr("Step response against the targets"));
    metrics_->setHorizontalHeaderLabels({tr("Quantity"), tr("Value"), tr("Target"), tr("Result")});
    metrics_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    metrics_->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    fit_columns_to_headings(metrics_);
    metrics_->verticalHeader()->setVisible(false);
    modes_ = new QLabel(this);
    expose_status(modes_, tr("Natural frequencies"));
    modes_->setWordWrap(true);
    residuals_ = new QLabel(this);
    residuals_->setObjectName(QStringLiteral("residualSummary"));
    residuals_->setAccessibleName(tr("Residual vibration at the strikes"));
    residuals_->setWordWrap(true);
    histogram_ = new QChartView(new QChart, this);
    histogram_->setObjectName(QStringLiteral("residualHistogram"));
    histogram_->setAccessibleName(tr("Residual vibration histogram"));
    histogram_->setFocusPolicy(Qt::StrongFocus);
    histogram_->setMinimumHeight(180);
    response_ = new QChartView(new QChart, this);
    response_->setObjectName(QStringLiteral("frequencyResponse"));
    response_->setAccessibleName(tr("Frequency response chart"));
    response_->setFocusPolicy(Qt::StrongFocus);
    response_->setMinimumHeight(180);
    for (auto* v : {histogram_, response_}) {
        v->setRenderHint(QPainter::Antialiasing);
        v->viewport()->setAccessibleName(v->accessibleName());  // the focusable part of a chart view
    }
    auto* charts = new QSplitter(Qt::Vertical, this);
    charts->addWidget(histogram_);
    charts->addWidget(response_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(metrics_);
    layout->addWidget(modes_);
    layout->addWidget(residuals_);
    layout->addWidget(charts, 1);
    set_profile(profile::default_profile());
}

void VibrationView::set_profile(const profile::PrinterProfile& p) {
    report_ = estimate::vibration_report(p, 61);
    const auto& s = report_.step;
    const auto& t = report_.targets;
    metrics_->setRowCount(0);
    const auto row = [&](const QString& name, const QString& value, const QString& target, bool ok) {
        const int r = metrics_->rowCount();
        metrics_->insertRow(r);
        metrics_->setItem(r, 0, new QTableWidgetItem(name));
        metrics_->setItem(r, 1, new QTableWidgetItem(value));
        metrics_->setItem(r, 2, new QTableWidgetItem(target));
        auto* result = new QTableWidgetItem(ok ? tr("pass") : tr("FAIL"));
        result->setForeground(ok ? QColor(0, 110, 0) : QColor(190, 0, 0));
        metrics_->setItem(r, 3, result);
    };
    row(tr("Overshoot"), tr("%1 %").arg(s.overshoot_pct, 0, 'f', 2), tr("< %1 %").arg(t.overshoot_pct),
        report_.overshoot_ok);
    row(tr("Rise time (10-90 %)"), tr("%1 ms").arg(s.rise_time_s * 1000, 0, 'f', 2),
        tr("< %1 ms").arg(t.rise_time_s * 1000), report_.rise_ok);
    row(tr("Settling time (2 %)"),
        s.settling_time_s ? tr("%1 ms").arg(*s.settling_time_s * 1000, 0, 'f', 2) : tr("never settles"),
        tr("< %1 ms").arg(t.settling_time_s * 1000), report_.settling_ok);
    // Exactly as tall as its rows: a fixed guess left half a row's blank or
    // pushed the charts down until their axis labels were elided.
    int height = metrics_->horizontalHeader()->sizeHint().height() + 2 * metrics_->frameWidth();
    for (int r = 0; r < metrics_->rowCount(); ++r) height += metrics_->rowHeight(r);
    metrics_->setFixedHeight(height);
    QStringList hz;
    for (double f : report_.natural_hz) hz << QString::number(f, 'f', 1);
    modes_->setText(tr("%1 model; natural frequencies %2 Hz; \u221a(k/m) = %3 rad/s; damping ratio %4.")
                        .arg(report_.two_inertia ? tr("Two-inertia") : tr("One-inertia"), hz.join(QStringLiteral(", ")))
                        .arg(report_.sqrt_k_over_m, 0, 'f', 0)
                        .arg(report_.damping_ratio, 0, 'f', 2));

    auto* chart = response_->chart();
    chart->removeAllSeries();
    for (auto* a : chart->axes()) chart->removeAxis(a);
    auto* magnitude = new QLineSeries;
    magnitude->setName(tr("Magnitude (dB)"));
    auto* phase = new QLineSeries;
    phase->setName(tr("Phase (degrees)"));
    double peak_db = -1e9, peak_hz = 0;
    for (const auto& pt : report_.response) {
        magnitude->append(pt.frequency_hz, pt.magnitude_db);
        phase->append(pt.frequency_hz, pt.phase_deg);
        if (pt.magnitude_db > peak_db) {
            peak_db = pt.magnitude_db;
            peak_hz = pt.frequency_hz;
        }
    }
    magnitude->setPen(QPen(QColor(0, 70, 160), 2));
    phase->setPen(QPen(QColor(230, 120, 0), 2, Qt::DashLine));
    chart->addSeries(magnitude);
    chart->addSeries(phase);
    auto* f_axis = new QLogValueAxis;
    f_axis->setTitleText(tr("Frequency (Hz)"));
    f_axis->setLabelFormat(QStringLiteral("%g"));
    auto* db_axis = new QValueAxis;
    db_axis->setTitleText(tr("dB"));
    auto* deg_axis = new QValueAxis;
    deg_axis->setTitleText(tr("degrees"));
    chart->addAxis(f_axis, Qt::AlignBottom);
    chart->addAxis(db_axis, Qt::AlignLeft);
    chart->addAxis(deg_axis, Qt::AlignRight);
    magnitude->attachAxis(f_axis);
    magnitude->attachAxis(db_axis);
    phase->attachAxis(f_axis);
    phase->attachAxis(deg_axis);
    chart->setTitle(tr("Head position versus command"));
    response_->setAccessibleDescription(tr("Peak %1 dB at %2 Hz; %3 points from %4 to %5 Hz.")
                                            .arg(peak_db, 0, 'f', 1)
                                            .arg(peak_hz, 0, 'f', 1)
                                            .arg(report_.response.size())
                                            .arg(report_.response.empty() ? 0.0 : report_.response.front().frequency_hz, 0, 'g', 3)
                                            .arg(report_.response.empty() ? 0.0 : report_.response.back().frequency_hz, 0, 'g', 3));
    metrics_->setAccessibleDescription(report_.all_ok() ? tr("All targets met") : tr("Some targets are not met"));
}

QString VibrationView::residual_summary() const { return residuals_->text(); }

void VibrationView::set_plan(const DocumentPlanPtr& plan) {
    auto* chart = histogram_->chart();
    chart->removeAllSeries();
    for (auto* a : chart->axes()) chart->removeAxis(a);
    if (!plan || plan->error || plan->sheets.empty()) {
        residuals_->setText(plan && plan->error ? QString::fromStdString(plan->error->to_string()) : tr("No plan yet"));
        return;
    }
    std::vector<double> nominal, worst;
    double worst_value = -1;
    QString worst_where;
    for (const auto& sheet : plan->sheets)
        for (std::size_t p = 0; p < sheet.passes.size(); ++p)
            for (const auto& s : sheet.passes[p].strikes) {
                nominal.push_back(s.residual_um);
                worst.push_back(s.worst_residual_um);
                if (s.worst_residual_um > worst_value) {
                    worst_value = s.worst_residual_um;
                    worst_where = tr("sheet %1, pass %2").arg(sheet.index).arg(p + 1);
                }
            }
    const double tolerance = plan->profile.vibration.tolerance_um;
    constexpr int kBins = 10;
    const double top = std::max({tolerance, worst_value, 1e-9});
    auto* nominal_set = new QBarSet(tr("Nominal machine"));
    auto* worst_set = new QBarSet(tr("Worst case over the band"));
    QStringList labels;
    std::vector<int> n(kBins), w(kBins);
    const auto bin = [&](double v) { return std::clamp(static_cast<int>(v / top * kBins), 0, kBins - 1); };
    for (double v : nominal) ++n[static_cast<std::size_t>(bin(v))];
    for (double v : worst) ++w[static_cast<std::size_t>(bin(v))];
    for (int b = 0; b < kBins; ++b) {
        nominal_set->append(n[static_cast<std::size_t>(b)]);
        worst_set->append(w[static_cast<std::size_t>(b)]);
        labels << QString::number(top * (b + 1) / kBins, 'g', 3);
    }
    nominal_set->setColor(QColor(0, 70, 160));
    worst_set->setColor(QColor(230, 120, 0));
    auto* series = new QBarSeries;
    series->append(nominal_set);
    series->append(worst_set);
    chart->addSeries(series);
    auto* x = new QBarCategoryAxis;
    x->append(labels);
    x->setTitleText(tr("Residual up to (\u00b5m)"));
    auto* y = new QValueAxis;
    y->setTitleText(tr("Strikes"));
    y->setLabelFormat(QStringLiteral("%d"));
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    y->setRange(0, std::max(1, *std::max_element(w.begin(), w.end())));
    chart->setTitle(tr("Residual vibration per strike"));
    const bool ok = worst_value <= tolerance;
    residuals_->setText(tr("%1 strikes on %2 planned sheets: worst case %3 \u00b5m at %4 (tolerance %5 \u00b5m) \u2014 %6.")
                            .arg(nominal.size())
                            .arg(plan->sheets.size())
                            .arg(worst_value, 0, 'f', 2)
                            .arg(worst_where)
                            .arg(tolerance, 0, 'f', 1)
                            .arg(ok ? tr("within tolerance") : tr("OVER TOLERANCE")));
    histogram_->setAccessibleDescription(residuals_->text());
}

}  // namespace tactus::gui
