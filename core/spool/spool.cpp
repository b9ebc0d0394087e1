// SPDX-License-Identifier: GPL-3.0-or-later
// The spool's store: every statement on the jobs, printers and events tables.
// Over 700 lines because each operator action and runner step is one SQL
// transaction written next to the others it must agree with (the job state
// machine in job_state.cpp decides; this file records). Splitting it by
// action (submission, operator requests, runner progress) is a move still to do.
#include "spool/spool.hpp"

#include <sqlite3.h>

#include <chrono>
#include <ctime>
#include <random>
#include <system_error>

#include "platform/clock.hpp"
#include "spool/runner_token.hpp"
#include "spool/schema.hpp"
#include "common/try.hpp"
#include "transport/device.hpp"

namespace tactus::spool {
namespace {

constexpr const char* kJobColumns =
    "j.id, j.printer_id, p.name, j.title, j.sheets_per_copy, j.copies, j.first_page, "
    "j.last_page, j.priority, j.state, j.reason, j.control, j.resume_sheet, j.retries, "
    "j.not_before, j.runner, j.submitted_by, j.submitted_at, j.updated_at, j.started_at, "
    "j.finished_at, j.link_job, j.run_start_sheet, j.run_open, j.run_first_pass";

std::string job_query(std::string_view tail) {
    // Appended in place: GCC 12 at -O2 warns falsely (-Warray-bounds) on a
    // chain of operator+ that starts with a short string temporary.
    std::string query = "SELECT ";
    query += kJobColumns;
    query += " FROM jobs j JOIN printers p ON p.id = j.printer_id ";
    query += tail;
    return query;
}

std::size_t size_col(const sql::Statement& s, int c) {
    const auto v = s.int64(c);
    return v > 0 ? static_cast<std::size_t>(v) : 0;
}

Result<JobRecord> read_job(const sql::Statement& s) {
    JobRecord j;
    j.id = s.int64(0);
    j.printer_id = s.int64(1);
    j.printer = s.text(2);
    j.title = s.text(3);
    j.sheets_per_copy = size_col(s, 4);
    j.copies = size_col(s, 5);
    j.first_page = size_col(s, 6);
    j.last_page = size_col(s, 7);
    j.priority = static_cast<int>(s.int64(8));
    TACTUS_TRY(state, parse_job_state(s.text(9)));
    j.state = state;
    j.reason = s.text(10);
    TACTUS_TRY(control, parse_control(s.text(11)));
    j.control = control;
    if (!s.is_null(12)) j.resume_sheet = size_col(s, 12);
    j.retries = static_cast<int>(s.int64(13));
    j.not_before = s.real(14);
    j.runner = s.text(15);
    j.user = s.text(16);
    j.submitted_at = s.real(17);
    j.updated_at = s.real(18);
    if (!s.is_null(19)) j.started_at = s.real(19);
    if (!s.is_null(20)) j.finished_at = s.real(20);
    if (!s.is_null(21)) j.link_job = static_cast<std::uint16_t>(s.int64(21));
    j.run_start_sheet = size_col(s, 22);
    j.run_open = s.int64(23) != 0;
    j.run_first_pass = size_col(s, 24);
    return j;
}

PrinterRecord read_printer(const sql::Statement& s) {
    return PrinterRecord{s.int64(0), s.text(1), s.text(2), s.text(3), s.text(4)};
}

constexpr const char* kPrinterColumns = "SELECT id, name, device, profile_json, runner FROM printers ";

auto i64(std::size_t v) { return static_cast<std::int64_t>(v); }

std::string job_where(JobId id) { return "job " + std::to_string(id); }

// Whether the first read works (it fails with SQLITE_CANTOPEN on a WAL
// database whose folder is read-only and has no -shm file).
bool can_read_wal(sql::Database& db) {
    auto s = db.prepare("PRAGMA user_version");
    return s && s->step().has_value();
}

bool wal_is_empty(const std::filesystem::path& path) {
    std::error_code ec;
    const auto wal = std::filesystem::path(path.string() + "-wal");
    return !std::filesystem::exists(wal, ec) || std::filesystem::file_size(wal, ec) == 0;
}

}  // namespace

double now_seconds() {
    using namespace std::chrono;
    return duration<double>(system_clock::now().time_since_epoch()).count();
}

namespace {

// The tables, the version and the application id of a new spool, in one
// transaction, in WAL mode.
Result<void> write_schema(sql::Database& db) {
    TACTUS_TRY_VOID(db.exec("PRAGMA journal_mode=WAL"));
    auto tx = sql::Transaction::begin(db);
    if (!tx) return std::unexpected(tx.error());
    TACTUS_TRY_VOID(db.exec(kSchema));
    TACTUS_TRY_VOID(db.exec("PRAGMA user_version=" + std::to_string(kSchemaVersion) +
                      "; PRAGMA application_id=" + std::to_string(kApplicationId)));
    return tx->commit();
}

// A new spool is made whole beside its place, then linked into it, so no
// process ever opens a half-made one: cupsd starts a server's first job's
// filter and backend together and both create the spool; writing the schema
// in place, the loser met "table printers already exists" or a file it could
// not open, and its failure stopped the CUPS queue. The link fails if another
// creator came first, and then its spool is the one everybody opens.
Result<void> create_spool_file(const std::filesystem::path& path, int busy_timeout_ms) {
    std::random_device random;
    auto made = path;
    made += ".new-" + std::to_string(random()) + std::to_string(random());
    {
        auto opened = sql::Database::open(made, true, busy_timeout_ms);
        if (!opened) {
            auto e = opened.error();  // said of the spool, not of its draft
            e.where = path.string();
            return std::unexpected(e);
        }
        sql::Database db = std::move(*opened);
        TACTUS_TRY_VOID(write_schema(db));
    }  // closed: the log is folded into the file and removed with it
    std::error_code linked, ec;
    std::filesystem::create_hard_link(made, path, linked);
    if (linked && linked != std::errc::file_exists && !std::filesystem::exists(path, ec))
        // No hard links on this file system (FAT, some network shares): a
        // rename, which another creator could still overtake in a moment.
        std::filesystem::rename(made, path, linked);
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
        auto leftover = made;
        leftover += suffix;
        std::filesystem::remove(leftover, ec);
    }
    if (!std::filesystem::exists(path, ec))
        return fail(ErrorKind::io, "cannot create the spool database: " + linked.message(), path.string());
    return {};
}

}  // namespace

