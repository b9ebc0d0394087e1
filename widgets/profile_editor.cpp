// SPDX-License-Identifier: GPL-3.0-or-later
#include "profile_editor.hpp"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "profile/profile_json.hpp"
#include "profile/profile_problem.hpp"

namespace tactus::gui {
namespace {

QString unit_text(const std::string& u) {
    if (u == "um") return QStringLiteral("\u00b5m");
    if (u == "mm/s2") return QStringLiteral("mm/s\u00b2");
    if (u == "mm/s3") return QStringLiteral("mm/s\u00b3");
    if (u == "s") return ProfileEditor::tr("s");
    if (u == "steps/s") return ProfileEditor::tr("steps/s");
    return QString::fromStdString(u);
}

// A number with its unit, as the fields show them ("25 mm").
QString amount(double v, const std::string& unit) {
    const auto n = QString::number(v, 'g', 6);
    return unit.empty() ? n : ProfileEditor::tr("%1 %2", "a number and its unit").arg(n, unit_text(unit));
}

}  // namespace

// The core's problem record in the interface's words (validate() gives the
// same in English for the command line).
QString ProfileEditor::problem_text(const profile::ProfileProblem& p) {
    using K = profile::ProblemKind;
    const auto value = amount(p.value, p.unit);
    const auto limit = amount(p.limit, p.unit);
    switch (p.kind) {
        case K::out_of_range:
            return tr("is %1, must be between %2 and %3").arg(value, QString::number(p.limit, 'g', 6), amount(p.high, p.unit));
        case K::not_above_zero: return tr("is %1, must be above 0").arg(value);
        case K::above_maximum: return tr("is %1, must not exceed %2").arg(value, limit);
        case K::below_physical_minimum: return tr("is %1, below the physical minimum of %2").arg(value, limit);
        case K::too_slow: return tr("is %1, below %2: motion that slow would take days to plan and to emboss").arg(value, limit);
        case K::too_many_steps:
            return tr("needs %1, more than the controller can time (%2, 8 timer ticks per step)").arg(value, limit);
        case K::not_above_dot_pitch: return tr("is %1, must exceed the dot pitch (%2) so neighbouring cells stay apart").arg(value, limit);
        case K::not_above_cell_height: return tr("is %1, must exceed the cell height (%2)").arg(value, limit);
        case K::line_too_wide:
            return tr("%n cell(s) need %1 but the paper leaves %2 between the margins", nullptr, p.count).arg(value, limit);
        case K::page_too_tall:
            return tr("%n line(s) need %1 but the paper leaves %2 between the margins", nullptr, p.count).arg(value, limit);
        case K::back_dots_off_paper: return tr("is %1, which puts back-side dots off the paper").arg(value);
        case K::wider_than_paper: return tr("is %1, wider than the paper (%2): one hammer could never reach it").arg(value, limit);
        case K::finer_than_half_step:
            return tr("is %1, finer than half a carriage step (%2): unreachable at any speed").arg(value, limit);
    }
    return tr("is %1").arg(value);
}

ProfileEditor::ProfileEditor(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("profileEditor"));
    valid_ = profile::default_profile();
    auto* inner = new QWidget;
    auto* outer = new QVBoxLayout(inner);
    const auto group = [&](const QString& title) {
        auto* box = new QGroupBox(title, inner);
        auto* form = new QFormLayout(box);
        outer->addWidget(box);
        return form;
    };
    using P = profile::PrinterProfile;
    auto* paper = group(tr("Paper"));
    add(paper, "paper.width_mm", tr("Width"), tr("mm"), 1, 2000, 1, [](P& p) -> double& { return p.paper.width_mm; });
    add(paper, "paper.height_mm", tr("Height"), tr("mm"), 1, 5000, 1, [](P& p) -> double& { return p.paper.height_mm; });
    add(paper, "paper.margin_left_mm", tr("Left margin"), tr("mm"), 0, 2000, 1, [](P& p) -> double& { return p.paper.margin_left_mm; });
    add(paper, "paper.margin_top_mm", tr("Top margin"), tr("mm"), 0, 5000, 1, [](P& p) -> double& { return p.paper.margin_top_mm; });
    auto* geometry = group(tr("Braille geometry"));
    add(geometry, "geometry.dot_pitch_mm", tr("Dot pitch"), tr("mm"), 0.1, 20, 2, [](P& p) -> double& { return p.geometry.dot_pitch_mm; });
    add(geometry, "geometry.cell_pitch_mm", tr("Cell pitch"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.geometry.cell_pitch_mm; });
    add(geometry, "geometry.line_pitch_mm", tr("Line pitch"), tr("mm"), 0.1, 200, 2, [](P& p) -> double& { return p.geometry.line_pitch_mm; });
    add(geometry, "geometry.back_offset_x_mm", tr("Back offset across"), tr("mm"), -50, 50, 2, [](P& p) -> double& { return p.geometry.back_offset_x_mm; });
    add(geometry, "geometry.back_offset_y_mm", tr("Back offset down"), tr("mm"), -50, 50, 2, [](P& p) -> double& { return p.geometry.back_offset_y_mm; });
    auto* head = group(tr("Head and carriage"));
    add(head, "head.concave_offset_mm", tr("Concave hammer offset"), tr("mm"), -500, 500, 2, [](P& p) -> double& { return p.head.concave_offset_mm; });
    add(head, "head.dwell_s", tr("Hammer dwell"), tr("s"), 0.0001, 10, 4, [](P& p) -> double& { return p.head.dwell_s; });
    add(head, "carriage.steps_per_mm", tr("Carriage steps"), tr("steps/mm"), 0.01, 10000, 2, [](P& p) -> double& { return p.carriage.steps_per_mm; });
    add(head, "carriage.v_max_mm_s", tr("Carriage top speed"), tr("mm/s"), 0.01, 10000, 1, [](P& p) -> double& { return p.carriage.v_max_mm_s; });
    add(head, "carriage.a_max_mm_s2", tr("Carriage acceleration"), tr("mm/s\u00b2"), 1, 1e7, 0, [](P& p) -> double& { return p.carriage.a_max_mm_s2; });
    add(head, "carriage.j_max_mm_s3", tr("Carriage jerk"), tr("mm/s\u00b3"), 1, 1e11, 0, [](P& p) -> double& { return p.carriage.j_max_mm_s3; });
    add(head, "carriage.backlash_mm", tr("Carriage backlash"), tr("mm"), 0, 1, 3, [](P& p) -> double& { return p.carriage.backlash_mm; });
    add(head, "motion.step_tolerance", tr("Step timing tolerance"), tr("of a step interval"), 0, 0.5, 2, [](P& p) -> double& { return p.motion.step_tolerance; });
    auto* dynamics = group(tr("Dynamics and vibration"));
    add(dynamics, "dynamics.head_mass_kg", tr("Head mass"), tr("kg"), 0.001, 1000, 3, [](P& p) -> double& { return p.dynamics.head_mass_kg; });
    add(dynamics, "dynamics.belt_stiffness_n_m", tr("Belt stiffness"), tr("N/m"), 1, 1e9, 0, [](P& p) -> double& { return p.dynamics.belt_stiffness_n_m; });
    add(dynamics, "dynamics.damping_ratio", tr("Damping ratio"), QString(), 0, 0.99, 3, [](P& p) -> double& { return p.dynamics.damping_ratio; });
    add(dynamics, "vibration.tolerance_um", tr("Position tolerance at the strike"), tr("\u00b5m"), 0.1, 1e5, 1, [](P& p) -> double& { return p.vibration.tolerance_um; });

