// The planning stage (planned_run.h): how --rerun-failed, the selection and the shard cut
// combine, on suites in memory and reports written to a scratch folder.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "build_paths.h"
#include "runner/cli/planned_run.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

TestSpec test(const std::string& name, std::vector<std::string> tags = {}) {
    TestSpec spec;
    spec.name = name;
    spec.plugin = name + ".so";
    spec.tags = std::move(tags);
    return spec;
}

SuiteSpec suite(const std::string& name, std::vector<TestSpec> tests) {
    SuiteSpec spec;
    spec.name = name;
    spec.where.file = name + ".xml";
    spec.tests = std::move(tests);
    return spec;
}

// Four suites of one test each: without durations, shard 0 of 2 is a and c, shard 1 b and d.
std::vector<SuiteSpec> fourSuites() {
    return {suite("a", {test("a1", {"skip"})}), suite("b", {test("b1")}), suite("c", {test("c1")}),
            suite("d", {test("d1")})};
}

std::vector<std::string> namesOf(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> names;
    for (const auto& one : suites) {
        for (const auto& t : one.tests) {
            names.push_back(one.name + "/" + t.name);
        }
    }
    return names;
}

std::vector<std::string> notesOf(const PlannedRun& plan) {
    std::vector<std::string> lines;
    for (const auto& note : plan.notes) {
        lines.push_back((note.stream == PlanNote::Stream::Out ? "out: " : "err: ") + note.text);
    }
    return lines;
}

ShardChoice shardOf(unsigned int index, unsigned int count) {
    ShardChoice choice;
    choice.sharded = true;
    choice.index = index;
    choice.count = count;
    choice.source =
        "--shard-index " + std::to_string(index) + " --shard-count " + std::to_string(count);
    return choice;
}

TagExpression tag(const std::string& text) {
    TagExpression expression;
    std::string error;
    EXPECT_TRUE(TagExpression::parse(text, expression, error)) << error;
    return expression;
}

struct Reported {
    std::string suite;
    std::string test;
    std::string status;
    double seconds = 0.5;
};

class PlannedRunTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ =
            fs::path(build_paths::unitTestTmpDir()) / ("planned_run_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A JUnit output of this runner, one suite per test; `shard` "INDEX/COUNT" or empty.
    std::string report(const std::vector<Reported>& tests, const std::string& shard = "") {
        std::string text =
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<testsuites name=\"RobotTestingFramework\" tests=\"" +
            std::to_string(tests.size()) +
            "\" failures=\"0\" errors=\"0\" "
            "time=\"1\">\n";
        if (!shard.empty()) {
            const std::size_t slash = shard.find('/');
            text += "  <properties>\n    <property name=\"rtf.shard.index\" value=\"" +
                    shard.substr(0, slash) +
                    "\"/>\n    <property name=\"rtf.shard.count\" value=\"" +
                    shard.substr(slash + 1) + "\"/>\n  </properties>\n";
        }
        int id = 0;
        for (const auto& t : tests) {
            text += "  <testsuite name=\"" + t.suite + "\" tests=\"1\" time=\"" +
                    std::to_string(t.seconds) + "\" id=\"" + std::to_string(id++) + "\">\n" +
                    "    <testcase name=\"" + t.test + "\" classname=\"" + t.suite +
                    "\" time=\"0.5\" status=\"" + t.status + "\"/>\n  </testsuite>\n";
        }
        text += "</testsuites>\n";
        const std::string path = (dir_ / ("report" + std::to_string(reports_++) + ".xml")).string();
        std::ofstream(path) << text;
        return path;
    }

    fs::path dir_;
    int reports_ = 0;
};

}  // namespace

TEST_F(PlannedRunTest, WithoutRerunSelectionOrShardEverySuiteRunsAsRead) {
    const PlannedRun plan = planRun(Options(), fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"a/a1", "b/b1", "c/c1", "d/d1"}));
    EXPECT_TRUE(plan.notes.empty());
    EXPECT_TRUE(plan.shardOf.empty());
    EXPECT_FALSE(plan.reportSettings.rerun);
    EXPECT_FALSE(plan.reportSettings.sharded);
    EXPECT_TRUE(plan.reportSettings.suitePlaces.empty());
}

TEST_F(PlannedRunTest, ARerunKeepsOnlyTheTestsTheReportSaysFailed) {
    Options options;
    options.rerunFailed = report({{"arm", "reach", "passed"},
                                  {"arm", "grip", "failed"},
                                  {"leg", "walk", "passed"},
                                  {"leg", "kick", "timed out"}});
    const PlannedRun plan =
        planRun(options,
                {suite("arm", {test("reach"), test("grip")}),
                 suite("leg", {test("walk"), test("kick")}), suite("head", {test("nod")})},
                ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"arm/grip", "leg/kick"}));
    EXPECT_TRUE(plan.reportSettings.rerun);
    EXPECT_FALSE(plan.reportSettings.sharded);
    EXPECT_TRUE(plan.notes.empty());
}