Result<Spool> Spool::open(const std::filesystem::path& path, OpenOptions options) {
    std::error_code ec;
    const bool exists = std::filesystem::exists(path, ec);
    auto not_there_yet = [&] {
        return fail(ErrorKind::input, "no spool database here yet: nothing has been queued on this machine. Queue a "
                    "document with `tactus-cli emboss --queue --device DEVICE FILE` (it sets up a printer "
                    "for DEVICE), or add one first with `tactus-cli queue printer add NAME --device DEVICE`",
                    path.string());
    };
    if (!exists) {
        if (!options.create) return not_there_yet();
        if (path.has_parent_path()) {
            std::filesystem::create_directories(path.parent_path(), ec);
            if (ec)
                return fail(ErrorKind::io, "cannot create the spool folder: " + ec.message(),
                            path.parent_path().string());
        }
        TACTUS_TRY_VOID(create_spool_file(path, options.busy_timeout_ms));
    }
    TACTUS_TRY(opened, sql::Database::open(path, options.create, options.busy_timeout_ms));
    sql::Database db = std::move(opened);
    bool read_only = sqlite3_db_readonly(db.handle(), "main") == 1;
    if (read_only && options.read_only_ok && !can_read_wal(db) && wal_is_empty(path)) {
        // A read-only spool in a read-only folder: SQLite cannot make the WAL's
        // shared-memory file, yet nobody can be writing it either.
        TACTUS_TRY(frozen, sql::Database::open_immutable(path));
        db = std::move(frozen);
    }
    if (read_only && !options.read_only_ok)
        return fail(ErrorKind::input, "the spool database is read-only (file or disk write-protected); "
                    "nothing can be queued or changed",
                    path.string());

    // The first read of the file: a damaged or foreign file fails here, before
    // anything is written to it. (Scoped: open statements hold a read
    // transaction, and the journal mode cannot change inside one.)
    std::int64_t user_version = 0, app_id = 0;
    bool empty = false;
    {
    TACTUS_TRY(version, db.prepare("PRAGMA user_version"));
    auto has_row = version.step();
    if (!has_row && has_row.error().kind == ErrorKind::io)
        // The disk failed the read (full, or an I/O error): the file is not
        // shown to be damaged, and `queue recover` would find nothing wrong.
        return fail(ErrorKind::io, "cannot read the spool database: " + has_row.error().message, path.string());
    if (!has_row)
        return fail(ErrorKind::input, "not a usable spool database: " + has_row.error().message +
                        "; it was left untouched (move it aside with `tactus-cli queue "
                        "recover`, or point --db elsewhere)",
                    path.string());
    user_version = version.int64(0);
    auto app = db.prepare("PRAGMA application_id");
    if (!app || !app->step()) return fail(ErrorKind::input, "cannot read the database header", path.string());
    app_id = app->int64(0);
    auto tables = db.prepare("SELECT count(*) FROM sqlite_schema");
    if (!tables || !tables->step())
        return fail(ErrorKind::input, "cannot read the database schema (damaged?)", path.string());
    empty = tables->int64(0) == 0;
    }

    if (empty && user_version == 0) {
        // An empty file is a spool another process is creating right now
        // (SQLite makes the file before the schema): one that may not create
        // leaves it to its creator. Writing the schema here raced the creator:
        // root polling the CUPS backend's new spool made it read-only for lp.
        if (!options.create) return not_there_yet();
        if (read_only) return fail(ErrorKind::input, "the spool database is empty and read-only", path.string());
        TACTUS_TRY_VOID(write_schema(db));
    } else if (app_id != kApplicationId) {
        return fail(ErrorKind::input, "this SQLite file is not a Tactus spool (application id " +
                        std::to_string(app_id) + "); it was left untouched",
                    path.string());
    } else if (user_version > kSchemaVersion) {
        return fail(ErrorKind::input, "the spool was written by a newer Tactus (schema " +
                        std::to_string(user_version) + ", this one knows " +
                        std::to_string(kSchemaVersion) + "); it was left untouched: use that "
                        "Tactus, or point --db elsewhere",
                    path.string());
    } else if (user_version < kSchemaVersion) {
        if (read_only)
            return fail(ErrorKind::input, "the spool is from an older Tactus and read-only, so it cannot be upgraded",
                        path.string());
        TACTUS_TRY(tx, sql::Transaction::begin(db));
        TACTUS_TRY_VOID(db.exec(kMigrate1To2));
        TACTUS_TRY_VOID(db.exec("PRAGMA user_version=" + std::to_string(kSchemaVersion)));
        TACTUS_TRY_VOID(tx.commit());
    }
    if (!read_only) {
        // WAL: readers never block the runner's progress writes. FULL: a
        // committed pass survives a power cut, not just a process crash (a lost
        // pass record would mean embossing a sheet twice).
        TACTUS_TRY_VOID(db.exec("PRAGMA journal_mode=WAL"));
        TACTUS_TRY_VOID(db.exec("PRAGMA synchronous=FULL"));
    }
    if (!read_only) TACTUS_TRY_VOID(db.exec(kJobOrigins));
    TACTUS_TRY_VOID(db.exec("PRAGMA foreign_keys=ON"));
    return Spool(std::move(db), read_only);
}

