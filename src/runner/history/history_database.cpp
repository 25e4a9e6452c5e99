#include "runner/history/history_database.h"

#include "runner/history/sqlite_library.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <thread>

#include "runner/history/history_error.h"
#include "runner/history/sqlite_statement.h"

namespace robottestingframework {
namespace runner {

namespace {

const char* const schema = R"sql(
CREATE TABLE IF NOT EXISTS runs(
    id INTEGER PRIMARY KEY,
    run_key TEXT NOT NULL,
    started REAL NOT NULL,
    host TEXT NOT NULL,
    command TEXT NOT NULL,
    shard_index INTEGER,
    shard_count INTEGER,
    source TEXT NOT NULL);
CREATE INDEX IF NOT EXISTS runs_by_key ON runs(run_key);
CREATE TABLE IF NOT EXISTS tests(
    id INTEGER PRIMARY KEY,
    name TEXT NOT NULL UNIQUE);
CREATE TABLE IF NOT EXISTS results(
    run INTEGER NOT NULL REFERENCES runs(id),
    test INTEGER NOT NULL REFERENCES tests(id),
    suite TEXT NOT NULL,
    state TEXT NOT NULL,
    duration REAL NOT NULL,
    attempts INTEGER NOT NULL);
-- Covering: a run's results are read from the index alone (--history-report, the pages).
CREATE INDEX IF NOT EXISTS results_by_run ON results(run, test, state, duration, attempts);
CREATE TABLE IF NOT EXISTS suites(
    run INTEGER NOT NULL REFERENCES runs(id),
    name TEXT NOT NULL,
    duration REAL NOT NULL);
CREATE INDEX IF NOT EXISTS suites_by_name ON suites(name, run);
CREATE TABLE IF NOT EXISTS measurements(
    run INTEGER NOT NULL REFERENCES runs(id),
    test INTEGER NOT NULL REFERENCES tests(id),
    name TEXT NOT NULL,
    value REAL NOT NULL,
    unit TEXT NOT NULL,
    low REAL,
    high REAL);
CREATE INDEX IF NOT EXISTS measurements_by_run ON measurements(run);
)sql";

std::int64_t pragmaNumber(sqlite3* db, const char* pragma, const std::string& file) {
    SqliteStatement statement(db, std::string("PRAGMA ") + pragma, file);
    return statement.step() ? statement.integer(0) : 0;
}

// `path` as an SQLite URI that reads it as it is (immutable: no lock, no -wal or -shm file
// made beside it), for a file in a folder this process may not write.
std::string immutableUri(const std::string& path) {
    static const char* const hex = "0123456789ABCDEF";
    std::string uri = "file:";
    for (const char ch : path) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
            c == '/' || c == '.' || c == '-' || c == '_' || c == '~') {
            uri += ch;
        } else {
            uri += '%';
            uri += hex[c >> 4];
            uri += hex[c & 0xF];
        }
    }
    return uri + "?immutable=1";
}

// The folder of `path`, as the messages name it.
std::string folderOf(const std::string& path) {
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return folder.empty() ? "." : folder;
}

}  // namespace

HistoryDatabase::HistoryDatabase(const std::string& path, Mode mode) : path_(path) {
    checkHistoryFileKind(path);  // never a device: SQLite would leave PATH-journal beside it
    // A reader opens the file for writing too (never creating it) and writes nothing: SQLite
    // makes -wal and -shm files beside a WAL database to read it, and only a connection that
    // may write removes them when it closes (a read-only one would leave them in the user's
    // folder after every --history-report). A file the user may not write is opened read-only.
    const int flags =
        mode == Mode::Append ? SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE : SQLITE_OPEN_READWRITE;
    open(path, flags);
    try {
        if (!readFacts()) {
            // A WAL file is read beside its -wal and -shm files, which SQLite makes when they
            // are missing: in a folder this process may not write, it cannot. Read as it is,
            // the file tells whether it is a history file; then only a write is impossible.
            sqlite().close(db_);
            db_ = nullptr;
            open(immutableUri(path), SQLITE_OPEN_READONLY | SQLITE_OPEN_URI);
            if (!readFacts()) {
                throw HistoryError("--history " + path_ +
                                   ": not a history file (not an SQLite database, or a damaged "
                                   "one)");
            }
            if (mode != Mode::Read) {
                throw HistoryError("--history " + path_ + ": the folder " + folderOf(path_) +
                                   " cannot be written (a run is recorded in the history file "
                                   "and SQLite's -wal and -shm files beside it); give a history "
                                   "file in a folder you may write");
            }
        }
        checkOrCreateSchema(mode);
    } catch (...) {
        sqlite().close(db_);
        db_ = nullptr;
        throw;
    }
}