    // Tactile graphics' dot spacings: the spin boxes only keep the number sane;
    // their real bounds follow the dot pitch and each other (core's validate()).
    auto* graphic = group(tr("Tactile graphics"));
    add(graphic, "graphic.line_dot_spacing_mm", tr("Dot spacing along a solid line"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.graphic.line_dot_spacing_mm; });
    add(graphic, "graphic.dotted_dot_spacing_mm", tr("Dot spacing along a dotted line"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.graphic.dotted_dot_spacing_mm; });
    add(graphic, "graphic.dash_gap_mm", tr("Gap between dashes"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.graphic.dash_gap_mm; });
    add(graphic, "graphic.texture_pitch_mm", tr("Texture row spacing"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.graphic.texture_pitch_mm; });
    add(graphic, "graphic.texture_dot_spacing_mm", tr("Dot spacing along a texture row"), tr("mm"), 0.1, 100, 2, [](P& p) -> double& { return p.graphic.texture_dot_spacing_mm; });

    auto* scroll = new QScrollArea(this);
    scroll->setWidget(inner);
    scroll->setWidgetResizable(true);
    scroll->setAccessibleName(tr("Profile fields"));
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("profileStatus"));
    status_->setWordWrap(true);
    status_->setAccessibleName(tr("Profile check"));
    auto* load_button = new QPushButton(tr("&Load profile..."), this);
    auto* save_button = new QPushButton(tr("Save pr&ofile..."), this);
    auto* reset_button = new QPushButton(tr("&Defaults"), this);
    connect(load_button, &QPushButton::clicked, this, [this] {
        const auto path = QFileDialog::getOpenFileName(this, tr("Load printer profile"), {}, tr("Profiles (*.json)"));
        if (!path.isEmpty()) load(path);
    });
    connect(save_button, &QPushButton::clicked, this, [this] {
        const auto path = QFileDialog::getSaveFileName(this, tr("Save printer profile"), {}, tr("Profiles (*.json)"));
        if (!path.isEmpty()) save(path);
    });
    connect(reset_button, &QPushButton::clicked, this, [this] { set_profile(profile::default_profile()); });
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(load_button);
    buttons->addWidget(save_button);
    buttons->addWidget(reset_button);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(status_);
    layout->addWidget(scroll, 1);
    layout->addLayout(buttons);
    set_profile(valid_);
}

