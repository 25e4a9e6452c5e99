#include "runner/history/run_appender.h"

#include "runner/history/sqlite_library.h"

#include "runner/history/sqlite_statement.h"

namespace robottestingframework {
namespace runner {

RunAppender::RunAppender(HistoryDatabase& database, const HistoryRun& run) : database_(database) {
    sqlite3* db = database.handle();
    const std::string& file = database.path();
    // IMMEDIATE: take the write lock now, so two shards never both start and one then fails.
    runSql(db, "BEGIN IMMEDIATE", file);
    open_ = true;
    SqliteStatement insertRun(db,
                              "INSERT INTO runs(run_key, started, host, command, shard_index, "
                              "shard_count, source) VALUES(?, ?, ?, ?, ?, ?, ?)",
                              file);
    insertRun.bind(1, run.runKey).bind(2, run.started).bind(3, run.host).bind(4, run.command);
    if (run.sharded) {
        insertRun.bind(5, static_cast<std::int64_t>(run.shardIndex))
            .bind(6, static_cast<std::int64_t>(run.shardCount));
    } else {
        insertRun.bindNull(5).bindNull(6);
    }
    insertRun.bind(7, run.source);
    insertRun.step();
    run_ = sqlite().last_insert_rowid(db);
    insertTest_ =
        std::make_unique<SqliteStatement>(db, "INSERT OR IGNORE INTO tests(name) VALUES(?)", file);
    findTest_ = std::make_unique<SqliteStatement>(db, "SELECT id FROM tests WHERE name = ?", file);
    insertResult_ = std::make_unique<SqliteStatement>(
        db,
        "INSERT INTO results(run, test, suite, state, duration, attempts) VALUES(?, ?, ?, ?, ?, ?)",
        file);
    insertSuite_ = std::make_unique<SqliteStatement>(
        db, "INSERT INTO suites(run, name, duration) VALUES(?, ?, ?)", file);
    insertMeasurement_ = std::make_unique<SqliteStatement>(
        db,
        "INSERT INTO measurements(run, test, name, value, unit, low, high) "
        "VALUES(?, ?, ?, ?, ?, ?, ?)",
        file);
}

RunAppender::~RunAppender() {
    // Statements first: a rollback with statements still running is refused.
    insertTest_.reset();
    findTest_.reset();
    insertResult_.reset();
    insertSuite_.reset();
    insertMeasurement_.reset();
    if (open_) {
        sqlite().exec(database_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
    }
}

std::int64_t RunAppender::testRow(const std::string& test) {
    insertTest_->reset();
    insertTest_->bind(1, test).step();
    if (sqlite().changes(database_.handle()) > 0) {
        return sqlite().last_insert_rowid(database_.handle());
    }
    findTest_->reset();
    findTest_->bind(1, test);
    findTest_->step();
    return findTest_->integer(0);
}

void RunAppender::addSuite(const HistorySuiteResult& suite) {
    insertSuite_->reset();
    insertSuite_->bind(1, run_).bind(2, suite.name).bind(3, suite.duration).step();
}

void RunAppender::addTest(const HistoryTestResult& test) {
    const std::int64_t row = testRow(test.test);
    insertResult_->reset();
    insertResult_->bind(1, run_)
        .bind(2, row)
        .bind(3, test.suite)
        .bind(4, test.state)
        .bind(5, test.duration)
        .bind(6, static_cast<std::int64_t>(test.attempts))
        .step();
}

void RunAppender::addMeasurement(const HistoryMeasurement& measurement) {
    const std::int64_t row = testRow(measurement.test);
    SqliteStatement& insert = *insertMeasurement_;
    insert.reset();
    insert.bind(1, run_)
        .bind(2, row)
        .bind(3, measurement.name)
        .bind(4, measurement.value)
        .bind(5, measurement.unit);
    if (measurement.hasLow) {
        insert.bind(6, measurement.low);
    }
    if (measurement.hasHigh) {
        insert.bind(7, measurement.high);
    }
    insert.step();
}

void RunAppender::commit() {
    runSql(database_.handle(), "COMMIT", database_.path());
    open_ = false;
}

}  // namespace runner
}  // namespace robottestingframework
