// The --history file (src/runner/history): its schema and checks, appending runs, reading
// each test's recent runs back, flaky rates and slowdowns; a run's part of it (RunHistory).
#include <gtest/gtest.h>

#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestSuite.h>

#include "build_paths.h"
#include "runner/cli/run_history.h"
#include "runner/history/history_database.h"
#include "runner/history/history_error.h"
#include "runner/history/history_queries.h"
#include "runner/history/history_trends.h"
#include "runner/history/run_appender.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

class History : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) / ("history_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        path_ = (dir_ / "history.db").string();
    }
    void TearDown() override { fs::remove_all(dir_); }

    // Appends a run of `key` started at `started` with the tests (id, state, seconds).
    void append(const std::string& key, double started,
                const std::vector<HistoryTestResult>& tests) {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        HistoryRun run;
        run.runKey = key;
        run.started = started;
        RunAppender appender(database, run);
        for (const HistoryTestResult& test : tests) {
            appender.addTest(test);
        }
        appender.commit();
    }

    std::string message(HistoryDatabase::Mode mode) {
        try {
            HistoryDatabase database(path_, mode);
        } catch (const HistoryError& e) {
            return e.what();
        }
        return "";
    }

    fs::path dir_;
    std::string path_;
};

HistoryTestResult result(const std::string& test, const std::string& state, double seconds = 1) {
    return {test, "s", state, seconds, 1};
}

TestHistory historyOf(const std::vector<std::string>& states,
                      const std::vector<double>& seconds = {}) {
    TestHistory history{"s/t", {}};
    for (std::size_t i = 0; i < states.size(); ++i) {
        history.runs.push_back({states[i], i < seconds.size() ? seconds[i] : 1.0, 1});
    }
    return history;
}

TEST_F(History, ANewFileGetsTheSchemaAndReadsBack) {
    append("a", 1, {result("s/t", "passed")});
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    const auto histories = recentHistories(database, 30);
    ASSERT_EQ(histories.size(), 1u);
    EXPECT_EQ(histories[0].test, "s/t");
    ASSERT_EQ(histories[0].runs.size(), 1u);
    EXPECT_EQ(histories[0].runs[0].state, "passed");
    EXPECT_EQ(countRuns(database), 1u);
}

TEST_F(History, AFileThatIsNoDatabaseIsAnErrorNamingIt) {
    std::ofstream(path_) << "this is a text file, long enough to be read as a header......";
    const std::string error = message(HistoryDatabase::Mode::Append);
    EXPECT_NE(error.find(path_), std::string::npos) << error;
    EXPECT_NE(error.find("not a history file"), std::string::npos) << error;
}

TEST_F(History, AnotherProgramsDatabaseIsRefused) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE notes(text TEXT)", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
    const std::string error = message(HistoryDatabase::Mode::Append);
    EXPECT_NE(error.find("another program"), std::string::npos) << error;
    EXPECT_NE(error.find(path_), std::string::npos) << error;
}

TEST_F(History, ANewerSchemaIsRefused) {
    append("a", 1, {});
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version=99", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
    const std::string error = message(HistoryDatabase::Mode::Read);
    EXPECT_NE(error.find("newer"), std::string::npos) << error;
}

TEST_F(History, ReadingAMissingFileIsAnErrorAndMakesNoFile) {
    EXPECT_NE(message(HistoryDatabase::Mode::Read).find(path_), std::string::npos);
    EXPECT_FALSE(fs::exists(path_));
}

TEST_F(History, RunsComeBackOldestFirstAndOnlyTheLastN) {
    append("r1", 100, {result("s/t", "passed", 1)});
    append("r3", 300, {result("s/t", "failed", 3)});
    append("r2", 200, {result("s/t", "flaky", 2), result("s/u", "passed")});
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    auto histories = recentHistories(database, 30);
    ASSERT_EQ(histories.size(), 2u);
    ASSERT_EQ(histories[0].runs.size(), 3u);
    EXPECT_EQ(histories[0].runs[0].state, "passed");
    EXPECT_EQ(histories[0].runs[1].state, "flaky");
    EXPECT_EQ(histories[0].runs[2].state, "failed");
    histories = recentHistories(database, 1);
    ASSERT_EQ(histories.size(), 1u);
    EXPECT_EQ(histories[0].runs.size(), 1u);
    EXPECT_DOUBLE_EQ(histories[0].runs[0].duration, 3);
}