Result<void> Spool::check() {
    TACTUS_TRY(s, db_.prepare("PRAGMA quick_check"));
    TACTUS_TRY(row, s.step());
    if (!row || s.text(0) != "ok")
        return fail(ErrorKind::input, "integrity check failed: " + (row ? s.text(0) : std::string("no answer")),
                    db_.path().string());
    return {};
}

Result<void> Spool::insert_event(std::optional<JobId> job, std::optional<PrinterId> printer,
                                 std::string_view kind, std::string_view message) {
    TACTUS_TRY(s, db_.prepare(
                     "INSERT INTO events(job_id, printer_id, at, kind, message) VALUES(?,?,?,?,?)"));
    s.bind(1, job).bind(2, printer).bind(3, now_seconds()).bind(4, kind).bind(5, message);
    return s.run();
}

Result<void> Spool::log(std::optional<JobId> job, std::optional<PrinterId> printer,
                        std::string_view kind, std::string_view message) {
    return insert_event(job, printer, kind, message);
}

// --- printers

Result<PrinterRecord> Spool::add_printer(std::string_view name, std::string_view device,
                                         std::string_view profile_json) {
    if (name.empty()) return fail(ErrorKind::usage, "a printer needs a name", "--printer");
    if (device.empty()) return fail(ErrorKind::usage, "a printer needs a device string", "--device");
    if (auto d = transport::check_device(device); !d) return std::unexpected(located(d.error(), "--device"));
    {
        TACTUS_TRY(tx, sql::Transaction::begin(db_));
        TACTUS_TRY(s, db_.prepare(
                         "INSERT INTO printers(name, device, profile_json, created_at) VALUES(?,?,?,?)"));
        s.bind(1, name).bind(2, device).bind(3, profile_json).bind(4, now_seconds());
        if (auto r = s.run(); !r) {
            if (printer(name)) return fail(ErrorKind::usage, "printer '" + std::string(name) + "' already exists", "--printer");
            return std::unexpected(r.error());
        }
        const auto id = db_.last_insert_rowid();
        TACTUS_TRY_VOID(insert_event({}, id, "printer",
                               "printer '" + std::string(name) + "' added on " + std::string(device)));
        TACTUS_TRY_VOID(tx.commit());
    }
    return printer(name);
}

Result<PrinterRecord> Spool::update_printer(std::string_view name, std::optional<std::string> device,
                                            std::optional<std::string> profile_json) {
    if (device)
        if (auto d = transport::check_device(*device); !d) return std::unexpected(located(d.error(), "--device"));
    TACTUS_TRY(p, printer(name));
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare("UPDATE printers SET device = ?, profile_json = ? WHERE id = ?"));
    s.bind(1, device.value_or(p.device)).bind(2, profile_json.value_or(p.profile_json)).bind(3, p.id);
    TACTUS_TRY_VOID(s.run());
    std::string what = "printer '" + p.name + "' changed:";
    if (device) what += " device " + *device;
    if (profile_json) what += " new profile";
    TACTUS_TRY_VOID(insert_event({}, p.id, "printer", what));
    TACTUS_TRY_VOID(tx.commit());
    return printer(p.id);
}

Result<PrinterRecord> Spool::printer(std::string_view name) {
    TACTUS_TRY(s, db_.prepare(std::string(kPrinterColumns) + "WHERE name = ?"));
    s.bind(1, name);
    TACTUS_TRY(row, s.step());
    if (!row) {
        std::string known;
        if (auto all = printers(); all)
            for (const auto& p : *all) known += (known.empty() ? "" : ", ") + p.name;
        return fail(ErrorKind::input, "unknown printer '" + std::string(name) + "' (" +
                        (known.empty() ? "no printers are set up; add one with "
                                         "`tactus-cli queue printer add`"
                                       : "known: " + known) +
                        ")",
                    "--printer");
    }
    return read_printer(s);
}

Result<PrinterRecord> Spool::printer(PrinterId id) {
    TACTUS_TRY(s, db_.prepare(std::string(kPrinterColumns) + "WHERE id = ?"));
    s.bind(1, id);
    TACTUS_TRY(row, s.step());
    if (!row) return fail(ErrorKind::input, "no printer with id " + std::to_string(id));
    return read_printer(s);
}

