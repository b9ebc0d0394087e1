// SPDX-License-Identifier: GPL-3.0-or-later
#include "printer_panel.hpp"
#include "printer_panel_rows.hpp"

#include <QComboBox>
#include <QDateTime>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

#include "controller/builtin_sim.hpp"
#include "controller/device_choices.hpp"
#include "ipp/queue_uri.hpp"
#include "link/fault_words.hpp"
#include "link/link.hpp"
#include "profile/controller_config.hpp"
#include "profile/firmware_tables.hpp"
#include "profile/profile_json.hpp"
#include "spool/db_path.hpp"
#include "spool/printer_setup.hpp"
#include "spool/printing.hpp"
#include "spool/runner.hpp"
#include "spool/strike_check.hpp"
#include "spool/runner_token.hpp"
#include "spool/snapshot.hpp"
#include "spool/spool.hpp"
#include "emboss_choice.hpp"
#include "status_label.hpp"
#include "transport/device.hpp"

namespace tactus::gui {
namespace {

constexpr const char* kSim = "sim";
// The choices of the simulator's speed: the value of its `speed` option ("": none, the plan's own speed).
constexpr const char* kFaster = "10";
constexpr const char* kMax = "max";
constexpr std::size_t kFinishedShown = 100;
using namespace panel;

QString state_text(spool::JobState s) {
    switch (s) {
        case spool::JobState::queued: return QObject::tr("waiting");
        case spool::JobState::running: return QObject::tr("embossing");
        case spool::JobState::paused: return QObject::tr("paused");
        case spool::JobState::completed: return QObject::tr("done");
        case spool::JobState::failed: return QObject::tr("stopped");
        case spool::JobState::cancelled: return QObject::tr("cancelled");
    }
    return {};
}

// A `sim` device string (with or without options): the app's built-in simulator.
bool is_sim(const std::string& device) {
    const auto spec = transport::parse_device(device);
    return spec && spec->scheme == kSim;
}
bool is_sim(const QString& device) { return is_sim(device.toStdString()); }

// The simulator's speed option in a `sim` device string: "" (none: the plan's
// own speed), a number, or "max".
QString speed_option(const QString& device) {
    const auto spec = transport::parse_device(device.toStdString());
    if (!spec) return {};
    const auto it = spec->options.find("speed");
    return it == spec->options.end() ? QString() : qs(it->second);
}

// `device` with its speed option set to `speed` ("": removed).
QString with_speed(const QString& device, const QString& speed) {
    auto spec = transport::parse_device(device.toStdString());
    if (!spec) return device;
    if (speed.isEmpty()) spec->options.erase("speed");
    else spec->options["speed"] = speed.toStdString();
    return qs(transport::format_device(*spec));
}

// Opens the printer's device: the app's one built-in simulator for any `sim`
// device string, with that string's options (so its controller keeps its count
// across connections), else the cable.
spool::ConnectFn connector(std::shared_ptr<controller::BuiltInSimulator> sim, link::LinkOptions options) {
    return [sim = std::move(sim), options](const spool::PrinterRecord& p) -> Result<link::Link> {
        if (is_sim(p.device)) {
            auto spec = transport::parse_device(p.device);
            auto settings = spec ? transport::sim_settings(*spec) : std::unexpected(spec.error());
            if (!settings) return std::unexpected(settings.error());
            // The built-in simulator runs the firmware the printer's profile
            // makes (protocol 3), unless the device string says protocol=2.
            const auto tables = spool::printer_firmware_tables(p);
            auto stream = sim->connect(*settings, tables);
            if (!stream) return std::unexpected(stream.error());
            return link::Link::over(std::move(*stream), options);
        }
        return spool::open_printer(p, options);
    };
}

// What the app says of a finished job on its built-in simulator: the
// strikes the simulated controller logged against the plan (core's check).
QString strike_check_text(const Result<spool::StrikeCheck>& check) {
    if (!check) return QObject::tr("the strikes could not be checked: %1").arg(qs(check.error().to_string()));
    if (!check->agrees)
        return QObject::tr("%1 strikes embossed but %2 planned: the simulator disagrees with the plan")
            .arg(check->embossed).arg(check->planned);
    return check->first_sheet > 1
               ? QObject::tr("all %1 strikes of sheets %2 to %3 checked against the plan")
                     .arg(check->embossed).arg(check->first_sheet).arg(check->last_sheet)
               : QObject::tr("all %1 strikes checked against the plan").arg(check->embossed);
}

}  // namespace

QString panel::joined(const QString& head, const QString& detail) {
    return detail.isEmpty() ? head : PrinterPanel::tr("%1: %2", "a message and its detail").arg(head, detail);
}

// This window's runner: core's spool::Runner on its own thread, stopped and
// joined when the window lets go of the printer.
struct PrinterPanel::AppRunner {
    std::atomic<bool> stop{false};
    std::unique_ptr<spool::Runner> runner;
    std::thread thread;
    std::mutex mutex;
    std::optional<Error> error;  // the spool became unusable