void HistoryDatabase::open(const std::string& name, int flags) {
    if (sqlite().open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
        const std::string why = db_ != nullptr ? sqlite().errmsg(db_) : "out of memory";
        sqlite().close(db_);
        db_ = nullptr;
        throw HistoryError("--history " + path_ + ": cannot open the history file (" + why + ")");
    }
    sqlite().busy_timeout(db_, busyTimeoutMilliseconds);
}

HistoryDatabase::~HistoryDatabase() {
    if (db_ != nullptr) {
        sqlite().close(db_);
    }
}

bool HistoryDatabase::readFacts() {
    try {
        // One read transaction, so the three come from one snapshot: another run may commit
        // the schema meanwhile, and tables without the application_id would read as another
        // program's database.
        runSql(db_, "BEGIN", path_);
        facts_.application = pragmaNumber(db_, "application_id", path_);
        facts_.version = pragmaNumber(db_, "user_version", path_);
        {
            SqliteStatement count(db_, "SELECT count(*) FROM sqlite_master", path_);
            facts_.tables = count.step() ? count.integer(0) : 0;
        }
        runSql(db_, "COMMIT", path_);
        return true;
    } catch (const HistoryError&) {
        sqlite().exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        return false;
    }
}

void HistoryDatabase::checkOrCreateSchema(Mode mode) {
    const std::int64_t application = facts_.application;
    const std::int64_t tables = facts_.tables;
    const std::int64_t version = facts_.version;
    const bool fresh = application == 0 && tables == 0;
    if (!fresh && application != applicationId) {
        throw HistoryError("--history " + path_ +
                           ": an SQLite database of another program, not a history file of "
                           "this runner (its application_id is " +
                           std::to_string(application) + ")");
    }
    if (!fresh && version > schemaVersion) {
        throw HistoryError("--history " + path_ + ": written by a newer runner (schema " +
                           std::to_string(version) + "; this runner reads up to " +
                           std::to_string(schemaVersion) + ")");
    }
    if (mode == Mode::Read && fresh) {
        throw HistoryError("--history " + path_ + ": an empty file, no run recorded yet");
    }
    if (mode != Mode::Append) {
        return;
    }
    // WAL: readers never wait for the shard that writes. Changing the journal mode takes a
    // lock that the busy timeout does not wait for, so a shard that meets another one doing
    // it retries for a while.
    const auto giveUp =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(busyTimeoutMilliseconds);
    for (;;) {
        const int status = sqlite().exec(db_, "PRAGMA journal_mode=WAL", nullptr, nullptr, nullptr);
        if (status == SQLITE_OK) {
            break;
        }
        if ((status != SQLITE_BUSY && status != SQLITE_LOCKED) ||
            std::chrono::steady_clock::now() > giveUp) {
            throw HistoryError("--history " + path_ + ": " + sqlite().errmsg(db_));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (fresh || version < schemaVersion) {
        runSql(db_, "BEGIN IMMEDIATE", path_);
        try {
            runSql(db_, schema, path_);
            runSql(db_,
                   "PRAGMA application_id=" + std::to_string(applicationId) +
                       "; PRAGMA user_version=" + std::to_string(schemaVersion),
                   path_);
            runSql(db_, "COMMIT", path_);
        } catch (...) {
            sqlite().exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
            throw;
        }
    }
}

}  // namespace runner
}  // namespace robottestingframework
