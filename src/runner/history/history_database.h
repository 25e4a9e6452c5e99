// The --history file: one SQLite database a CI job can carry as an artifact. Opening it checks
// it is this runner's (SQLite's application_id "RTFH") and of a schema version this runner
// reads, and makes the tables when the file is new. WAL and a busy timeout let the shards of
// one run (separate processes) append at once.
//
// Tables (schema version 1):
//   runs(id, run_key, started, host, command, shard_index, shard_count, source)
//     one row per process that appended (a run's shards share run_key) or per imported report
//   tests(id, name)            the test ids (docs/reference/test-ids.md), each once
//   results(run, test, suite, state, duration, attempts)
//   suites(run, name, duration)                       fixtures included: for --durations-from
//   measurements(run, test, name, value, unit, low, high)
#pragma once

#include <cstdint>
#include <string>

struct sqlite3;

namespace robottestingframework {
namespace runner {

class HistoryDatabase {
public:
    enum class Mode {
        Read,    // the file must exist; nothing is written
        Append,  // made when missing; a read-only file fails on the first write
        // As Read, but a file without tables yet is accepted: another run may be making them
        // (it has set WAL, so the file is no longer empty, and not yet written its schema).
        Check,
    };
    // Throws HistoryError naming `path` when it cannot be opened, is not an SQLite database,
    // is another program's database or is of a newer schema. A file in a folder this process
    // may not write is read as it is (Read); Append and Check say that the folder cannot be
    // written.
    HistoryDatabase(const std::string& path, Mode mode);
    ~HistoryDatabase();
    HistoryDatabase(const HistoryDatabase&) = delete;
    HistoryDatabase& operator=(const HistoryDatabase&) = delete;

    sqlite3* handle() const { return db_; }
    const std::string& path() const { return path_; }

    // "RTFH", SQLite's PRAGMA application_id of a history file.
    static constexpr int applicationId = 0x52544648;
    static constexpr int schemaVersion = 1;
    // How long a writer waits for another shard's transaction before giving up.
    static constexpr int busyTimeoutMilliseconds = 30000;

private:
    // What the file says of itself (PRAGMA application_id, user_version; its table count).
    struct Facts {
        std::int64_t application = 0;
        std::int64_t version = 0;
        std::int64_t tables = 0;
    };
    void open(const std::string& name, int flags);
    // False when the file cannot be read (not a database, damaged, or its -shm not made).
    bool readFacts();
    void checkOrCreateSchema(Mode mode);

    Facts facts_;
    sqlite3* db_ = nullptr;
    std::string path_;
};

// True when the file at `path` starts as an SQLite database does ("SQLite format 3"): how
// --durations-from tells a history file from a report.
bool looksLikeHistoryFile(const std::string& path);

// Throws HistoryError "--history PATH: is a character device, not a history file ..." when
// `path` names something other than a regular file (a folder, a FIFO, a device such as /dev/null
// or /dev/full, a socket): SQLite would write its journal beside it (/dev/null-journal). A path
// that names nothing yet is fine (the history file is created there).
void checkHistoryFileKind(const std::string& path);

}  // namespace runner
}  // namespace robottestingframework