    ~AppRunner() {
        stop = true;
        if (thread.joinable()) thread.join();
        runner->finish();
    }
};

PrinterPanel::PrinterPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("printerPanel"));
    if (auto p = spool::spool_path(); p) db_ = *p;
    devices_ = new QComboBox(this);
    devices_->setObjectName(QStringLiteral("devicePicker"));
    devices_->setEditable(true);
    devices_->setInsertPolicy(QComboBox::NoInsert);
    devices_->setAccessibleName(tr("Embosser"));
    devices_->setAccessibleDescription(
        tr("The built-in simulator, serial ports with their USB descriptions, HID bridges and parallel ports, "
           "and the Tactus queues of the CUPS servers this computer sees, marked network queue; "
           "or type a device string such as pty:/dev/pts/3, serial:/dev/ttyUSB0?baud=57600 or "
           "ipp://server/printers/Embosser"));
    devices_->lineEdit()->setAccessibleName(tr("Embosser device"));
    auto* refresh_button = new QPushButton(tr("&Refresh"), this);
    connect_ = new QPushButton(tr("&Connect"), this);
    connect_->setObjectName(QStringLiteral("connectButton"));
    choice_ = new EmbossChoice(this);  // after the device row, as it is laid out and tabbed through
    connect(choice_, &EmbossChoice::said, this, [this](const QString& text) { Q_EMIT message(text, false); });
    status_label_ = new QLabel(tr("Not connected"), this);
    status_label_->setObjectName(QStringLiteral("controllerStatus"));
    expose_status(status_label_, tr("Controller status"));
    status_label_->setWordWrap(true);
    status_label_->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
    fault_ = new QLabel(this);
    fault_->setObjectName(QStringLiteral("faultMessage"));
    expose_status(fault_, tr("Fault"));
    fault_->setWordWrap(true);
    fault_->setStyleSheet(QStringLiteral("QLabel { color: #a00000; font-weight: bold; }"));
    queue_ = new QTableWidget(0, col_count, this);
    queue_->setObjectName(QStringLiteral("jobQueue"));
    queue_->setAccessibleName(tr("Job queue"));
    queue_->setAccessibleDescription(tr("The print spool's jobs, from this window, tactus-cli and the network"));
    queue_->setHorizontalHeaderLabels({tr("Job"), tr("Document"), tr("Printer"), tr("State"), tr("Progress"), tr("Sheet")});
    queue_->verticalHeader()->hide();
    queue_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    queue_->setTabKeyNavigation(false);  // Tab leaves the table; arrows move between cells
    queue_->setSelectionBehavior(QAbstractItemView::SelectRows);
    queue_->setSelectionMode(QAbstractItemView::SingleSelection);
    // Each column as wide as its widest text, so a state such as "done: all
    // 1453 strikes checked" is read whole; the document's title takes the rest.
    queue_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    queue_->horizontalHeader()->setSectionResizeMode(col_document, QHeaderView::Stretch);
    pause_ = new QPushButton(tr("&Pause"), this);
    resume_ = new QPushButton(tr("Res&ume"), this);
    cancel_ = new QPushButton(tr("Ca&ncel job"), this);
    pause_->setObjectName(QStringLiteral("pauseJob"));
    resume_->setObjectName(QStringLiteral("resumeJob"));
    cancel_->setObjectName(QStringLiteral("cancelJob"));
    page_ = new QSpinBox(this);
    page_->setRange(1, 100000);
    page_->setAccessibleName(tr("Braille page to resume from"));
    from_page_ = new QPushButton(tr("Resume from pa&ge"), this);
    log_ = new QPlainTextEdit(this);
    log_->setObjectName(QStringLiteral("linkLog"));
    log_->setReadOnly(true);
    log_->setAccessibleName(tr("Link log"));
    log_->setMaximumBlockCount(5000);
    log_->setTabChangesFocus(true);

    // The technician's bench: faults for the built-in simulator only.
    faults_box_ = new QGroupBox(tr("Simulator faults (built-in simulator)"), this);
    faults_box_->setObjectName(QStringLiteral("simulatorFaults"));
    auto* fault_row = new QHBoxLayout(faults_box_);
    const auto fault_button = [&](const QString& text, const QString& name, const QString& what, void (PrinterPanel::*slot)()) {
        auto* b = new QPushButton(text, faults_box_);
        b->setObjectName(name);
        b->setAccessibleDescription(what);
        connect(b, &QPushButton::clicked, this, slot);
        fault_row->addWidget(b);
    };
    fault_button(tr("Paper out"), QStringLiteral("injectPaperOut"),
                 tr("The feeder runs empty; the simulated operator loads paper 5 seconds later"),
                 &PrinterPanel::inject_paper_out);
    fault_button(tr("Pull the cable"), QStringLiteral("injectPulledCable"),
                 tr("The cable is out for 5 seconds; the link reconnects"), &PrinterPanel::inject_pulled_cable);
    fault_button(tr("Line noise"), QStringLiteral("injectNoise"),
                 tr("For 2 seconds, 1 byte in 100 is lost, changed or doubled; the link sends again"),
                 &PrinterPanel::inject_noise);
    fault_button(tr("Controller reset"), QStringLiteral("injectReset"),
                 tr("A watchdog reset: the controller keeps its place and the job continues"),
                 &PrinterPanel::inject_reset);
    // How fast the simulated machine runs: the device string's speed option,
    // chosen here or typed in the picker (docs/gui.md).
    speed_ = new QComboBox(faults_box_);
    speed_->setObjectName(QStringLiteral("simulatorSpeed"));
    speed_->addItem(tr("The plan's own speed"), QString());
    speed_->addItem(tr("10 times faster"), QString::fromLatin1(kFaster));
    speed_->addItem(tr("As fast as the computer can"), QString::fromLatin1(kMax));
    speed_->setAccessibleName(tr("Simulator speed"));
    speed_->setAccessibleDescription(
        tr("How fast the built-in simulator embosses: at the plan's own speed, as the embosser would, or faster. "
           "It sets the speed option of the device string, for example sim?speed=10"));
    auto* speed_label = new QLabel(tr("Speed:"), faults_box_);
    speed_label->setBuddy(speed_);
    fault_row->addWidget(speed_label);
    fault_row->addWidget(speed_);
    fault_row->addStretch();

    auto* device_row = new QHBoxLayout;
    auto* label = new QLabel(tr("E&mbosser:"), this);
    label->setBuddy(devices_);
    device_row->addWidget(label);
    device_row->addWidget(devices_, 1);
    device_row->addWidget(refresh_button);
    device_row->addWidget(connect_);
    auto* job_row = new QHBoxLayout;
    job_row->addWidget(pause_);
    job_row->addWidget(resume_);
    job_row->addWidget(cancel_);
    job_row->addStretch();
    job_row->addWidget(page_);
    job_row->addWidget(from_page_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(device_row);
    layout->addWidget(choice_);
    layout->addWidget(status_label_);
    layout->addWidget(fault_);
    layout->addWidget(queue_, 2);
    layout->addLayout(job_row);
    layout->addWidget(faults_box_);
    auto* log_label = new QLabel(tr("Lin&k log (for technicians):"), this);
    log_label->setBuddy(log_);
    layout->addWidget(log_label);
    layout->addWidget(log_, 1);

    connect(refresh_button, &QPushButton::clicked, this, &PrinterPanel::refresh_devices);
    connect(connect_, &QPushButton::clicked, this, [this] {
        if (connected()) disconnect_device();
        else connect_device(selected_device(), profile_source_ ? profile_source_() : profile::default_profile());
    });
    connect(pause_, &QPushButton::clicked, this, &PrinterPanel::pause_job);
    connect(resume_, &QPushButton::clicked, this, &PrinterPanel::resume_job);
    connect(cancel_, &QPushButton::clicked, this, &PrinterPanel::cancel_job);
    connect(from_page_, &QPushButton::clicked, this, [this] { resume_from_page(page_->value()); });
    connect(queue_, &QTableWidget::itemSelectionChanged, this, &PrinterPanel::update_buttons);
    connect(devices_, &QComboBox::currentTextChanged, this, &PrinterPanel::update_buttons);
    connect(devices_, &QComboBox::currentTextChanged, this, &PrinterPanel::show_speed);
    connect(speed_, &QComboBox::activated, this, [this](int i) { set_simulator_speed(speed_->itemData(i).toString()); });
    // Another process's commit (a runner's progress, `tactus-cli queue`, CUPS)
    // shows as a new PRAGMA data_version: cheap to ask, so asked often.
    poll_timer_.setInterval(200);
    connect(&poll_timer_, &QTimer::timeout, this, &PrinterPanel::poll);
    refresh_devices();
    select_device(QSettings().value(QStringLiteral("printer/last"), QString::fromLatin1(kSim)).toString());
    if (std::filesystem::exists(db_)) open_spool(false);
    refresh();
    poll_timer_.start();
}

