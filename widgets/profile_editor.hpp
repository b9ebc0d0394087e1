// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer profile editor for technicians: every field with its unit and
// range, checked by core's validate() as it is typed. A bad value is named in
// plain words (and announced); the views keep the last valid profile meanwhile.
#include <QWidget>
#include <functional>
#include <vector>

#include "profile/profile.hpp"
#include "profile/profile_problem.hpp"

class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace tactus::gui {

class ProfileEditor : public QWidget {
    Q_OBJECT
public:
    explicit ProfileEditor(QWidget* parent = nullptr);
    [[nodiscard]] const profile::PrinterProfile& profile() const { return valid_; }
    [[nodiscard]] QString error() const;
    void set_profile(const profile::PrinterProfile& p);
    // The spin box editing a field ("carriage.v_max_mm_s"), for tests and focus.
    [[nodiscard]] QDoubleSpinBox* field(const QString& name) const;
    bool load(const QString& path);
    bool save(const QString& path);

Q_SIGNALS:
    void profile_changed(const tactus::profile::PrinterProfile& p);
    void message(const QString& text, bool error);

private:
    struct Field {
        QString name;
        QDoubleSpinBox* box = nullptr;
        std::function<double&(profile::PrinterProfile&)> ref;
    };
    void add(QFormLayout* form, const QString& name, const QString& label, const QString& unit, double lo,
             double hi, int decimals, std::function<double&(profile::PrinterProfile&)> ref);
    void edited();
    // Puts a problem in the field's accessible description, or takes it out.
    static void mark_invalid(QDoubleSpinBox* box, const QString& problem);
    static QString problem_text(const profile::ProfileProblem& p);

    std::vector<Field> fields_;
    profile::PrinterProfile valid_;
    QLabel* status_ = nullptr;
    QString bad_label_;  // the field the standing error names, as the form reads it
    bool loading_ = false;
};

}  // namespace tactus::gui
