// Appends one run to the history in one transaction: begin with the run, add its suites, tests
// and measurements, commit. Nothing of the run is in the file until commit() returns; a
// failure throws HistoryError and leaves the file as it was.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "runner/history/history_database.h"
#include "runner/history/history_run.h"

namespace robottestingframework {
namespace runner {

class SqliteStatement;

class RunAppender {
public:
    // Starts the transaction (waits for another shard's up to the busy timeout).
    RunAppender(HistoryDatabase& database, const HistoryRun& run);
    ~RunAppender();  // rolls back what was not committed
    RunAppender(const RunAppender&) = delete;
    RunAppender& operator=(const RunAppender&) = delete;

    void addSuite(const HistorySuiteResult& suite);
    void addTest(const HistoryTestResult& test);
    // The measurement events feed this (test id, name, value, unit, limits).
    void addMeasurement(const HistoryMeasurement& measurement);
    void commit();

private:
    std::int64_t testRow(const std::string& test);

    HistoryDatabase& database_;
    std::int64_t run_ = 0;
    bool open_ = false;
    std::unique_ptr<SqliteStatement> insertTest_;
    std::unique_ptr<SqliteStatement> findTest_;
    std::unique_ptr<SqliteStatement> insertResult_;
    std::unique_ptr<SqliteStatement> insertSuite_;
    std::unique_ptr<SqliteStatement> insertMeasurement_;
};

}  // namespace runner
}  // namespace robottestingframework