TEST_F(History, TheShardsOfOneRunAreOneRun) {
    append("ci-7", 100, {result("s/a", "passed")});
    append("ci-7", 101, {result("s/b", "passed")});
    append("ci-8", 200, {result("s/a", "failed")});
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    EXPECT_EQ(countRuns(database), 2u);
    const auto histories = recentHistories(database, 2);
    ASSERT_EQ(histories.size(), 2u);
    EXPECT_EQ(histories[0].runs.size(), 2u);  // s/a in both runs
    EXPECT_EQ(histories[1].runs.size(), 1u);  // s/b in the first
}

TEST_F(History, AnUncommittedRunLeavesNothing) {
    append("first", 1, {result("s/t", "passed")});
    {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        HistoryRun run;
        run.runKey = "lost";
        RunAppender appender(database, run);
        appender.addTest(result("s/t", "failed"));
    }
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    EXPECT_EQ(countRuns(database), 1u);
}

TEST_F(History, MeasurementsAreStoredWithTheirLimits) {
    {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        HistoryRun run;
        run.runKey = "m";
        RunAppender appender(database, run);
        HistoryMeasurement within{"s/t", "latency", 0.5, "s", true, 0, true, 1};
        HistoryMeasurement open{"s/t", "rate", 99, "Hz", false, 0, false, 0};
        appender.addMeasurement(within);
        appender.addMeasurement(open);
        appender.commit();
    }
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
    sqlite3_stmt* statement = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(db,
                                 "SELECT m.name, m.value, m.unit, m.low IS NULL, m.high "
                                 "FROM measurements m JOIN tests t ON t.id = m.test "
                                 "WHERE t.name = 's/t' ORDER BY m.rowid",
                                 -1, &statement, nullptr),
              SQLITE_OK);
    ASSERT_EQ(sqlite3_step(statement), SQLITE_ROW);
    EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(statement, 0)), "latency");
    EXPECT_DOUBLE_EQ(sqlite3_column_double(statement, 4), 1);
    ASSERT_EQ(sqlite3_step(statement), SQLITE_ROW);
    EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(statement, 2)), "Hz");
    EXPECT_EQ(sqlite3_column_int(statement, 3), 1);
    EXPECT_EQ(sqlite3_step(statement), SQLITE_DONE);
    sqlite3_finalize(statement);
    sqlite3_close(db);
}

TEST_F(History, EachSuitesLatestTimeIsKept) {
    for (const auto& [key, started, seconds] :
         {std::make_tuple("old", 1.0, 5.0), std::make_tuple("new", 2.0, 7.0)}) {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        HistoryRun run;
        run.runKey = key;
        run.started = started;
        RunAppender appender(database, run);
        appender.addSuite({"arm", seconds});
        appender.commit();
    }
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    EXPECT_DOUBLE_EQ(latestSuiteSeconds(database).at("arm"), 7.0);
}

TEST_F(History, SeveralWritersAppendAtOnce) {
    append("setup", 0, {});  // the schema, as the first shard of a CI run would make it
    std::vector<std::thread> shards;
    for (int shard = 0; shard < 4; ++shard) {
        shards.emplace_back([this, shard] {
            std::vector<HistoryTestResult> tests;
            for (int i = 0; i < 200; ++i) {
                tests.push_back(
                    result("s" + std::to_string(shard) + "/" + std::to_string(i), "passed"));
            }
            append("run", 1 + shard, tests);
        });
    }
    for (auto& shard : shards) {
        shard.join();
    }
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    EXPECT_EQ(recentHistories(database, 30).size(), 800u);
}

TEST(HistoryTrends, AFlakyRunOrAChangeOfOutcomeCountsAsFlaky) {
    EXPECT_DOUBLE_EQ(flakyRate(historyOf({"passed", "passed", "passed", "passed"})), 0);
    EXPECT_DOUBLE_EQ(flakyRate(historyOf({"passed", "flaky", "passed", "passed"})), 0.25);
    EXPECT_DOUBLE_EQ(flakyRate(historyOf({"passed", "failed", "passed", "passed"})), 0.5);
    EXPECT_DOUBLE_EQ(flakyRate(historyOf({"failed", "failed", "failed", "failed"})), 0);
    // Skipped runs are not outcomes: passed, skipped, passed is no change.
    EXPECT_DOUBLE_EQ(flakyRate(historyOf({"passed", "skipped", "passed"})), 0);
}