PrinterPanel::~PrinterPanel() { stop_runner(); }

void PrinterPanel::set_profile_source(std::function<profile::PrinterProfile()> source) {
    profile_source_ = std::move(source);
}

controller::BuiltInSimulator& PrinterPanel::simulator() {
    if (!sim_) {
        // It runs the reference firmware built from the app's profile
        // (protocol 3); a printer with another profile reflashes it when it
        // connects (BuiltInSimulator::connect).
        auto options = controller::BuiltInSimulator::default_options();
        const auto prof = profile_source_ ? profile_source_() : profile::default_profile();
        if (auto t = profile::make_firmware_tables(prof)) options.firmware = std::move(*t);
        sim_ = std::make_shared<controller::BuiltInSimulator>(options);
    }
    return *sim_;
}

void PrinterPanel::refresh_devices() {
    const auto current = selected_device();
    std::vector<std::string> problems;
    const auto found = controller::list_devices(&problems);
    devices_->clear();
    for (const auto& d : found) {
        // The core names devices in English; the simulator, always listed, in the interface's language.
        const auto description = d.device == kSim ? tr("Built-in simulated embosser") : qs(d.description);
        devices_->addItem(QStringLiteral("%1 [%2]").arg(description, qs(d.device)), qs(d.device));
        devices_->setItemData(devices_->count() - 1,
                              d.device == kSim ? tr("The built-in simulated embosser, on this computer")
                                               : tr("An embosser on a cable to this computer"),
                              Qt::AccessibleDescriptionRole);
    }
    for (const auto& p : problems) log(tr("Listing devices: %1").arg(qs(p)));
    select_device(current);
    discover_queues();
}

QString PrinterPanel::selected_device() const {
    // A listed device shows as "description [device]"; anything else typed is
    // taken as a device string.
    const auto text = devices_->currentText().trimmed();
    const int i = devices_->findText(text);
    if (i >= 0) return devices_->itemData(i).toString();
    return text;
}

void PrinterPanel::select_device(const QString& device) {
    if (device.isEmpty()) return;
    const int i = devices_->findData(device);
    if (i >= 0) devices_->setCurrentIndex(i);
    else devices_->setEditText(device);
}

void PrinterPanel::set_simulator_speed(const QString& speed) {
    const auto device = selected_device();
    if (!is_sim(device)) return;
    const auto changed = with_speed(device, speed);
    if (changed == device) return;
    select_device(changed);
    log(tr("The built-in simulator will run as %1 (%2); it takes effect at the next Connect or job")
            .arg(changed, speed_->currentText()));
}

void PrinterPanel::show_speed() {
    const auto device = selected_device();
    if (!is_sim(device)) return;
    auto speed = speed_option(device);
    if (speed == QLatin1String("1")) speed.clear();
    int i = speed_->findData(speed);
    if (i < 0) {
        // A speed typed in the picker: shown as one more choice.
        speed_->addItem(tr("%1 times faster").arg(speed), speed);
        i = speed_->count() - 1;
    }
    if (speed_->currentIndex() != i) speed_->setCurrentIndex(i);
}

void PrinterPanel::log(const QString& line) {
    log_->appendPlainText(QStringLiteral("%1  %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz")), line));
}

QString PrinterPanel::log_text() const { return log_->toPlainText(); }
QString PrinterPanel::fault_text() const { return fault_->text(); }
QString PrinterPanel::status_text() const { return status_label_->text(); }

