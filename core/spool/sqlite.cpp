// SPDX-License-Identifier: GPL-3.0-or-later
#include "spool/sqlite.hpp"
#include "common/try.hpp"

#include <sqlite3.h>

#include <utility>

namespace tactus::spool::sql {
namespace {

// SQLite's messages are terse ("database is locked"); say what it means for a
// print queue and what to do about it.
std::string explain(int code, const char* message) {
    std::string why = message ? message : "unknown SQLite error";
    switch (code & 0xFF) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
        return why + " (another process holds the spool database; is a second "
                     "`tactus-cli serve` stuck?)";
    case SQLITE_READONLY:
        return why + " (the spool database or its folder is read-only)";
    case SQLITE_FULL:
        return why + " (the disk holding the spool database is full; nothing was changed)";
    case SQLITE_NOTADB:
    case SQLITE_CORRUPT:
        return why + " (the spool database is damaged)";
    case SQLITE_CANTOPEN:
        return why + " (the file or its folder cannot be opened)";
    case SQLITE_IOERR:
        return why + " (the disk reported an I/O error)";
    default: return why;
    }
}

// What kind of failure an SQLite code is, for the exit code: a disk that is
// full or failing is an I/O failure (exit 1, the job waits for room), not a
// damaged or unusable database (bad input, exit 3).
ErrorKind kind_of(int code) {
    switch (code & 0xFF) {
    case SQLITE_FULL:
    case SQLITE_IOERR: return ErrorKind::io;
    default: return ErrorKind::input;
    }
}

}  // namespace

Result<Database> Database::open(const std::filesystem::path& path, bool create,
                                int busy_timeout_ms) {
    sqlite3* db = nullptr;
    const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) |
                      SQLITE_OPEN_NOMUTEX | SQLITE_OPEN_EXRESCODE;
    // SQLite takes the name in UTF-8 on every system (a Windows path is UTF-16).
    const auto name = path.u8string();
    const int rc = sqlite3_open_v2(reinterpret_cast<const char*>(name.c_str()), &db, flags, nullptr);
    if (rc != SQLITE_OK) {
        std::string why = explain(rc, db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
        sqlite3_close_v2(db);
        return fail(kind_of(rc), "cannot open the spool database: " + why, path.string());
    }
    sqlite3_busy_timeout(db, busy_timeout_ms);
    sqlite3_extended_result_codes(db, 1);
    return Database(db, path);
}

Result<Database> Database::open_immutable(const std::filesystem::path& path) {
    sqlite3* db = nullptr;
    const std::string uri = "file:" + path.string() + "?immutable=1";
    const int flags = SQLITE_OPEN_READONLY | SQLITE_OPEN_URI | SQLITE_OPEN_NOMUTEX | SQLITE_OPEN_EXRESCODE;
    const int rc = sqlite3_open_v2(uri.c_str(), &db, flags, nullptr);
    if (rc != SQLITE_OK) {
        std::string why = explain(rc, db ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
        sqlite3_close_v2(db);
        return fail(kind_of(rc), "cannot open the spool database: " + why, path.string());
    }
    sqlite3_extended_result_codes(db, 1);
    return Database(db, path);
}

Database::Database(Database&& o) noexcept
    : db_(std::exchange(o.db_, nullptr)), path_(std::move(o.path_)) {}

Database& Database::operator=(Database&& o) noexcept {
    if (this != &o) {
        sqlite3_close_v2(db_);
        db_ = std::exchange(o.db_, nullptr);
        path_ = std::move(o.path_);
    }
    return *this;
}

Database::~Database() { sqlite3_close_v2(db_); }

Error Database::error(std::string_view doing) const {
    const int code = sqlite3_extended_errcode(db_);
    return Error{std::string(doing) + ": " + explain(code, sqlite3_errmsg(db_)), path_.string(), kind_of(code)};
}

Result<void> Database::exec(std::string_view sql) {
    const std::string text(sql);
    char* message = nullptr;
    const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &message);
    if (rc != SQLITE_OK) {
        std::string why = explain(rc, message ? message : sqlite3_errmsg(db_));
        sqlite3_free(message);
        return fail(kind_of(rc), why, path_.string());
    }
    return {};
}

Result<Statement> Database::prepare(std::string_view sql) {
    sqlite3_stmt* stmt = nullptr;
    const int rc = sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt,
                                      nullptr);
    if (rc != SQLITE_OK) return std::unexpected(error("preparing a query"));
    return Statement(stmt, this);
}

std::int64_t Database::last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }
int Database::changes() const { return sqlite3_changes(db_); }

Statement::Statement(Statement&& o) noexcept
    : stmt_(std::exchange(o.stmt_, nullptr)), db_(o.db_), bind_failed_(o.bind_failed_) {}

Statement& Statement::operator=(Statement&& o) noexcept {
    if (this != &o) {
        sqlite3_finalize(stmt_);
        stmt_ = std::exchange(o.stmt_, nullptr);
        db_ = o.db_;
        bind_failed_ = o.bind_failed_;
    }
    return *this;
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int index, std::int64_t value) {
    bind_failed_ |= sqlite3_bind_int64(stmt_, index, value) != SQLITE_OK;
    return *this;
}
Statement& Statement::bind(int index, double value) {
    bind_failed_ |= sqlite3_bind_double(stmt_, index, value) != SQLITE_OK;
    return *this;
}
Statement& Statement::bind(int index, std::string_view text) {
    // An empty view may have no data pointer, which SQLite would store as NULL.
    bind_failed_ |= sqlite3_bind_text64(stmt_, index, text.data() ? text.data() : "", text.size(),
                                        SQLITE_TRANSIENT, SQLITE_UTF8) != SQLITE_OK;
    return *this;
}
Statement& Statement::bind_null(int index) {
    bind_failed_ |= sqlite3_bind_null(stmt_, index) != SQLITE_OK;
    return *this;
}
Statement& Statement::bind(int index, std::optional<std::int64_t> value) {
    return value ? bind(index, *value) : bind_null(index);
}

Result<bool> Statement::step() {
    if (bind_failed_) return std::unexpected(db_->error("binding a query parameter"));
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    return std::unexpected(db_->error("running a query"));
}

Result<void> Statement::run() {
    for (;;) {
        TACTUS_TRY(row, step());
        if (!row) return {};
    }
}

void Statement::reset() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
    bind_failed_ = false;
}

std::int64_t Statement::int64(int column) const { return sqlite3_column_int64(stmt_, column); }
double Statement::real(int column) const { return sqlite3_column_double(stmt_, column); }
std::string Statement::text(int column) const {
    const auto* p = sqlite3_column_text(stmt_, column);
    const int n = sqlite3_column_bytes(stmt_, column);
    return p ? std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n))
             : std::string();
}
bool Statement::is_null(int column) const {
    return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

Result<Transaction> Transaction::begin(Database& db) {
    TACTUS_TRY_VOID(db.exec("BEGIN IMMEDIATE"));
    return Transaction(db);
}

Transaction::~Transaction() {
    if (db_) (void)db_->exec("ROLLBACK");
}

Result<void> Transaction::commit() {
    auto r = db_->exec("COMMIT");
    if (r) db_ = nullptr;
    return r;
}

}  // namespace tactus::spool::sql
