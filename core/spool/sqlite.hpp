// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A thin RAII layer over the SQLite C API: a connection, prepared statements
// with typed binds and columns, and transactions that roll back unless
// committed. Every failure becomes a Result error naming the database file and
// SQLite's own explanation, so "locked", "read-only" and "disk full" reach the
// user as such.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace tactus::spool::sql {

class Statement;

class Database {
public:
    // Opens (creating when `create`) the file in read-write mode with a busy
    // timeout, so concurrent clients wait for each other instead of failing.
    static Result<Database> open(const std::filesystem::path& path, bool create,
                                 int busy_timeout_ms);
    // Opens a file nobody can be writing (read-only file in a read-only
    // folder, where SQLite cannot make the WAL's shared-memory file): no
    // locks, no WAL. Only valid when no -wal file holds changes.
    static Result<Database> open_immutable(const std::filesystem::path& path);

    Database(Database&& o) noexcept;
    Database& operator=(Database&& o) noexcept;
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;
    ~Database();

    // Runs one or more statements without results.
    Result<void> exec(std::string_view sql);
    Result<Statement> prepare(std::string_view sql);
    [[nodiscard]] std::int64_t last_insert_rowid() const;
    [[nodiscard]] int changes() const;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] sqlite3* handle() const { return db_; }

    // The error of the last failed call, located at the database file.
    [[nodiscard]] Error error(std::string_view doing) const;

private:
    Database(sqlite3* db, std::filesystem::path path) : db_(db), path_(std::move(path)) {}
    sqlite3* db_ = nullptr;
    std::filesystem::path path_;
};

class Statement {
public:
    Statement(Statement&& o) noexcept;
    Statement& operator=(Statement&& o) noexcept;
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    ~Statement();

    // Binds are 1-based like SQLite's; they return *this so calls chain.
    Statement& bind(int index, std::int64_t value);
    Statement& bind(int index, double value);
    Statement& bind(int index, std::string_view text);
    Statement& bind_null(int index);
    Statement& bind(int index, std::optional<std::int64_t> value);

    // Steps once: true with a row, false when done.
    Result<bool> step();
    // Steps to the end (statements without rows).
    Result<void> run();
    // Clears binds and rewinds for another use.
    void reset();

    [[nodiscard]] std::int64_t int64(int column) const;
    [[nodiscard]] double real(int column) const;
    [[nodiscard]] std::string text(int column) const;
    [[nodiscard]] bool is_null(int column) const;

private:
    friend class Database;
    Statement(sqlite3_stmt* stmt, const Database* db) : stmt_(stmt), db_(db) {}
    sqlite3_stmt* stmt_ = nullptr;
    const Database* db_ = nullptr;
    bool bind_failed_ = false;
};

// BEGIN IMMEDIATE ... COMMIT. Taking the write lock at the start means two
// clients never both read, then both try to write, then one fails with BUSY
// half-way: the second simply waits (busy timeout) for the first.
class Transaction {
public:
    static Result<Transaction> begin(Database& db);
    Transaction(Transaction&& o) noexcept : db_(o.db_) { o.db_ = nullptr; }
    Transaction& operator=(Transaction&&) = delete;
    Transaction(const Transaction&) = delete;
    ~Transaction();
    Result<void> commit();

private:
    explicit Transaction(Database& db) : db_(&db) {}
    Database* db_ = nullptr;
};

}  // namespace tactus::spool::sql