void ProfileEditor::add(QFormLayout* form, const QString& name, const QString& label, const QString& unit, double lo,
                        double hi, int decimals, std::function<double&(profile::PrinterProfile&)> ref) {
    auto* box = new QDoubleSpinBox(this);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setKeyboardTracking(true);
    if (!unit.isEmpty()) box->setSuffix(QLatin1Char(' ') + unit);
    const auto range = tr("%1 to %2 %3").arg(lo).arg(hi).arg(unit).trimmed();
    box->setAccessibleName(unit.isEmpty() ? label : tr("%1 in %2").arg(label, unit));
    box->setAccessibleDescription(tr("Range %1; profile field %2").arg(range, name));
    box->setToolTip(box->accessibleDescription());
    box->setProperty("usualDescription", box->accessibleDescription());
    form->addRow(tr("%1:", "a form field's label").arg(label), box);
    connect(box, &QDoubleSpinBox::valueChanged, this, &ProfileEditor::edited);
    fields_.push_back({name, box, std::move(ref)});
}

void ProfileEditor::mark_invalid(QDoubleSpinBox* box, const QString& problem) {
    const auto usual = box->property("usualDescription").toString();
    const auto wanted = problem.isEmpty() ? usual : tr("Invalid: %1. %2").arg(problem, usual);
    if (box->accessibleDescription() != wanted) box->setAccessibleDescription(wanted);
}

QDoubleSpinBox* ProfileEditor::field(const QString& name) const {
    for (const auto& f : fields_)
        if (f.name == name) return f.box;
    return nullptr;
}

QString ProfileEditor::error() const { return status_->property("error").toBool() ? status_->text() : QString(); }

void ProfileEditor::set_profile(const profile::PrinterProfile& p) {
    loading_ = true;
    auto copy = p;
    for (auto& f : fields_) f.box->setValue(f.ref(copy));
    loading_ = false;
    edited();
}

void ProfileEditor::edited() {
    if (loading_) return;
    auto candidate = valid_;
    for (auto& f : fields_) f.ref(candidate) = f.box->value();
    if (auto problem = profile::first_problem(candidate)) {
        // Name the field in words the technician used in the form.
        const auto field = QString::fromStdString(problem->field);
        const auto why = problem_text(*problem);
        QString label = field;
        for (auto& f : fields_) {
            const bool bad = f.name == field;
            f.box->setProperty("invalid", bad);
            if (bad) label = f.box->accessibleName();
            f.box->setStyleSheet(bad ? QStringLiteral("QDoubleSpinBox { border: 2px solid #c00000; }") : QString());
        }
        const auto text = tr("%1 %2. The plan and preview keep the last valid profile.").arg(label, why);
        bad_label_ = label;
        // Back on the field later, the screen reader says it is invalid and why.
        for (auto& f : fields_) mark_invalid(f.box, f.name == field ? why : QString());
        status_->setText(text);
        status_->setProperty("error", true);
        Q_EMIT message(text, true);
        return;
    }
    for (auto& f : fields_) {
        f.box->setStyleSheet(QString());
        mark_invalid(f.box, {});
    }
    const bool was_error = status_->property("error").toBool();
    const bool changed = !(candidate == valid_) || was_error;
    valid_ = candidate;
    status_->setText(tr("Profile is valid."));
    status_->setProperty("error", false);
    // The fix is heard as the error was, naming the field the error named (the
    // user may have fixed it from another field, as a wider paper fixes a margin).
    if (was_error) Q_EMIT message(tr("%1 is valid again.", "a profile field whose error is fixed").arg(bad_label_), false);
    bad_label_.clear();
    if (changed) Q_EMIT profile_changed(valid_);
}

bool ProfileEditor::load(const QString& path) {
    auto p = profile::load_profile(path.toStdString());
    if (!p) {
        Q_EMIT message(tr("Cannot load %1: %2").arg(path, QString::fromStdString(p.error().to_string())), true);
        return false;
    }
    valid_ = *p;
    set_profile(*p);
    Q_EMIT profile_changed(valid_);
    Q_EMIT message(tr("Loaded profile %1").arg(QString::fromStdString(p->name)), false);
    return true;
}

bool ProfileEditor::save(const QString& path) {
    if (auto ok = profile::save_profile(valid_, path.toStdString()); !ok) {
        Q_EMIT message(tr("Cannot save %1: %2").arg(path, QString::fromStdString(ok.error().to_string())), true);
        return false;
    }
    Q_EMIT message(tr("Saved profile to %1").arg(path), false);
    return true;
}

}  // namespace tactus::gui