Result<std::vector<PrinterRecord>> Spool::printers() {
    TACTUS_TRY(s, db_.prepare(std::string(kPrinterColumns) + "ORDER BY name"));
    std::vector<PrinterRecord> out;
    for (;;) {
        TACTUS_TRY(row, s.step());
        if (!row) break;
        out.push_back(read_printer(s));
    }
    return out;
}

// --- jobs

Result<JobId> Spool::submit(const JobSubmission& job) {
    if (job.sheets_per_copy == 0) return fail(ErrorKind::input, "the document has no pages to emboss");
    if (job.copies == 0 || job.copies > 10000) return fail(ErrorKind::usage, "copies must be 1 to 10000", "--copies");
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    if (!job.origin.empty()) {
        // Inside the transaction: two submitters of one origin cannot both miss it.
        TACTUS_TRY(known, db_.prepare("SELECT job_id FROM job_origins WHERE origin = ?"));
        known.bind(1, job.origin);
        TACTUS_TRY(row, known.step());
        if (row) return known.int64(0);
    }
    TACTUS_TRY(p, printer(job.printer));
    TACTUS_TRY(s, db_.prepare(
                     "INSERT INTO jobs(printer_id, title, document, profile_json, sheets_per_copy, "
                     "copies, first_page, last_page, priority, state, submitted_by, submitted_at, "
                     "updated_at) VALUES(?,?,?,?,?,?,?,?,?,'queued',?,?,?)"));
    const double now = now_seconds();
    s.bind(1, p.id).bind(2, job.title).bind(3, job.document).bind(4, p.profile_json)
        .bind(5, i64(job.sheets_per_copy)).bind(6, i64(job.copies)).bind(7, i64(job.first_page))
        .bind(8, i64(job.last_page)).bind(9, std::int64_t{job.priority}).bind(10, job.user)
        .bind(11, now).bind(12, now);
    TACTUS_TRY_VOID(s.run());
    const JobId id = db_.last_insert_rowid();
    if (!job.origin.empty()) {
        TACTUS_TRY(o, db_.prepare("INSERT INTO job_origins(origin, job_id) VALUES(?,?)"));
        o.bind(1, job.origin).bind(2, id);
        TACTUS_TRY_VOID(o.run());
    }
    TACTUS_TRY_VOID(insert_event(id, p.id, "submitted",
                           "'" + job.title + "' by " + job.user + ": " +
                               std::to_string(job.sheets_per_copy) + " sheet(s) x " +
                               std::to_string(job.copies) + " cop" + (job.copies == 1 ? "y" : "ies") +
                               " on " + p.name));
    TACTUS_TRY_VOID(tx.commit());
    return id;
}

Result<JobRecord> Spool::job_locked(JobId id) {
    TACTUS_TRY(s, db_.prepare(job_query("WHERE j.id = ?")));
    s.bind(1, id);
    TACTUS_TRY(row, s.step());
    if (!row) return fail(ErrorKind::input, "no such job", job_where(id));
    return read_job(s);
}

Result<JobRecord> Spool::job(JobId id) { return job_locked(id); }

Result<std::optional<JobRecord>> Spool::job_by_origin(std::string_view origin) {
    TACTUS_TRY(s, db_.prepare("SELECT job_id FROM job_origins WHERE origin = ?"));
    s.bind(1, origin);
    TACTUS_TRY(row, s.step());
    if (!row) return std::optional<JobRecord>{};
    const JobId id = s.int64(0);
    TACTUS_TRY(j, job_locked(id));
    return std::optional<JobRecord>(std::move(j));
}

Result<std::string> Spool::document_snapshot(JobId id) {
    TACTUS_TRY(s, db_.prepare("SELECT document FROM jobs WHERE id = ?"));
    s.bind(1, id);
    TACTUS_TRY(row, s.step());
    if (!row) return fail(ErrorKind::input, "no such job", job_where(id));
    return s.text(0);
}

Result<std::string> Spool::profile_snapshot(JobId id) {
    TACTUS_TRY(s, db_.prepare("SELECT profile_json FROM jobs WHERE id = ?"));
    s.bind(1, id);
    TACTUS_TRY(row, s.step());
    if (!row) return fail(ErrorKind::input, "no such job", job_where(id));
    return s.text(0);
}

Result<std::vector<JobRecord>> Spool::jobs(bool finished, std::optional<std::string> printer_name) {
    std::string where = printer_name ? "AND p.name = ?1 " : "";
    std::string sql =
        job_query("WHERE j.state IN ('queued','running','paused') " + where +
                  "ORDER BY (j.state = 'running') DESC, j.priority DESC, j.id");
    std::vector<JobRecord> out;
    auto collect = [&](const std::string& q) -> Result<void> {
        TACTUS_TRY(s, db_.prepare(q));
        if (printer_name) s.bind(1, *printer_name);
        for (;;) {
            TACTUS_TRY(row, s.step());
            if (!row) return {};
            TACTUS_TRY(j, read_job(s));
            out.push_back(std::move(j));
        }
    };
    TACTUS_TRY_VOID(collect(sql));
    if (finished)
        TACTUS_TRY_VOID(collect(job_query("WHERE j.state IN ('completed','cancelled','failed') " + where +
                                    "ORDER BY j.id DESC")));
    return out;
}