TEST(HistoryTrends, ASlowdownComparesTheNewestThirdWithTheOlderRuns) {
    const Slowdown slowed = slowdownOf(historyOf(
        {"passed", "passed", "passed", "passed", "passed", "passed"}, {1, 1, 1, 1, 3, 3}));
    EXPECT_DOUBLE_EQ(slowed.before, 1);
    EXPECT_DOUBLE_EQ(slowed.recent, 3);
    EXPECT_DOUBLE_EQ(slowdownOf(historyOf({"passed", "passed"}, {1, 5})).ratio(), 0);
}

TEST(HistoryTrends, TheListsAreOrderedAndLeaveOutSteadyTests) {
    std::vector<TestHistory> histories = {
        historyOf({"passed", "failed", "passed"}, {1, 1, 1}),
        historyOf({"passed", "passed", "passed"}, {1, 1, 1}),
        historyOf({"passed", "flaky", "passed"}, {1, 1, 2}),
        historyOf({"passed", "passed", "passed"}, {0.01, 0.01, 0.04}),  // 4 times, yet 30 ms
    };
    histories[0].test = "a";
    histories[1].test = "b";
    histories[2].test = "c";
    histories[3].test = "d";
    const auto flaky = flakiestTests(histories, 10);
    ASSERT_EQ(flaky.size(), 2u);
    EXPECT_EQ(flaky[0].history->test, "a");
    EXPECT_EQ(flaky[1].history->test, "c");
    const auto slowed = mostSlowedTests(histories, 10);
    ASSERT_EQ(slowed.size(), 1u);
    EXPECT_EQ(slowed[0].history->test, "c");
}

// Issue 38, friction 12: a 7x slow-down from 0.016 s to 0.112 s under -j 2 was noise.
TEST(HistoryTrends, ASlowdownIsJudgedAgainstANoiseFloor) {
    const std::vector<std::string> passed(9, "passed");
    // Absolute: 96 ms slower is below the 0.1 s floor, however many times slower.
    const Slowdown small = slowdownOf(
        historyOf(passed, {0.016, 0.016, 0.016, 0.016, 0.016, 0.016, 0.112, 0.112, 0.112}));
    EXPECT_GT(small.ratio(), 6);
    EXPECT_DOUBLE_EQ(small.noise, 0.1);
    EXPECT_FALSE(small.slowedDown());
    // Relative: 10 s to 11.5 s is within 20 %.
    EXPECT_FALSE(
        slowdownOf(historyOf(passed, {10, 10, 10, 10, 10, 10, 11.5, 11.5, 11.5})).slowedDown());
    // The test's own spread: older runs 1 s give or take 0.5 s make 1.5 s noise, not 2.5 s.
    const Slowdown spread =
        slowdownOf(historyOf(passed, {0.5, 1.5, 1, 0.5, 1.5, 1, 1.5, 1.5, 1.5}));
    EXPECT_NEAR(spread.noise, 1.5, 1e-9);
    EXPECT_FALSE(spread.slowedDown());
    EXPECT_TRUE(slowdownOf(historyOf(passed, {1, 1, 1, 1, 1, 1, 2, 2, 2})).slowedDown());
}

TEST(HistoryTrends, ATestThatFailsEveryRunIsListedAsAlwaysFailing) {
    std::vector<TestHistory> histories = {
        historyOf({"failed", "failed", "skipped", "crashed"}, {1, 1, 0, 1}),
        historyOf({"failed", "passed", "failed"}, {1, 1, 1}),
        historyOf({"failed"}, {1}),  // one run says little
        historyOf({"passed", "passed"}, {3, 3}),
    };
    histories[0].test = "a";
    histories[1].test = "b";
    histories[2].test = "c";
    histories[3].test = "d";
    const auto failing = alwaysFailingTests(histories);
    ASSERT_EQ(failing.size(), 1u);
    EXPECT_EQ(failing[0]->test, "a");
    EXPECT_EQ(flakyRate(histories[0]), 0);  // why the flaky list left it out
    const auto slowest = slowestByMedian(histories, 2);
    ASSERT_EQ(slowest.size(), 2u);
    EXPECT_EQ(slowest[0]->test, "d");
}

}  // namespace

