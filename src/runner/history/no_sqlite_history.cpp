// A build without SQLite (Windows here: Debian has no SQLite for MinGW): --history is refused
// when the options are read (historyBuiltIn), so nothing below is reached but through
// --durations naming a history file, which HistoryDatabase refuses with a message that says why.

#include "runner/history/history_database.h"
#include "runner/history/history_error.h"
#include "runner/history/history_queries.h"
#include "runner/history/run_appender.h"
#include "runner/history/sqlite_statement.h"

namespace robottestingframework {
namespace runner {

namespace {

[[noreturn]] void notBuilt(const std::string& path) {
    throw HistoryError("--history " + path +
                       ": the run history is not built into this runner (it needs SQLite)");
}

}  // namespace

HistoryDatabase::HistoryDatabase(const std::string& path, Mode) : path_(path) {
    notBuilt(path);
}

HistoryDatabase::~HistoryDatabase() = default;

bool historyBuiltIn() {
    return false;
}

// No HistoryDatabase can exist, so these are never called; they throw like the rest.
std::size_t countRuns(HistoryDatabase& database) {
    notBuilt(database.path());
}

std::vector<TestHistory> recentHistories(HistoryDatabase& database, unsigned int) {
    notBuilt(database.path());
}

RecentMeasurements recentMeasurements(HistoryDatabase& database, unsigned int,
                                      const std::set<std::string>*) {
    notBuilt(database.path());
}

std::map<std::string, double> latestSuiteSeconds(HistoryDatabase& database) {
    notBuilt(database.path());
}

SqliteStatement::~SqliteStatement() = default;

RunAppender::RunAppender(HistoryDatabase& database, const HistoryRun&) : database_(database) {
    notBuilt(database.path());
}

RunAppender::~RunAppender() = default;

void RunAppender::addSuite(const HistorySuiteResult&) {}
void RunAppender::addTest(const HistoryTestResult&) {}
void RunAppender::addMeasurement(const HistoryMeasurement&) {}
void RunAppender::commit() {}

}  // namespace runner
}  // namespace robottestingframework