Result<std::vector<SheetProgress>> Spool::progress(JobId id) {
    TACTUS_TRY(s, db_.prepare("SELECT sheet, passes_total, passes_done, spoiled FROM progress "
                             "WHERE job_id = ? ORDER BY sheet"));
    s.bind(1, id);
    std::vector<SheetProgress> out;
    for (;;) {
        TACTUS_TRY(row, s.step());
        if (!row) break;
        out.push_back(SheetProgress{size_col(s, 0), size_col(s, 1), size_col(s, 2), size_col(s, 3)});
    }
    return out;
}

Result<std::vector<EventRecord>> Spool::events(std::optional<JobId> job, std::size_t limit) {
    TACTUS_TRY(s, db_.prepare(
                     "SELECT * FROM (SELECT id, job_id, at, kind, message FROM events "
                     "WHERE ?1 IS NULL OR job_id = ?1 ORDER BY id DESC LIMIT ?2) ORDER BY id"));
    s.bind(1, job).bind(2, i64(limit));
    std::vector<EventRecord> out;
    for (;;) {
        TACTUS_TRY(row, s.step());
        if (!row) break;
        EventRecord e;
        e.id = s.int64(0);
        if (!s.is_null(1)) e.job = s.int64(1);
        e.at = s.real(2);
        e.kind = s.text(3);
        e.message = s.text(4);
        out.push_back(std::move(e));
    }
    return out;
}

Result<JobRecord> Spool::act(JobId id, Action action, std::optional<std::size_t> resume_sheet) {
    {
        TACTUS_TRY(tx, sql::Transaction::begin(db_));
        TACTUS_TRY(j, job_locked(id));
        const bool held = !j.runner.empty();
        // The opposite request while one is still waiting for the runner
        // withdraws it (Pause then Resume at once, before the runner looked):
        // refusing the second left the job paused against the operator's word.
        const bool withdraws = held && !resume_sheet &&
                               ((action == Action::resume && j.control == Control::pause) ||
                                (action == Action::pause && j.control == Control::resume));
        if (withdraws) {
            TACTUS_TRY(w, db_.prepare("UPDATE jobs SET control = ?, updated_at = ? WHERE id = ?"));
            w.bind(1, to_string(Control::none)).bind(2, now_seconds()).bind(3, id);
            TACTUS_TRY_VOID(w.run());
            TACTUS_TRY_VOID(insert_event(id, j.printer_id, to_string(action),
                                   std::string(to_string(action)) + " requested by the operator: the " +
                                       to_string(j.control) + " had not reached the runner and is withdrawn"));
            TACTUS_TRY_VOID(tx.commit());
            return job(id);
        }
        auto t = apply(j.state, held, action);
        if (!t) return std::unexpected(located(t.error(), job_where(id)));
        if (resume_sheet) {
            if (action != Action::resume && action != Action::retry)
                return fail(ErrorKind::usage, "a start sheet only goes with resume or retry", "--from-sheet");
            if (*resume_sheet < 1 || *resume_sheet > j.total_sheets())
                return fail(ErrorKind::input, "sheet " + std::to_string(*resume_sheet) + " is outside the job's " +
                                std::to_string(j.total_sheets()) + " sheets",
                            "--from-sheet");
            if (t->control == Control::resume)
                return fail(ErrorKind::input, "the job is paused on its printer and continues where it stopped; "
                            "cancel-free restart from another sheet needs the runner to let go "
                            "first (pause, then stop serve, or retry after it fails)",
                            "--from-sheet");
        }
        TACTUS_TRY(s, db_.prepare(
                         "UPDATE jobs SET state = ?, control = ?, reason = ?, updated_at = ?, "
                         "resume_sheet = coalesce(?, resume_sheet), retries = "
                         "CASE WHEN ? THEN 0 ELSE retries END, not_before = "
                         "CASE WHEN ? THEN 0 ELSE not_before END, finished_at = "
                         "CASE WHEN ? THEN ? ELSE finished_at END WHERE id = ?"));
        const bool requeued = t->state == JobState::queued;
        const bool finishes = is_terminal(t->state) && !is_terminal(j.state);
        const double now = now_seconds();
        std::optional<std::int64_t> sheet;
        if (resume_sheet) sheet = i64(*resume_sheet);
        s.bind(1, to_string(t->state)).bind(2, to_string(t->control))
            .bind(3, t->control == Control::none ? std::string_view(t->reason) : std::string_view(j.reason))
            .bind(4, now).bind(5, sheet).bind(6, std::int64_t{requeued}).bind(7, std::int64_t{requeued})
            .bind(8, std::int64_t{finishes}).bind(9, now).bind(10, id);
        if (requeued) s.bind(3, std::string_view{});
        TACTUS_TRY_VOID(s.run());
        std::string message = std::string(to_string(action)) + " requested by the operator";
        if (t->control != Control::none) message += " (passed to the runner)";
        if (resume_sheet) message += "; restart at sheet " + std::to_string(*resume_sheet);
        TACTUS_TRY_VOID(insert_event(id, j.printer_id, to_string(action), message));
        TACTUS_TRY_VOID(tx.commit());
    }
    return job(id);
}

// --- runners

