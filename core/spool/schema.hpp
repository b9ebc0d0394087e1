// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The spool's tables (docs/spool.md explains each column). The version lives in
// PRAGMA user_version and the application id marks the file as a Tactus spool,
// so another program's SQLite file is refused rather than written into.
#include <cstdint>

namespace tactus::spool {

inline constexpr int kSchemaVersion = 2;
inline constexpr std::int32_t kApplicationId = 0x54435350;  // "TCSP"

// Jobs sent from another system (a CUPS job, by its job-uuid) and the spool
// job each became: submitting the same origin again gives the same job, so a
// job CUPS runs twice is queued once. Made on open when missing, so spools
// written before it gain it without a version change.
inline constexpr const char* kJobOrigins = R"sql(
CREATE TABLE IF NOT EXISTS job_origins(
  origin TEXT PRIMARY KEY,
  job_id INTEGER NOT NULL UNIQUE REFERENCES jobs(id) ON DELETE CASCADE
) WITHOUT ROWID;
)sql";

inline constexpr const char* kSchema = R"sql(
CREATE TABLE printers(
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL UNIQUE,
  device        TEXT NOT NULL,
  profile_json  TEXT NOT NULL,
  runner        TEXT NOT NULL DEFAULT '',
  created_at    REAL NOT NULL,
  next_link_job INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE jobs(
  id              INTEGER PRIMARY KEY,
  printer_id      INTEGER NOT NULL REFERENCES printers(id),
  title           TEXT NOT NULL,
  document        TEXT NOT NULL,
  profile_json    TEXT NOT NULL,
  sheets_per_copy INTEGER NOT NULL CHECK(sheets_per_copy > 0),
  copies          INTEGER NOT NULL CHECK(copies > 0),
  first_page      INTEGER NOT NULL DEFAULT 0,
  last_page       INTEGER NOT NULL DEFAULT 0,
  priority        INTEGER NOT NULL DEFAULT 0,
  state           TEXT NOT NULL CHECK(state IN ('queued','running','paused','completed','cancelled','failed')),
  reason          TEXT NOT NULL DEFAULT '',
  control         TEXT NOT NULL DEFAULT '',
  resume_sheet    INTEGER,
  retries         INTEGER NOT NULL DEFAULT 0,
  not_before      REAL NOT NULL DEFAULT 0,
  runner          TEXT NOT NULL DEFAULT '',
  link_job        INTEGER,
  run_start_sheet INTEGER NOT NULL DEFAULT 0,
  run_open        INTEGER NOT NULL DEFAULT 0,
  run_first_pass  INTEGER NOT NULL DEFAULT 0,
  submitted_by    TEXT NOT NULL,
  submitted_at    REAL NOT NULL,
  started_at      REAL,
  finished_at     REAL,
  updated_at      REAL NOT NULL
);
CREATE INDEX jobs_by_queue ON jobs(printer_id, state, priority DESC, id);
CREATE INDEX jobs_by_state ON jobs(state, id);
CREATE TABLE progress(
  job_id       INTEGER NOT NULL REFERENCES jobs(id) ON DELETE CASCADE,
  sheet        INTEGER NOT NULL,
  passes_total INTEGER NOT NULL,
  passes_done  INTEGER NOT NULL DEFAULT 0 CHECK(passes_done <= passes_total),
  spoiled      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY(job_id, sheet)
) WITHOUT ROWID;
CREATE TABLE events(
  id         INTEGER PRIMARY KEY,
  job_id     INTEGER REFERENCES jobs(id) ON DELETE CASCADE,
  printer_id INTEGER REFERENCES printers(id),
  at         REAL NOT NULL,
  kind       TEXT NOT NULL,
  message    TEXT NOT NULL
);
CREATE INDEX events_by_job ON events(job_id, id);
)sql";

// From version 1: the run record names the stream's first pass, and each
// printer counts the controller job ids it hands out (docs/spool.md).
inline constexpr const char* kMigrate1To2 = R"sql(
ALTER TABLE printers ADD COLUMN next_link_job INTEGER NOT NULL DEFAULT 0;
ALTER TABLE jobs ADD COLUMN run_first_pass INTEGER NOT NULL DEFAULT 0;
)sql";

// Controller job ids the spool hands out; direct embossing uses the rest.
inline constexpr std::uint16_t kFirstLinkJob = 0x8001;

}  // namespace tactus::spool