TEST_F(History, MeasurementsOfTheLastRunsAreReadPerTestWithTheirRunsPlace) {
    // Three runs; the second of two shards (one key). "s/b" measured nothing.
    const auto appendMeasured = [&](const std::string& key, double started, double value) {
        HistoryDatabase database(path_, HistoryDatabase::Mode::Append);
        HistoryRun run;
        run.runKey = key;
        run.started = started;
        RunAppender appender(database, run);
        appender.addTest(result("s/a", "passed"));
        appender.addTest(result("s/b", "passed"));
        appender.addMeasurement({"s/a", "error", value, "rad", true, 0, true, 0.05});
        appender.addMeasurement({"s/a", "rate", 100, "Hz", false, 0, false, 0});
        appender.commit();
    };
    appendMeasured("one", 1, 0.01);
    appendMeasured("two", 2, 0.02);
    appendMeasured("two", 2.5, 0.03);
    appendMeasured("three", 3, 0.09);
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);

    const RecentMeasurements all = recentMeasurements(database, 2, nullptr);
    EXPECT_EQ(all.runs, 2u);
    ASSERT_EQ(all.byTest.size(), 1u);
    const std::vector<MeasuredValue>& a = all.byTest.at("s/a");
    ASSERT_EQ(a.size(), 6u);
    EXPECT_EQ(a[0].run, 0u);
    EXPECT_EQ(a[0].name, "error");
    EXPECT_DOUBLE_EQ(a[0].value, 0.02);
    EXPECT_EQ(a[0].unit, "rad");
    EXPECT_EQ(a[0].low, 0.0);
    EXPECT_EQ(a[0].high, 0.05);
    EXPECT_EQ(a[1].name, "rate");
    EXPECT_FALSE(a[1].low.has_value());
    EXPECT_FALSE(a[1].high.has_value());
    EXPECT_EQ(a[2].run, 0u);  // the second shard of the same run
    EXPECT_DOUBLE_EQ(a[2].value, 0.03);
    EXPECT_EQ(a[4].run, 1u);
    EXPECT_DOUBLE_EQ(a[4].value, 0.09);

    const std::set<std::string> onlyB = {"s/b"};
    EXPECT_TRUE(recentMeasurements(database, 30, &onlyB).byTest.empty());
}

namespace {

class NamedTest : public robottestingframework::Test {
public:
    explicit NamedTest(std::string name) : Test(std::move(name)) {}
    void run(robottestingframework::TestResult&) override {}
    bool succeeded() const override { return true; }
};

}  // namespace

TEST_F(History, ARunsStripsAreReadBackOnlyWhenAnOutputShowsThem) {
    append("earlier", 1, {result("s/t", "failed")});
    robottestingframework::TestResultCollector collector;
    robottestingframework::TestSuite suite("s");
    NamedTest test("t");
    collector.startTestSuite(&suite);
    collector.startTest(&test);
    collector.endTest(&test);
    collector.endTestSuite(&suite);

    HistoryRun run;
    run.runKey = "shown";
    run.started = 2;
    RunHistory shown(path_, run);
    EXPECT_TRUE(shown.record(collector, stderr, true));
    ASSERT_EQ(shown.strips()->count("s/t"), 1u);
    EXPECT_EQ(shown.strips()->at("s/t").states, (std::vector<std::string>{"failed", "passed"}));

    // With no output showing them (no HTML report: --no-output, say), the run is recorded and
    // nothing is read back.
    run.runKey = "unshown";
    run.started = 3;
    RunHistory unshown(path_, run);
    EXPECT_TRUE(unshown.record(collector, stderr, false));
    EXPECT_TRUE(unshown.strips()->empty());
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    const auto histories = recentHistories(database, 30);
    ASSERT_EQ(histories.size(), 1u);
    EXPECT_EQ(histories[0].runs.size(), 3u);
}

TEST_F(History, TheLastRunsFailuresAreEveryShardsOfItsLastRun) {
    append("one", 100, {result("s/a", "failed"), result("s/b", "failed")});
    append("two", 200, {result("s/a", "passed"), result("s/c", "timed out")});
    append("two", 201,
           {result("s/d", "crashed"), result("s/e", "skipped"), result("s/f", "flaky")});
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    std::vector<std::string> ids;
    for (const FailedInHistory& test : lastRunFailures(database)) {
        EXPECT_EQ(test.suite, "s");
        ids.push_back(test.test);
    }
    EXPECT_EQ(ids, (std::vector<std::string>{"s/c", "s/d"}));
}

TEST_F(History, AnEmptyHistoryHasNoFailures) {
    append("one", 100, {});
    HistoryDatabase database(path_, HistoryDatabase::Mode::Read);
    EXPECT_TRUE(lastRunFailures(database).empty());
}