void PrinterPanel::show_fault(const QString& text) {
    if (fault_->text() == text) return;  // an unchanged text sends no event
    fault_->setText(text);
    if (!text.isEmpty()) Q_EMIT message(text, true);
}

spool::Spool* PrinterPanel::open_spool(bool create) {
    if (spool_) return spool_.get();
    if (db_.empty()) {
        show_fault(tr("No place for the print queue: set TACTUS_SPOOL_DB or HOME."));
        return nullptr;
    }
    auto s = spool::Spool::open(db_, {.create = create});
    if (!s) {
        show_fault(tr("Cannot open the print queue: %1").arg(qs(s.error().to_string())));
        return nullptr;
    }
    spool_ = std::make_unique<spool::Spool>(std::move(*s));
    return spool_.get();
}

std::string PrinterPanel::setup_printer(const QString& device, const profile::PrinterProfile& p) {
    const auto dev = device.trimmed().toStdString();
    if (auto ok = transport::check_device(dev); !ok) {
        show_fault(tr("“%1” is not a device Tactus can open: %2. Examples: sim, serial:/dev/ttyUSB0?baud=57600, "
                      "pty:/dev/pts/3, hid:10c4:ea80, lpt:/dev/parport0.")
                       .arg(device, qs(ok.error().to_string())));
        return {};
    }
    auto* s = open_spool(true);
    if (!s) return {};
    const auto json = profile::to_json(p).dump();
    bool created = false;
    auto printer = spool::printer_for_device(*s, dev, json, &created);
    if (!printer) {
        show_fault(tr("Cannot set up a printer for %1: %2").arg(device, qs(printer.error().to_string())));
        return {};
    }
    if (created) {
        log(tr("Set up printer %1 on %2 with the profile being edited").arg(qs(printer->name), device));
    } else {
        // The controller is configured and the job planned with the printer's
        // profile: make it the one the user chose here.
        auto stored = profile::parse_profile(printer->profile_json);
        if (!stored || profile::to_json(*stored).dump() != json) {
            if (auto u = s->update_printer(printer->name, std::nullopt, json); !u) {
                show_fault(tr("Cannot give printer %1 the profile being edited: %2")
                               .arg(qs(printer->name), qs(u.error().to_string())));
                return {};
            }
            log(tr("Printer %1 now uses the profile being edited").arg(qs(printer->name)));
        }
    }
    QSettings().setValue(QStringLiteral("printer/last"), device);
    return printer->name;
}

void PrinterPanel::start_runner(const std::string& printer) {
    if (runner_ && printer_ == printer) return;
    stop_runner();
    printer_ = printer;
    auto* s = open_spool(true);
    if (!s) return;
    auto record = s->printer(printer);
    if (!record) return;
    if (!record->runner.empty() && record->runner != spool::this_runner_token() && spool::runner_alive(record->runner)) {
        log(tr("Printer %1 is run by %2: this window shows its jobs").arg(qs(printer), qs(record->runner)));
        update_status();
        return;
    }
    spool::RunnerOptions options;
    options.poll = std::chrono::milliseconds(100);
    if (is_sim(record->device)) simulator();
    auto r = std::make_unique<AppRunner>();
    r->runner = std::make_unique<spool::Runner>(db_, printer, connector(sim_, options.link), options);
    if (auto started = r->runner->start(); !started) {
        // Another runner took it first: watch.
        log(tr("Printer %1: %2; this window shows its jobs").arg(qs(printer), qs(started.error().to_string())));
        update_status();
        return;
    }
    auto* raw = r.get();
    r->thread = std::thread([raw] {
        if (auto ran = raw->runner->run(raw->stop); !ran) {
            std::lock_guard lock(raw->mutex);
            raw->error = ran.error();
        }
    });
    runner_ = std::move(r);
    log(tr("This window runs printer %1").arg(qs(printer)));
    connect_->setText(tr("Dis&connect"));
    update_status();
}

void PrinterPanel::stop_runner() {
    if (!runner_) return;
    // Stopping aborts the job in hand on the controller; it goes back to the
    // queue and the next runner settles it with the controller's count.
    runner_.reset();
    log(tr("This window no longer runs printer %1").arg(qs(printer_)));
}

bool PrinterPanel::connect_device(const QString& device, const profile::PrinterProfile& p) {
    if (ipp::is_queue_uri(device.toStdString())) {
        show_fault(tr("%1 is a CUPS queue: there is nothing to connect to. Ctrl+P sends the document to it.")
                       .arg(device));
        return false;
    }
    const auto printer = setup_printer(device, p);
    if (printer.empty()) return false;
    auto record = spool_->printer(printer);
    if (!record) return false;
    const bool held_elsewhere = !record->runner.empty() && record->runner != spool::this_runner_token() &&
                                spool::runner_alive(record->runner);
    if (!held_elsewhere && !runner_) {
        // Talk to the controller before the runner takes the device: it answers,
        // and it is configured from this profile.
        log(tr("Connecting to %1").arg(device));
        if (is_sim(record->device)) simulator();
        auto link = connector(sim_, {})(*record);
        Result<encode::Status> status = link ? Result<encode::Status>{} : std::unexpected(link.error());
        if (link) {
            if (auto h = link->hello(); !h) status = std::unexpected(h.error());
            else if (auto c = link->configure(profile::controller_config(p)); !c) status = std::unexpected(c.error());
            else status = link->status();
        }
        if (!status) {
            const auto why = qs(located(status.error(), record->device).to_string());
            log(why);
            show_fault(tr("Cannot connect to %1: %2. Check that it is switched on and plugged in, then try again.")
                           .arg(device, why));
            return false;
        }
        status_ = tr("Connected to %1: %2").arg(device, qs(link::explain_status(*status)));
        fault_->clear();
    }
    start_runner(printer);
    select_device(device);
    Q_EMIT message(tr("Connected to %1").arg(devices_->currentText()), false);
    refresh();
    return true;
}

