// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The vibration panel: the head's step response against the sources' targets
// (overshoot < 2 %, rise < 5 ms, settling < 10 ms) with pass or fail, the
// residual vibration at each strike of the planned sheets (histogram and worst
// case), and the frequency response. Tables carry the numbers for screen readers.
#include <QWidget>

#include "estimate/vibration.hpp"
#include "motion_model.hpp"

class QChartView;
class QLabel;
class QTableWidget;

namespace tactus::gui {

class VibrationView : public QWidget {
    Q_OBJECT
public:
    explicit VibrationView(QWidget* parent = nullptr);
    void set_profile(const profile::PrinterProfile& p);
    void set_plan(const DocumentPlanPtr& plan);
    [[nodiscard]] QTableWidget* metrics() const { return metrics_; }
    [[nodiscard]] const estimate::VibrationReport& report() const { return report_; }
    [[nodiscard]] QString residual_summary() const;

private:
    QTableWidget* metrics_;
    QLabel* modes_;
    QLabel* residuals_;
    QChartView* histogram_;
    QChartView* response_;
    estimate::VibrationReport report_;
};

}  // namespace tactus::gui
