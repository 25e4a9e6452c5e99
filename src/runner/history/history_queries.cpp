#include "runner/history/history_queries.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "runner/history/sqlite_statement.h"

namespace robottestingframework {
namespace runner {

std::size_t countRuns(HistoryDatabase& database) {
    SqliteStatement count(database.handle(), "SELECT count(DISTINCT run_key) FROM runs",
                          database.path());
    return count.step() ? static_cast<std::size_t>(count.integer(0)) : 0;
}

bool hasRun(HistoryDatabase& database, const std::string& runKey) {
    SqliteStatement find(database.handle(), "SELECT 1 FROM runs WHERE run_key = ? LIMIT 1",
                         database.path());
    find.bind(1, runKey);
    return find.step();
}

namespace {

struct RunRow {
    std::int64_t row;   // runs.id
    std::size_t place;  // the run's place among the runs read, from 0 (the oldest)
};

// The rows of the last `runs` runs, oldest run first. A run is its key: the rows of its
// shards; runs are ordered by their first shard's start.
std::vector<RunRow> recentRunRows(HistoryDatabase& database, unsigned int runs) {
    SqliteStatement recent(database.handle(),
                           "SELECT u.id, u.run_key FROM (SELECT run_key, min(started) AS first "
                           "FROM runs GROUP BY run_key ORDER BY first DESC, run_key LIMIT ?) k "
                           "JOIN runs u ON u.run_key = k.run_key ORDER BY k.first, k.run_key, u.id",
                           database.path());
    recent.bind(1, static_cast<std::int64_t>(runs));
    std::vector<RunRow> rows;
    std::string previousKey;
    std::size_t place = 0;
    while (recent.step()) {
        const std::string key = recent.text(1);
        if (!rows.empty() && key != previousKey) {
            ++place;
        }
        previousKey = key;
        rows.push_back({recent.integer(0), place});
    }
    return rows;
}

}  // namespace

std::vector<TestHistory> recentHistories(HistoryDatabase& database, unsigned int runs) {
    std::vector<std::int64_t> rows;
    for (const RunRow& run : recentRunRows(database, runs)) {
        rows.push_back(run.row);
    }
    // One run at a time, from the covering index: no sort of every row.
    SqliteStatement results(database.handle(),
                            "SELECT test, state, duration, attempts FROM results WHERE run = ?",
                            database.path());
    SqliteStatement name(database.handle(), "SELECT name FROM tests WHERE id = ?", database.path());
    std::vector<TestHistory> histories;
    std::unordered_map<std::int64_t, std::size_t> places;  // a test's row -> its history
    for (const std::int64_t row : rows) {
        results.reset();
        results.bind(1, row);
        while (results.step()) {
            const auto found = places.emplace(results.integer(0), histories.size());
            if (found.second) {
                name.reset();
                name.bind(1, results.integer(0));
                histories.push_back({name.step() ? name.text(0) : std::string(), {}});
            }
            histories[found.first->second].runs.push_back(
                {results.text(1), results.real(2), static_cast<unsigned int>(results.integer(3))});
        }
    }
    std::sort(histories.begin(), histories.end(),
              [](const TestHistory& a, const TestHistory& b) { return a.test < b.test; });
    return histories;
}

RecentMeasurements recentMeasurements(HistoryDatabase& database, unsigned int runs,
                                      const std::set<std::string>* only) {
    RecentMeasurements found;
    const std::vector<RunRow> rows = recentRunRows(database, runs);
    found.runs = rows.empty() ? 0 : rows.back().place + 1;
    // One run at a time, from its index; each test's name looked up once.
    SqliteStatement values(database.handle(),
                           "SELECT test, name, value, unit, low, high FROM measurements "
                           "WHERE run = ? ORDER BY rowid",
                           database.path());
    SqliteStatement name(database.handle(), "SELECT name FROM tests WHERE id = ?", database.path());
    std::unordered_map<std::int64_t, std::vector<MeasuredValue>*> places;  // null: not wanted
    for (const RunRow& run : rows) {
        values.reset();
        values.bind(1, run.row);
        while (values.step()) {
            auto place = places.find(values.integer(0));
            if (place == places.end()) {
                name.reset();
                name.bind(1, values.integer(0));
                const std::string test = name.step() ? name.text(0) : std::string();
                const bool wanted = only == nullptr || only->count(test) > 0;
                place =
                    places.emplace(values.integer(0), wanted ? &found.byTest[test] : nullptr).first;
            }
            if (place->second == nullptr) {
                continue;
            }
            MeasuredValue value;
            value.run = run.place;
            value.name = values.text(1);
            value.value = values.real(2);
            value.unit = values.text(3);
            if (!values.isNull(4)) {
                value.low = values.real(4);
            }
            if (!values.isNull(5)) {
                value.high = values.real(5);
            }
            place->second->push_back(std::move(value));
        }
    }
    return found;
}

std::vector<FailedInHistory> lastRunFailures(HistoryDatabase& database) {
    std::vector<FailedInHistory> failed;
    SqliteStatement results(database.handle(),
                            "SELECT r.suite, t.name, r.state FROM results r JOIN tests t ON "
                            "t.id = r.test WHERE r.run = ? ORDER BY r.rowid",
                            database.path());
    for (const RunRow& run : recentRunRows(database, 1)) {
        results.reset();
        results.bind(1, run.row);
        while (results.step()) {
            const std::string state = results.text(2);
            // TestStatus's words, as the reports' rerun takes them (rerun_report.h).
            if (state == "failed" || state == "error" || state == "crashed" ||
                state == "timed out") {
                failed.push_back({results.text(0), results.text(1)});
            }
        }
    }
    return failed;
}

std::map<std::string, double> latestSuiteSeconds(HistoryDatabase& database) {
    SqliteStatement rows(database.handle(),
                         "SELECT s.name, s.duration FROM suites s JOIN runs u ON u.id = s.run "
                         "ORDER BY u.started, s.rowid",
                         database.path());
    std::map<std::string, double> seconds;
    while (rows.step()) {
        seconds[rows.text(0)] = rows.real(1);  // a later run's wins
    }
    return seconds;
}

}  // namespace runner
}  // namespace robottestingframework