Result<void> Spool::claim_printer(PrinterId printer_id, std::string_view token) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(p, printer(printer_id));
    if (!p.runner.empty() && p.runner != token && runner_alive(p.runner))
        return fail(ErrorKind::device, "printer '" + p.name + "' is already served by " + p.runner, p.name);
    if (!p.runner.empty() && p.runner != token)
        TACTUS_TRY_VOID(insert_event({}, p.id, "recovered",
                               "runner " + p.runner + " is gone; " + std::string(token) + " takes over"));
    TACTUS_TRY(set, db_.prepare("UPDATE printers SET runner = ? WHERE id = ?"));
    set.bind(1, token).bind(2, p.id);
    TACTUS_TRY_VOID(set.run());
    // Jobs the dead runner held: running ones were interrupted mid-stream and
    // go back to the queue; their write-ahead record stays so the next run
    // reconciles with the controller before sending anything.
    TACTUS_TRY(held, db_.prepare(job_query("WHERE j.printer_id = ? AND j.runner != '' AND j.runner != ?")));
    held.bind(1, p.id).bind(2, token);
    std::vector<JobRecord> orphans;
    for (;;) {
        TACTUS_TRY(row, held.step());
        if (!row) break;
        TACTUS_TRY(j, read_job(held));
        orphans.push_back(std::move(j));
    }
    for (const auto& j : orphans) {
        TACTUS_TRY(u, db_.prepare(
                         "UPDATE jobs SET runner = '', control = '', updated_at = ?, "
                         "state = CASE WHEN state = 'running' THEN 'queued' ELSE state END, "
                         "reason = CASE WHEN state = 'running' THEN 'interrupted: resumes at the first "
                         "unfinished sheet' ELSE reason END WHERE id = ?"));
        u.bind(1, now_seconds()).bind(2, j.id);
        TACTUS_TRY_VOID(u.run());
        TACTUS_TRY_VOID(insert_event(j.id, p.id, "interrupted",
                               "the runner holding it (" + j.runner + ") stopped while the job was " +
                                   to_string(j.state)));
    }
    return tx.commit();
}

Result<void> Spool::release_printer(PrinterId printer_id, std::string_view token) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare("UPDATE printers SET runner = '' WHERE id = ? AND runner = ?"));
    s.bind(1, printer_id).bind(2, token);
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY(u, db_.prepare("UPDATE jobs SET runner = '', updated_at = ?, "
                             "state = CASE WHEN state = 'running' THEN 'queued' ELSE state END "
                             "WHERE printer_id = ? AND runner = ?"));
    u.bind(1, now_seconds()).bind(2, printer_id).bind(3, token);
    TACTUS_TRY_VOID(u.run());
    return tx.commit();
}

Result<std::optional<JobRecord>> Spool::claim_next(PrinterId printer_id, std::string_view token,
                                                   double now) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare(job_query("WHERE j.printer_id = ? AND j.state = 'queued' AND "
                                       "j.not_before <= ? ORDER BY j.priority DESC, j.id LIMIT 1")));
    s.bind(1, printer_id).bind(2, now);
    TACTUS_TRY(row, s.step());
    if (!row) return std::optional<JobRecord>{};
    TACTUS_TRY(j, read_job(s));
    TACTUS_TRY(u, db_.prepare("UPDATE jobs SET state = 'running', runner = ?, reason = '', "
                             "control = '', updated_at = ?, started_at = coalesce(started_at, ?) "
                             "WHERE id = ?"));
    u.bind(1, token).bind(2, now).bind(3, now).bind(4, j.id);
    TACTUS_TRY_VOID(u.run());
    TACTUS_TRY_VOID(insert_event(j.id, printer_id, "started", "taken by runner " + std::string(token)));
    TACTUS_TRY_VOID(tx.commit());
    return job(j.id);
}

Result<void> Spool::set_sheet_passes(JobId id, const std::vector<std::size_t>& passes) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare("INSERT INTO progress(job_id, sheet, passes_total) VALUES(?,?,?) "
                             "ON CONFLICT(job_id, sheet) DO UPDATE SET passes_total = "
                             "excluded.passes_total WHERE passes_done <= excluded.passes_total"));
    for (std::size_t i = 0; i < passes.size(); ++i) {
        s.reset();
        s.bind(1, id).bind(2, i64(i + 1)).bind(3, i64(passes[i]));
        TACTUS_TRY_VOID(s.run());
    }
    return tx.commit();
}

Result<void> Spool::record_passes(JobId id, std::size_t sheet, std::size_t passes_done) {
    // One autocommit statement: the cheapest durable write, done once per
    // executed pass. max() keeps a late or repeated report from lowering it.
    TACTUS_TRY(s, db_.prepare("UPDATE progress SET passes_done = max(passes_done, ?) "
                             "WHERE job_id = ? AND sheet = ? AND ? <= passes_total"));
    s.bind(1, i64(passes_done)).bind(2, id).bind(3, i64(sheet)).bind(4, i64(passes_done));
    TACTUS_TRY_VOID(s.run());
    if (db_.changes() != 1)
        return fail(ErrorKind::internal, "progress for sheet " + std::to_string(sheet) + " pass " +
                        std::to_string(passes_done) + " does not fit the job's plan",
                    job_where(id));
    return {};
}

Result<void> Spool::spoil_sheet(JobId id, std::size_t sheet, std::string_view message) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare("UPDATE progress SET passes_done = 0, spoiled = spoiled + 1 "
                             "WHERE job_id = ? AND sheet = ?"));
    s.bind(1, id).bind(2, i64(sheet));
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY_VOID(insert_event(id, {}, "spoiled", message));
    return tx.commit();
}

