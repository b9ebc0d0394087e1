// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The technician's motion view: for a sheet and pass, carriage position,
// velocity, acceleration or jerk against time with the strikes marked, other
// profile shapes on the same pass for comparison, and time estimates against
// the lower bound. A table of the strikes carries the same data for screen readers.
#include <QWidget>

#include "motion_model.hpp"

class QChart;
class QChartView;
class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace tactus::gui {

class MotionView : public QWidget {
    Q_OBJECT
public:
    explicit MotionView(QWidget* parent = nullptr);
    void set_plan(DocumentPlanPtr plan);
    [[nodiscard]] const DocumentPlanPtr& plan() const { return plan_; }
    [[nodiscard]] QString summary() const;
    [[nodiscard]] QTableWidget* shape_table() const { return shapes_; }
    [[nodiscard]] QTableWidget* strike_table() const { return strikes_; }
    void select(int sheet, int pass);

private:
    void refresh();
    DocumentPlanPtr plan_;
    QSpinBox* sheet_;
    QSpinBox* pass_;
    QComboBox* quantity_;
    QCheckBox* compare_;
    QChartView* chart_view_;
    QLabel* times_;
    QTableWidget* shapes_;
    QTableWidget* strikes_;
};

// "3 min 12.4 s" / "0.213 s"
QString format_duration(double seconds);

}  // namespace tactus::gui