TEST_F(PlannedRunTest, ARerunOfAReportWithoutFailuresRunsNothing) {
    Options options;
    options.rerunFailed = report({{"a", "a1", "passed"}, {"b", "b1", "skipped"}});
    const PlannedRun plan = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::NothingToRerun);
    EXPECT_EQ(notesOf(plan), (std::vector<std::string>{"out: " + options.rerunFailed +
                                                       " has no failed test: nothing to rerun"}));
}

TEST_F(PlannedRunTest, ARerunOfAReportThatCannotBeReadIsAnErrorNamingIt) {
    Options options;
    options.rerunFailed = (dir_ / "missing.xml").string();
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Error);
    EXPECT_NE(plan.error.find("--rerun-failed " + options.rerunFailed), std::string::npos)
        << plan.error;
    EXPECT_TRUE(plan.notes.empty());
}

TEST_F(PlannedRunTest, ARerunOfAShardRunsItsFailuresAsTheSameShardWithoutCuttingAgain) {
    Options options;
    // Shard 1 of 3 failed b1 and c1; this machine would be shard 0 of 2 (a and c).
    options.rerunFailed = report({{"b", "b1", "failed"}, {"c", "c1", "error"}}, "1/3");
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"b/b1", "c/c1"}));
    EXPECT_FALSE(plan.shard.sharded);
    EXPECT_TRUE(plan.reportSettings.rerun);
    EXPECT_TRUE(plan.reportSettings.sharded);
    EXPECT_EQ(plan.reportSettings.shardIndex, 1u);
    EXPECT_EQ(plan.reportSettings.shardCount, 3u);
    EXPECT_TRUE(plan.reportSettings.suitePlaces.empty());
    EXPECT_EQ(notesOf(plan), (std::vector<std::string>{
                                 "out: --rerun-failed: the failed tests of " + options.rerunFailed +
                                 " run again as they are; the shard (--shard-index 0 "
                                 "--shard-count 2) is not taken again"}));
}

TEST_F(PlannedRunTest, ARerunThenASelectionRunsOnlyTheFailedTestsSelected) {
    Options options;
    options.rerunFailed = report({{"arm", "reach", "failed"}, {"arm", "grip", "crashed"}});
    options.selection.include.push_back(tag("slow"));
    const PlannedRun plan = planRun(
        options, {suite("arm", {test("reach"), test("grip", {"slow"}), test("wave", {"slow"})})},
        ShardChoice());
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"arm/grip"}));
}

TEST_F(PlannedRunTest, ARerunMatchingNoTestOfThisRunIsAnErrorNamingTheReport) {
    Options options;
    options.rerunFailed = report({{"other", "x", "failed"}});
    const PlannedRun plan = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Error);
    EXPECT_EQ(plan.error, "--rerun-failed " + options.rerunFailed +
                              ": none of its 1 failed test(s) is a test of this run (other/x, "
                              "...); give the suites that report was written for");
}

TEST_F(PlannedRunTest, ASelectionMatchingNothingIsNothingSelectedUnlessAllowed) {
    Options options;
    options.selection.include.push_back(tag("nothing"));
    const PlannedRun plan = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::NothingSelected);
    EXPECT_NE(plan.error.find("no test is selected"), std::string::npos) << plan.error;
    options.allowEmpty = true;
    const PlannedRun allowed = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(allowed.outcome, PlannedRun::Outcome::Run);
    EXPECT_TRUE(allowed.suites.empty());
    EXPECT_EQ(notesOf(allowed), (std::vector<std::string>{"err: warning: no test is selected"}));
}

TEST_F(PlannedRunTest, SuitesWrittenWithoutTestsRunAsRtf2RanThemWithANote) {
    const PlannedRun plan = planRun(Options(), {suite("empty", {})}, ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_EQ(namesOf(plan.suites), std::vector<std::string>{});
    EXPECT_EQ(notesOf(plan),
              (std::vector<std::string>{"out: note: the suites given have no test"}));
}

TEST_F(PlannedRunTest, AShardKeepsItsSuitesWithTheirPlacesInTheWholeSelection) {
    const PlannedRun plan = planRun(Options(), fourSuites(), shardOf(1, 2));
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"b/b1", "d/d1"}));
    EXPECT_EQ(plan.reportSettings.suitePlaces, (std::vector<std::size_t>{1, 3}));
    EXPECT_TRUE(plan.reportSettings.sharded);
    EXPECT_FALSE(plan.reportSettings.rerun);
    EXPECT_EQ(plan.reportSettings.shardIndex, 1u);
    EXPECT_EQ(plan.reportSettings.shardCount, 2u);
    EXPECT_TRUE(plan.shardOf.empty());
    EXPECT_EQ(notesOf(plan), (std::vector<std::string>{
                                 "out: shard 1 of 2 (from --shard-index 1 --shard-count 2): 2 of "
                                 "4 suites"}));
}

TEST_F(PlannedRunTest, TheShardIsCutFromTheSelectionNotFromEverySuiteRead) {
    Options options;
    options.selection.exclude.push_back(tag("skip"));  // a is out: b c d split b d | c
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"b/b1", "d/d1"}));
    EXPECT_EQ(plan.reportSettings.suitePlaces, (std::vector<std::size_t>{0, 2}));
}