Result<void> Spool::restart_sheet(JobId id, std::size_t sheet, std::string_view message) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(s, db_.prepare("UPDATE progress SET passes_done = 0 WHERE job_id = ? AND sheet = ?"));
    s.bind(1, id).bind(2, i64(sheet));
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY_VOID(insert_event(id, {}, "reprint", message));
    return tx.commit();
}

Result<std::uint16_t> Spool::begin_run(JobId id, std::size_t start_sheet, std::size_t first_pass,
                                       std::uint16_t avoid) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(j, job_locked(id));
    TACTUS_TRY(q, db_.prepare("SELECT next_link_job FROM printers WHERE id = ?"));
    q.bind(1, j.printer_id);
    TACTUS_TRY(row, q.step());
    if (!row) return fail(ErrorKind::internal, "no printer for the job", job_where(id));
    // 0x8001..0xFFFF in turn, skipping the controller's current id.
    auto next = [](std::int64_t v) -> std::uint16_t {
        return v < kFirstLinkJob || v > 0xFFFF ? kFirstLinkJob : static_cast<std::uint16_t>(v);
    };
    std::uint16_t link_job = next(q.int64(0));
    if (link_job == avoid) link_job = next(std::int64_t{link_job} + 1);
    TACTUS_TRY(p, db_.prepare("UPDATE printers SET next_link_job = ? WHERE id = ?"));
    p.bind(1, std::int64_t{link_job} + 1).bind(2, j.printer_id);
    TACTUS_TRY_VOID(p.run());
    TACTUS_TRY(s, db_.prepare("UPDATE jobs SET link_job = ?, run_start_sheet = ?, run_first_pass = ?, "
                             "run_open = 1, updated_at = ? WHERE id = ?"));
    s.bind(1, std::int64_t{link_job}).bind(2, i64(start_sheet)).bind(3, i64(first_pass)).bind(4, now_seconds())
        .bind(5, id);
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY_VOID(tx.commit());
    return link_job;
}

Result<std::vector<JobRecord>> Spool::open_runs(PrinterId printer_id) {
    TACTUS_TRY(s, db_.prepare(job_query("WHERE j.printer_id = ? AND j.run_open = 1 ORDER BY j.id")));
    s.bind(1, printer_id);
    std::vector<JobRecord> out;
    for (;;) {
        TACTUS_TRY(row, s.step());
        if (!row) break;
        TACTUS_TRY(j, read_job(s));
        out.push_back(std::move(j));
    }
    return out;
}

Result<void> Spool::settle_run(JobId id, const RunSettlement& settlement) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(j, job_locked(id));
    for (const auto& [sheet, done] : settlement.record) {
        TACTUS_TRY(s, db_.prepare("UPDATE progress SET passes_done = max(passes_done, ?) "
                                 "WHERE job_id = ? AND sheet = ? AND ? <= passes_total"));
        s.bind(1, i64(done)).bind(2, id).bind(3, i64(sheet)).bind(4, i64(done));
        TACTUS_TRY_VOID(s.run());
    }
    if (settlement.discard) {
        TACTUS_TRY(s, db_.prepare("UPDATE progress SET passes_done = 0, spoiled = spoiled + 1 "
                                 "WHERE job_id = ? AND sheet = ?"));
        s.bind(1, id).bind(2, i64(*settlement.discard));
        TACTUS_TRY_VOID(s.run());
    }
    TACTUS_TRY_VOID(insert_event(id, j.printer_id, "reconciled", settlement.message));
    if (settlement.discard) TACTUS_TRY_VOID(insert_event(id, j.printer_id, "spoiled", settlement.discard_message));
    TACTUS_TRY(c, db_.prepare("UPDATE jobs SET run_open = 0, updated_at = ? WHERE id = ?"));
    c.bind(1, now_seconds()).bind(2, id);
    TACTUS_TRY_VOID(c.run());
    return tx.commit();
}

Result<void> Spool::end_run(JobId id) {
    TACTUS_TRY(s, db_.prepare("UPDATE jobs SET run_open = 0, updated_at = ? WHERE id = ?"));
    s.bind(1, now_seconds()).bind(2, id);
    return s.run();
}

Result<void> Spool::set_state(JobId id, JobState state, std::string_view reason,
                              std::string_view kind, std::string_view message, bool held) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(j, job_locked(id));
    const double now = now_seconds();
    const bool release = !held || is_terminal(state) || state == JobState::queued;
    TACTUS_TRY(s, db_.prepare(
                     "UPDATE jobs SET state = ?, reason = ?, updated_at = ?, "
                     "runner = CASE WHEN ? THEN '' ELSE runner END, "
                     "control = CASE WHEN ? THEN '' ELSE control END, "
                     "finished_at = CASE WHEN ? THEN ? ELSE finished_at END WHERE id = ?"));
    s.bind(1, to_string(state)).bind(2, reason).bind(3, now).bind(4, std::int64_t{release})
        .bind(5, std::int64_t{release}).bind(6, std::int64_t{is_terminal(state)}).bind(7, now)
        .bind(8, id);
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY_VOID(insert_event(id, j.printer_id, kind, message));
    return tx.commit();
}

