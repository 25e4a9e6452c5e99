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

std::vector<TestHistory> recentHistories(HistoryDatabase& database, unsigned int runs) {
    // A run is its key: the rows of its shards; runs are ordered by their first shard's start.
    SqliteStatement recent(database.handle(),
                           "SELECT u.id FROM (SELECT run_key, min(started) AS first FROM runs "
                           "GROUP BY run_key ORDER BY first DESC, run_key LIMIT ?) k "
                           "JOIN runs u ON u.run_key = k.run_key ORDER BY k.first, k.run_key, u.id",
                           database.path());
    recent.bind(1, static_cast<std::int64_t>(runs));
    std::vector<std::int64_t> rows;
    while (recent.step()) {
        rows.push_back(recent.integer(0));
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