void PrinterPanel::disconnect_device() {
    stop_runner();
    if (!printer_.empty()) log(tr("Disconnected from printer %1").arg(qs(printer_)));
    printer_.clear();
    status_.clear();
    connect_->setText(tr("&Connect"));
    update_status();
    update_buttons();
}

spool::JobId PrinterPanel::submit(const QString& title, const layout::PagedDocument& pages,
                                  const profile::PrinterProfile& p) {
    const auto range = choice_->chosen();
    // The whole document goes as it is (an empty one too); a part is cut from it.
    const bool whole = range && range->first == 0;
    auto cut = range ? (whole ? Result<layout::PagedDocument>{} : spool::select_pages(pages, range->first, range->second))
                     : std::unexpected(range.error());
    if (!cut) {
        show_fault(tr("Cannot queue %1: %2").arg(title, qs(cut.error().message)));
        return 0;
    }
    const auto* part = whole ? &pages : &*cut;
    const auto printer = setup_printer(selected_device(), p);
    if (printer.empty()) return 0;
    spool::JobSubmission job;
    job.printer = printer;
    job.title = title.toStdString();
    job.document = spool::to_snapshot(*part);
    job.sheets_per_copy = part->sheet_count();
    job.first_page = range->first;
    job.last_page = range->second;
    job.user = spool::this_user_name();
    auto id = spool_->submit(job);
    if (!id) {
        show_fault(tr("Cannot queue %1: %2").arg(title, qs(id.error().to_string())));
        return 0;
    }
    watch_[*id] = Watch{};  // followed from "queued", however soon the runner takes it
    log(tr("Queued %1 as job %2 on printer %3").arg(title).arg(*id).arg(qs(printer)));
    Q_EMIT message(tr("%1 added to the queue").arg(title), false);
    if (!runner_ || printer_ != printer) start_runner(printer);
    refresh();
    select_job(*id);
    return *id;
}

void PrinterPanel::poll() {
    follow_queue_jobs();
    if (runner_) {
        std::optional<Error> error;
        {
            std::lock_guard lock(runner_->mutex);
            error = runner_->error;
        }
        if (error) {
            // The runner stopped itself: nothing more could be recorded, so nothing more is embossed.
            stop_runner();
            connect_->setText(tr("&Connect"));
            show_fault(tr("The print queue cannot be written (%1): this window stopped running printer %2")
                           .arg(qs(error->to_string()), qs(printer_)));
            update_status();
        }
    }
    if (!spool_) {
        if (!std::filesystem::exists(db_) || !open_spool(false)) return;
    }
    auto v = spool_->data_version();
    if (v && *v == data_version_) return;
    if (v) data_version_ = *v;
    refresh();
}

void PrinterPanel::refresh() {
    if (!spool_) {
        update_status();
        update_buttons();
        return;
    }
    reload();
    append_events();
    update_status();
    update_buttons();
}

void PrinterPanel::reload() {
    auto all = spool_->jobs(true);
    if (!all) {
        show_fault(tr("Cannot read the print queue: %1").arg(qs(all.error().to_string())));
        return;
    }
    std::vector<spool::JobRecord> shown;
    std::size_t finished = 0;
    for (auto& j : *all) {
        if (spool::is_terminal(j.state) && ++finished > kFinishedShown) continue;
        shown.push_back(std::move(j));
    }
    jobs_ = std::move(shown);
    for (const auto& j : jobs_) {
        // A finished job's progress no longer changes: read it once.
        const auto seen = watch_.find(j.id);
        if (spool::is_terminal(j.state) && seen != watch_.end() && seen->second.state == j.state &&
            shown_.count(j.id))
            continue;
        Shown s;
        std::size_t done = 0, total = 0;
        if (auto progress = spool_->progress(j.id); progress) {
            for (const auto& p : *progress) {
                done += p.passes_done;
                total += p.passes_total;
                if (!s.sheet && !p.done()) s.sheet = p.sheet;
            }
        }
        s.percent = j.state == spool::JobState::completed ? 100 : total ? static_cast<int>(100 * done / total) : 0;
        follow(j, s, done, total);
        shown_[j.id] = s;
    }
    show_jobs();
}

// What a screen reader hears of a job: its start, progress in steps, a fault,
// and its end; other changes only update the row.
void PrinterPanel::follow(const spool::JobRecord& j, const Shown& s, std::size_t done, std::size_t total) {
    const auto title = qs(j.title);
    auto it = watch_.find(j.id);
    if (it == watch_.end()) {
        // Seen for the first time: what happened before is history, not news.
        Watch w;
        w.state = j.state;
        w.reason = j.reason;
        watch_.emplace(j.id, std::move(w));
        return;
    }
    Watch& w = it->second;
    const auto before = w.state;
    w.state = j.state;
    const bool reason_changed = w.reason != j.reason;
    const bool operator_pause_before = before == spool::JobState::paused && w.reason == "paused by the operator";
    w.reason = j.reason;
    if (before != j.state) {
        if (j.state == spool::JobState::running && before == spool::JobState::queued) {
            w.steps = std::make_unique<ProgressSteps>(std::max<std::size_t>(j.total_sheets(), 1));
            log(tr("Embossing %1 (job %2) on %3").arg(title).arg(j.id).arg(qs(j.printer)));
            Q_EMIT message(tr("Embossing %1").arg(title), false);
        }
        if (spool::is_terminal(j.state)) finished(j, s);
    }
    if (j.state == spool::JobState::paused && reason_changed && !j.reason.empty() &&
        j.reason != "paused by the operator")
        announce_fault(j.id, tr("%1 paused: %2").arg(title, qs(j.reason)));
    // Alt+P says "Pausing" at once; the job reaching the state is said too.
    if (before != j.state && j.state == spool::JobState::paused && j.reason == "paused by the operator")
        Q_EMIT message(tr("%1 paused").arg(title), false);
    if (operator_pause_before && j.state == spool::JobState::running)
        Q_EMIT message(tr("%1 resumed").arg(title), false);
    if (j.state == spool::JobState::queued && reason_changed && !j.reason.empty())
        show_fault(tr("%1 waits: %2").arg(title, qs(j.reason)));
    if (j.state == spool::JobState::running && !w.steps)
        w.steps = std::make_unique<ProgressSteps>(std::max<std::size_t>(j.total_sheets(), 1));
    if (j.state == spool::JobState::running && total) {
        // The runner records every pass; the bar, the status and the screen
        // reader hear only the steps (one event per strike would flood Orca).
        const auto now = ProgressSteps::Clock::now();
        const auto step = w.steps->update(done, total, std::max<std::size_t>(s.sheet, 1));
        if (step && w.steps->speak(now))
            Q_EMIT message(step->by_sheet ? tr("%1: sheet %2 of %3").arg(title).arg(step->sheet).arg(step->sheets)
                                          : tr("%1: %2 percent, sheet %3 of %4")
                                                .arg(title).arg(step->percent / 10 * 10).arg(step->sheet).arg(step->sheets),
                           false);
        else if (const auto beat = w.steps->overdue(now))  // a slow job is heard every half minute
            Q_EMIT message(tr("%1: %2 percent, sheet %3 of %4").arg(title).arg(beat->percent).arg(beat->sheet).arg(beat->sheets),
                           false);
    }
}

