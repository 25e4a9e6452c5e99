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
    SqliteStatement rows(database.handle(),
                         "WITH recent AS (SELECT run_key, min(started) AS first FROM runs "
                         "GROUP BY run_key ORDER BY first DESC, run_key LIMIT ?) "
                         "SELECT r.test, t.name, r.state, r.duration, r.attempts "
                         "FROM recent k JOIN runs u ON u.run_key = k.run_key "
                         "JOIN results r ON r.run = u.id JOIN tests t ON t.id = r.test "
                         "ORDER BY k.first, k.run_key, r.rowid",
                         database.path());
    rows.bind(1, static_cast<std::int64_t>(runs));
    std::vector<TestHistory> histories;
    std::unordered_map<std::int64_t, std::size_t> places;  // a test's row -> its history
    while (rows.step()) {
        const auto found = places.emplace(rows.integer(0), histories.size());
        if (found.second) {
            histories.push_back({rows.text(1), {}});
        }
        histories[found.first->second].runs.push_back(
            {rows.text(2), rows.real(3), static_cast<unsigned int>(rows.integer(4))});
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