Result<void> Spool::requeue(JobId id, std::string_view reason, double not_before, bool count_retry) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(j, job_locked(id));
    TACTUS_TRY(s, db_.prepare("UPDATE jobs SET state = 'queued', runner = '', control = '', "
                             "reason = ?, not_before = ?, retries = retries + ?, updated_at = ? "
                             "WHERE id = ?"));
    s.bind(1, reason).bind(2, not_before).bind(3, std::int64_t{count_retry}).bind(4, now_seconds())
        .bind(5, id);
    TACTUS_TRY_VOID(s.run());
    TACTUS_TRY_VOID(insert_event(id, j.printer_id, "requeued", reason));
    return tx.commit();
}

Result<Control> Spool::take_control(JobId id) {
    TACTUS_TRY(tx, sql::Transaction::begin(db_));
    TACTUS_TRY(q, db_.prepare("SELECT control FROM jobs WHERE id = ?"));
    q.bind(1, id);
    TACTUS_TRY(row, q.step());
    if (!row) return fail(ErrorKind::input, "no such job", job_where(id));
    TACTUS_TRY(control, parse_control(q.text(0)));
    if (control != Control::none) {
        TACTUS_TRY(clear, db_.prepare("UPDATE jobs SET control = '' WHERE id = ?"));
        clear.bind(1, id);
        TACTUS_TRY_VOID(clear.run());
    }
    TACTUS_TRY_VOID(tx.commit());
    return control;
}

Result<void> Spool::clear_resume_sheet(JobId id) {
    TACTUS_TRY(s, db_.prepare("UPDATE jobs SET resume_sheet = NULL WHERE id = ?"));
    s.bind(1, id);
    return s.run();
}

Result<std::int64_t> Spool::data_version() {
    TACTUS_TRY(s, db_.prepare("PRAGMA data_version"));
    TACTUS_TRY(row, s.step());
    if (!row) return fail(ErrorKind::internal, "no data_version", db_.path().string());
    return s.int64(0);
}

Diagnosis diagnose(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return {SpoolHealth::missing, Error{"no spool database here", path.string(), ErrorKind::input}};
    // An empty file is a spool its creator has not written yet (Spool::open
    // leaves it alone unless it may create): not there yet, never foreign.
    if (std::filesystem::file_size(path, ec) == 0 && !ec)
        return {SpoolHealth::missing, Error{"the spool database is empty: nothing has been queued yet", path.string(), ErrorKind::input}};
    auto s = Spool::open(path, {.create = false, .read_only_ok = true, .busy_timeout_ms = 2000});
    if (s) {
        if (auto c = s->check(); !c) return {SpoolHealth::damaged, c.error()};
        if (s->read_only())
            return {SpoolHealth::read_only,
                    Error{"the spool is healthy but read-only (file, folder or disk write-protected)", path.string(),
                          ErrorKind::input}};
        return {SpoolHealth::healthy, Error{"the spool database is fine", path.string(), ErrorKind::input}};
    }
    // Why it would not open: read the header without writing anything.
    sqlite3* db = nullptr;
    const std::string uri = "file:" + path.string() + "?mode=ro";
    int rc = sqlite3_open_v2(uri.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
    std::int64_t app_id = 0, version = 0;
    auto read = [&](const char* sql, std::int64_t& out) {
        sqlite3_stmt* st = nullptr;
        rc = sqlite3_prepare_v2(db, sql, -1, &st, nullptr);
        if (rc == SQLITE_OK) rc = sqlite3_step(st);
        if (rc == SQLITE_ROW) {
            out = sqlite3_column_int64(st, 0);
            rc = SQLITE_OK;
        }
        sqlite3_finalize(st);
        return rc == SQLITE_OK;
    };
    sqlite3_busy_timeout(db, 2000);
    const bool header = rc == SQLITE_OK && read("PRAGMA application_id", app_id) && read("PRAGMA user_version", version);
    const int code = rc & 0xFF;
    sqlite3_close_v2(db);
    if (!header && (code == SQLITE_BUSY || code == SQLITE_LOCKED)) return {SpoolHealth::in_use, s.error()};
    if (!header && code != SQLITE_NOTADB && code != SQLITE_CORRUPT) {
        // Not readable for another reason (permissions, a read-only folder):
        // nothing says the file itself is damaged.
        return {SpoolHealth::in_use, s.error()};
    }
    if (!header) return {SpoolHealth::damaged, s.error()};
    if (app_id != kApplicationId) return {SpoolHealth::foreign, s.error()};
    if (version > kSchemaVersion) return {SpoolHealth::newer, s.error()};
    return {SpoolHealth::in_use, s.error()};
}

Result<std::filesystem::path> set_aside(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return fail(ErrorKind::input, "no file to set aside", path.string());
    const std::time_t t = std::time(nullptr);
    const std::tm tm = platform::utc_time(t);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
    const std::filesystem::path aside = path.string() + ".broken-" + stamp;
    for (const char* suffix : {"", "-wal", "-shm"}) {
        const std::filesystem::path from = path.string() + suffix;
        if (!std::filesystem::exists(from, ec)) continue;
        std::filesystem::rename(from, aside.string() + suffix, ec);
        if (ec) return fail(ErrorKind::io, "cannot move the damaged database aside: " + ec.message(), from.string());
    }
    return aside;
}

}  // namespace tactus::spool