void PrinterPanel::finished(const spool::JobRecord& j, const Shown& s) {
    const auto title = qs(j.title);
    watch_[j.id].steps.reset();
    if (j.state == spool::JobState::completed) {
        // Only this window's simulator has the strikes (serve's "sim" is its own).
        const auto printer = spool_->printer(j.printer_id);
        if (runner_ && sim_ && j.printer == printer_ && printer && is_sim(printer->device)) {
            check_strikes(j);
            return;
        }
        const auto text = tr("Embossed %1").arg(title);
        log(text);
        Q_EMIT message(text, false);
        Q_EMIT job_finished(j.id, true, text);
        return;
    }
    QString text;
    if (j.state == spool::JobState::cancelled) {
        text = s.sheet ? tr("%1 cancelled; resume from sheet %2").arg(title).arg(s.sheet) : tr("%1 cancelled").arg(title);
    } else {
        text = tr("%1 stopped: %2. The job is kept; fix the problem, then resume it.").arg(title, qs(j.reason));
        fault_->setText(text);  // announced once, below (show_fault would announce it a second time)
    }
    log(text);
    Q_EMIT message(text, j.state == spool::JobState::failed);
    Q_EMIT job_finished(j.id, false, text);
}

// On the built-in simulator the app compares what the simulated 89C52 struck
// with the plan, off the GUI thread (planning a book takes a while).
void PrinterPanel::check_strikes(const spool::JobRecord& j) {
    auto doc = spool_->document_snapshot(j.id);
    auto printer = spool_->printer(j.printer_id);
    if (!doc || !printer) return;
    auto* watcher = new QFutureWatcher<QString>(this);
    const auto title = qs(j.title);
    const auto id = j.id;
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, title, id] {
        const auto check = watcher->result();
        watcher->deleteLater();
        const auto text = joined(tr("Embossed %1").arg(title), check);
        log(text);
        Q_EMIT message(text, false);
        Q_EMIT job_finished(id, true, text);
    });
    watcher->setFuture(QtConcurrent::run(
        [document = *doc, profile = printer->profile_json, j, strikes = sim_->strikes(), fw = sim_->firmware()] {
            return strike_check_text(
                spool::check_strikes(j, document, profile, strikes, fw ? &*fw : nullptr));
        }));
}

void PrinterPanel::show_jobs() {
    const auto selected = selected_job();
    const auto* selected_queue = selected_queue_job();
    const auto set_text = [this](int row, int col, const QString& text) {
        auto* item = queue_->item(row, col);
        if (!item) queue_->setItem(row, col, new QTableWidgetItem(text));
        else if (item->text() != text) item->setText(text);  // an unchanged text sends no event
    };
    const int local_rows = static_cast<int>(jobs_.size());
    const int rows = local_rows + static_cast<int>(queue_jobs_.size());
    if (queue_->rowCount() != rows) queue_->setRowCount(rows);
    const auto bar_at = [this](int row, const QString& name, int pct) {
        auto* bar = static_cast<QProgressBar*>(queue_->cellWidget(row, col_progress));
        if (!bar) {
            bar = new QProgressBar(queue_);
            bar->setRange(0, 100);
            queue_->setCellWidget(row, col_progress, bar);
        }
        if (bar->accessibleName() != name) bar->setAccessibleName(name);
        if (bar->value() != pct) bar->setValue(pct);
    };
    for (int row = 0; row < local_rows; ++row) {
        const auto& j = jobs_[static_cast<std::size_t>(row)];
        const auto& s = shown_[j.id];
        set_text(row, col_job, QString::number(j.id));
        set_text(row, col_document, qs(j.title));
        set_text(row, col_printer, qs(j.printer));
        set_text(row, col_state, joined(state_text(j.state), qs(j.reason)));
        set_text(row, col_sheet, s.sheet ? QString::number(s.sheet) : QString());
        // The bar moves in tenths: its value is what a screen reader reads.
        bar_at(row, tr("Progress of %1").arg(qs(j.title)), s.percent == 100 ? 100 : s.percent / 10 * 10);
    }
    // Jobs on CUPS queues: the server's state, its printer's message, the
    // sheets it counted and how far the sheet in hand is (it knows no total).
    for (int row = local_rows; row < rows; ++row) {
        const auto& j = *queue_jobs_[static_cast<std::size_t>(row - local_rows)];
        const auto& st = j.status;
        set_text(row, col_job, j.id ? QStringLiteral("%1-%2").arg(j.name).arg(j.id) : tr("sending"));
        set_text(row, col_document, j.title);
        set_text(row, col_printer, j.queue);
        QString state = st ? remote_state_text(st->state) : (j.error.isEmpty() ? tr("sending") : tr("not sent"));
        if (j.cancelling && st && !st->ended()) state = tr("cancelling");
        const auto said = st ? (st->ended() ? st->why_ended() : st->message) : std::string();
        const auto why = !said.empty() ? qs(said) : j.error;
        set_text(row, col_state, joined(state, why));
        const bool processing = st && st->state == ipp::RemoteJobState::processing;
        set_text(row, col_sheet, processing ? QString::number(std::max(st->sheets_completed, 0) + 1) : QString());
        const int pct = st && st->state == ipp::RemoteJobState::completed ? 100
                        : processing && st->media_progress > 0   ? st->media_progress / 10 * 10
                                                                 : 0;
        bar_at(row, tr("Progress of the sheet in hand of %1").arg(j.title), pct);
    }
    shown_local_rows_ = local_rows;
    if (selected_queue) {
        for (std::size_t i = 0; i < queue_jobs_.size(); ++i)
            if (queue_jobs_[i].get() == selected_queue && queue_->currentRow() != local_rows + static_cast<int>(i))
                queue_->selectRow(local_rows + static_cast<int>(i));
    } else if (selected) {
        select_job(*selected);
    }
}