TEST_F(PlannedRunTest, ListingKeepsEveryShardsSuitesWithTheirShard) {
    Options options;
    options.list = true;
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(1, 2));
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"a/a1", "b/b1", "c/c1", "d/d1"}));
    EXPECT_EQ(plan.shardOf, (std::vector<unsigned int>{0, 1, 0, 1}));
    EXPECT_EQ(plan.shard.count, 2u);
    EXPECT_EQ(notesOf(plan), (std::vector<std::string>{
                                 "out: shard 1 of 2 (from --shard-index 1 --shard-count 2): 2 of "
                                 "4 suites"}));
}

TEST_F(PlannedRunTest, AShardWithoutSuitesSaysSo) {
    std::vector<SuiteSpec> one{suite("a", {test("a1")})};
    const PlannedRun plan = planRun(Options(), std::move(one), shardOf(1, 2));
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_TRUE(plan.suites.empty());
    EXPECT_TRUE(plan.reportSettings.sharded);
    EXPECT_EQ(notesOf(plan), (std::vector<std::string>{
                                 "out: shard 1 of 2 (from --shard-index 1 --shard-count 2): 0 of "
                                 "1 suites",
                                 "out: shard 1 of 2 has no suite to run"}));
}

TEST_F(PlannedRunTest, VerboseNamesEachSuiteTheShardRunsAndItsFile) {
    Options options;
    options.verbose = true;
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(notesOf(plan),
              (std::vector<std::string>{
                  "out: shard 0 of 2 (from --shard-index 0 --shard-count 2): 2 of "
                  "4 suites",
                  "out: shard 0 runs suite a (a.xml)", "out: shard 0 runs suite c (c.xml)"}));
}

TEST_F(PlannedRunTest, DurationsWithoutAShardAreKeptForTheEtaWithoutAWarning) {
    Options options;
    options.durations = report({{"a", "a1", "passed", 30}, {"b", "b1", "passed", 10}});
    const PlannedRun plan = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_EQ(plan.suites.size(), 4u);
    // Only the progress line's ETA reads them: that is their use, not a mistake to warn about.
    EXPECT_EQ(notesOf(plan), std::vector<std::string>{});
    // Read here, once: the progress line takes them from the plan.
    ASSERT_TRUE(plan.durations.has_value());
    EXPECT_EQ(*plan.durations, (SuiteSeconds{{"a", 30.0}, {"b", 10.0}}));
}

TEST_F(PlannedRunTest, DurationsThatCannotBeReadWithoutAShardOnlyCostTheEta) {
    Options options;
    options.durations = (dir_ / "missing.xml").string();
    const PlannedRun plan = planRun(options, fourSuites(), ShardChoice());
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Run);
    EXPECT_FALSE(plan.durations.has_value());
    const std::vector<std::string> notes = notesOf(plan);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].rfind("err: warning: --durations-from " + options.durations + ": ", 0), 0u)
        << notes[0];
    EXPECT_NE(notes[0].find("; no ETA"), std::string::npos) << notes[0];
}

TEST_F(PlannedRunTest, DurationsBalanceTheShardAndTheShardLineSaysSo) {
    Options options;
    // a takes as long as the three others together: alone in its shard.
    options.durations = report({{"a", "a1", "passed", 30},
                                {"b", "b1", "passed", 10},
                                {"c", "c1", "passed", 10},
                                {"d", "d1", "passed", 10}});
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"a/a1"}));
    EXPECT_EQ(notesOf(plan),
              (std::vector<std::string>{"out: shard 0 of 2 (from --shard-index 0 --shard-count 2), "
                                        "balanced by " +
                                        options.durations + ": 1 of 4 suites"}));
}

TEST_F(PlannedRunTest, DurationsThatCannotBeReadAreAnErrorNamingThem) {
    Options options;
    options.durations = (dir_ / "missing.xml").string();
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(0, 2));
    EXPECT_EQ(plan.outcome, PlannedRun::Outcome::Error);
    EXPECT_NE(plan.error.find("--durations-from " + options.durations), std::string::npos)
        << plan.error;
}

TEST_F(PlannedRunTest, ARerunOfAShardThenASelectionKeepsTheShardItCameFrom) {
    Options options;
    options.rerunFailed = report({{"b", "b1", "failed"}, {"d", "d1", "failed"}}, "1/2");
    options.selection.filters.emplace_back();
    std::string error;
    ASSERT_TRUE(NameFilter::parse("d/*", options.selection.filters.back(), error)) << error;
    const PlannedRun plan = planRun(options, fourSuites(), shardOf(1, 2));
    EXPECT_EQ(namesOf(plan.suites), (std::vector<std::string>{"d/d1"}));
    EXPECT_TRUE(plan.reportSettings.sharded);
    EXPECT_EQ(plan.reportSettings.shardIndex, 1u);
    EXPECT_TRUE(plan.reportSettings.suitePlaces.empty());
}