int PrinterPanel::selected_row() const {
    const int row = queue_->currentRow();
    return row >= 0 && row < queue_->rowCount() && queue_->selectionModel()->isRowSelected(row, {}) ? row : -1;
}

std::optional<spool::JobId> PrinterPanel::selected_job() const {
    const int row = selected_row();
    if (row >= 0 && row < shown_local_rows_ && row < static_cast<int>(jobs_.size()))
        return jobs_[static_cast<std::size_t>(row)].id;
    if (row >= shown_local_rows_) return std::nullopt;  // a job on a CUPS queue
    if (auto e = embossing()) return e->id;
    return std::nullopt;
}

void PrinterPanel::select_job(spool::JobId id) {
    for (std::size_t i = 0; i < jobs_.size(); ++i)
        if (jobs_[i].id == id) {
            if (queue_->currentRow() != static_cast<int>(i)) queue_->selectRow(static_cast<int>(i));
            return;
        }
}

std::optional<spool::JobRecord> PrinterPanel::embossing() const {
    if (!runner_) return std::nullopt;
    const auto token = runner_->runner->token();
    for (const auto& j : jobs_)
        if ((j.state == spool::JobState::running || j.state == spool::JobState::paused) && j.runner == token) return j;
    return std::nullopt;
}

void PrinterPanel::append_events() {
    auto events = spool_->events(std::nullopt, last_event_ ? 200 : 50);
    if (!events) return;
    const bool news = last_event_ != 0;  // the first read is history, not news
    // A fault and the job going on again often arrive in one read (the built-in
    // simulator reloads paper at once): said as one message, since a second
    // notification straight after the first cuts it off in Orca.
    std::map<std::int64_t, QString> faults;
    std::vector<std::int64_t> order;
    const auto title_of = [&](std::int64_t id) {
        const auto j = std::find_if(jobs_.begin(), jobs_.end(), [&](const auto& r) { return r.id == id; });
        return j != jobs_.end() ? qs(j->title) : tr("job %1").arg(id);
    };
    for (const auto& e : *events) {
        if (e.id <= last_event_) continue;
        last_event_ = e.id;
        log((e.job ? tr("job %1: ").arg(*e.job) : QString()) + joined(qs(e.kind), qs(e.message)));
        if (!e.job || !news) continue;
        if (e.kind == "fault") {
            if (!faults.count(*e.job)) order.push_back(*e.job);
            faults[*e.job] = tr("%1 paused: %2").arg(title_of(*e.job), qs(e.message));
        } else if (e.kind == "resumed") {
            if (const auto f = faults.find(*e.job); f != faults.end()) {
                announced_fault_.erase(*e.job);  // over already: a later paused state is news again
                Q_EMIT message(tr("%1 The printer is running again.").arg(f->second), false);
                faults.erase(f);
            } else {
                announce_going_on(*e.job);
            }
        }
    }
    for (const auto id : order)
        if (const auto f = faults.find(id); f != faults.end()) announce_fault(id, f->second);
}

void PrinterPanel::announce_fault(std::int64_t job, const QString& text) {
    auto& last = announced_fault_[job];
    if (last == text) return;
    last = text;
    show_fault(text);
}

void PrinterPanel::announce_going_on(std::int64_t job) {
    const auto it = announced_fault_.find(job);
    if (it == announced_fault_.end()) return;  // a resume the user asked for is announced by its button
    announced_fault_.erase(it);
    show_fault({});
    const auto j = std::find_if(jobs_.begin(), jobs_.end(), [&](const auto& r) { return r.id == job; });
    Q_EMIT message(tr("%1 goes on: the printer is running again").arg(j != jobs_.end() ? qs(j->title) : tr("job %1").arg(job)),
                   false);
}

void PrinterPanel::update_status() {
    QString text;
    if (printer_.empty()) {
        text = tr("Not connected");
    } else {
        QString who;
        if (runner_) {
            who = tr("run by this window");
        } else if (spool_) {
            auto p = spool_->printer(printer_);
            who = p && !p->runner.empty() ? tr("run by %1").arg(qs(p->runner))
                                          : tr("no runner: start tactus-cli serve or press Connect");
        }
        QString doing;
        for (const auto& j : jobs_)
            if (j.printer == printer_ && (j.state == spool::JobState::running || j.state == spool::JobState::paused)) {
                doing = tr("%1 %2").arg(state_text(j.state), qs(j.title));
                break;
            }
        text = joined(tr("Printer %1, %2").arg(qs(printer_), who), doing);
        if (!status_.isEmpty() && doing.isEmpty()) text += QStringLiteral(". ") + status_;
    }
    if (status_label_->text() != text) status_label_->setText(text);  // an unchanged text sends no event
}

void PrinterPanel::update_buttons() {
    connect_->setEnabled(connected() || !selected_is_queue());
    if (const auto* q = selected_queue_job()) {
        // The server runs it: it can be cancelled there, not paused from here.
        const bool cancellable = !q->ended && !q->cancelling;
        if (cancellable) cancel_->setEnabled(true);
        for (QWidget* w : {pause_, resume_, from_page_}) w->setEnabled(false);
        if (!cancellable) cancel_->setEnabled(false);
        faults_box_->setEnabled(selected_device() == QLatin1String(kSim));
        return;
    }
    std::optional<spool::JobRecord> job;
    if (const auto id = selected_job())
        for (const auto& j : jobs_)
            if (j.id == *id) job = j;
    // A request the runner has not carried out yet counts as done: Alt+P turns
    // the buttons at once, as the click is heard.
    std::optional<spool::JobState> state = job ? std::optional(job->state) : std::nullopt;
    if (job && job->control == spool::Control::pause) state = spool::JobState::paused;
    if (job && job->control == spool::Control::resume) state = spool::JobState::running;
    const bool cancelling = job && job->control == spool::Control::cancel;
    const std::pair<QWidget*, bool> wanted[] = {
        {pause_, !cancelling && (state == spool::JobState::running || state == spool::JobState::queued)},
        {resume_, !cancelling && (state == spool::JobState::paused || state == spool::JobState::failed ||
                                  state == spool::JobState::cancelled)},
        {cancel_, !cancelling && state && !spool::is_terminal(*state)},
        {from_page_, state && *state != spool::JobState::running},
        {faults_box_, is_sim(selected_device())},
    };
    // Enable first, then disable: a pressed button that turns off hands the
    // focus to the next one in the row (Pause -> Resume), not out of the panel.
    for (const auto& [w, on] : wanted)
        if (on) w->setEnabled(true);
    for (const auto& [w, on] : wanted)
        if (!on) w->setEnabled(false);
}

void PrinterPanel::act(int action, std::optional<std::size_t> sheet) {
    const auto id = selected_job();
    if (!id || !spool_) return;
    auto j = spool_->act(*id, static_cast<spool::Action>(action), sheet);
    if (!j) {
        Q_EMIT message(qs(j.error().message), true);
        return;
    }
    log(tr("Job %1: %2 sent to the queue").arg(*id).arg(qs(spool::to_string(static_cast<spool::Action>(action)))));
    refresh();
}

void PrinterPanel::pause_job() {
    Q_EMIT message(tr("Pausing"), false);
    act(static_cast<int>(spool::Action::pause));
}

void PrinterPanel::resume_job() {
    const auto id = selected_job();
    const auto it = std::find_if(jobs_.begin(), jobs_.end(), [&](const auto& j) { return id && j.id == *id; });
    if (it == jobs_.end()) return;
    // A stopped or cancelled job starts again where it stopped.
    const bool stopped = it->state == spool::JobState::failed || it->state == spool::JobState::cancelled;
    Q_EMIT message(tr("Resuming"), false);
    act(static_cast<int>(stopped ? spool::Action::retry : spool::Action::resume));
}

void PrinterPanel::cancel_job() {
    if (auto* q = selected_queue_job()) {
        if (q->ended || q->cancelling) return;
        // The job's thread sends Cancel-Job and follows the job to its end.
        q->cancelling = true;
        q->cancel = true;
        log(tr("%1: cancel sent to %2").arg(q->title, q->queue));
        Q_EMIT message(tr("Cancelling %1 on %2").arg(q->title, q->queue), false);
        show_jobs();
        update_buttons();
        return;
    }
    act(static_cast<int>(spool::Action::cancel));
}

void PrinterPanel::resume_from_page(int page) {
    const auto id = selected_job();
    if (!id || !spool_) return;
    const auto it = std::find_if(jobs_.begin(), jobs_.end(), [&](const auto& j) { return j.id == *id; });
    if (it == jobs_.end()) return;
    auto snapshot = spool_->document_snapshot(*id);
    auto doc = snapshot ? spool::from_snapshot(*snapshot) : std::unexpected(snapshot.error());
    auto sheet = doc ? spool::sheet_of_page(*doc, static_cast<std::size_t>(std::max(page, 0)))
                     : std::unexpected(doc.error());
    if (!sheet) {
        Q_EMIT message(tr("%1: %2").arg(qs(it->title), qs(sheet.error().message)), true);
        return;
    }
    const bool stopped = spool::is_terminal(it->state);
    Q_EMIT message(tr("%1 is embossed again from sheet %2").arg(qs(it->title)).arg(*sheet), false);
    act(static_cast<int>(stopped ? spool::Action::retry : spool::Action::resume), *sheet);
}

void PrinterPanel::inject_paper_out() {
    simulator().paper_out();
    log(tr("Simulator: the paper runs out"));
}
void PrinterPanel::inject_pulled_cable() {
    simulator().pull_cable(5);
    log(tr("Simulator: the cable is pulled for 5 seconds"));
}
void PrinterPanel::inject_noise() {
    simulator().noise(2, 0.01);
    log(tr("Simulator: line noise for 2 seconds"));
}
void PrinterPanel::inject_reset() {
    simulator().reset_controller();
    log(tr("Simulator: the controller resets"));
}

}  // namespace tactus::gui
