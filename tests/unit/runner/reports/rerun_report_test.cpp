// --rerun-failed (rerun_report.h): which tests an earlier report says to run again, and the
// suites cut down to them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_paths.h"
#include "runner/reports/rerun_report.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

// A JUnit output of this runner: suite "arm" with a test in each state.
const char* const everyState = R"(<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="RobotTestingFramework" tests="7" failures="1" errors="1" time="3">
  <testsuite name="arm" tests="7" time="3" id="0">
    <testcase name="passes" classname="arm" time="0.1" status="passed"/>
    <testcase name="skips" classname="arm" time="0.1" status="skipped"/>
    <testcase name="fails" classname="arm" time="0.1" status="failed"/>
    <testcase name="errs" classname="arm" time="0.1" status="error"/>
    <testcase name="crashes" classname="arm" time="0.1" status="crashed"/>
    <testcase name="hangs" classname="arm" time="0.1" status="timed out"/>
    <testcase name="flakes" classname="arm" time="0.1" status="flaky"/>
  </testsuite>
</testsuites>
)";

std::vector<std::string> namesOf(const std::vector<FailedTest>& failed) {
    std::vector<std::string> names;
    for (const auto& test : failed) {
        names.push_back(test.suite + "/" + test.test);
    }
    return names;
}

TestSpec test(const std::string& name, const std::string& plugin = "") {
    TestSpec spec;
    spec.name = name;
    spec.plugin = plugin.empty() ? name + ".so" : plugin;
    return spec;
}

SuiteSpec suite(const std::string& name, std::vector<TestSpec> tests) {
    SuiteSpec spec;
    spec.name = name;
    spec.tests = std::move(tests);
    return spec;
}

std::vector<std::string> namesOf(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> names;
    for (const auto& one : suites) {
        for (const auto& t : one.tests) {
            names.push_back(one.name + "/" + (t.name.empty() ? t.plugin : t.name));
        }
    }
    return names;
}

}  // namespace

TEST(RerunReport, FailedErroredCrashedAndTimedOutTestsRunAgain) {
    EXPECT_EQ(namesOf(parseFailedTests(everyState, "r.xml")),
              (std::vector<std::string>{"arm/fails", "arm/errs", "arm/crashes", "arm/hangs"}));
}

TEST(RerunReport, AJsonReportNamesTheSameTests) {
    const std::string json =
        R"({"reportFormat":"CTRF","generatedBy":"robottestingframework-testrunner",
"results":{"tests":[
{"testId":"1.1","name":"reach","duration":3,"suite":["arm"],"extra":{"rtf":{"state":"passed"}},"status":"passed"},
{"testId":"1.2","name":"grip","duration":3,"suite":["arm"],"extra":{"rtf":{"state":"timed out"}},"status":"failed"},
{"testId":"1.3","name":"wave","duration":3,"suite":["arm"],"extra":{"rtf":{"state":"skipped"}},"status":"skipped"}]}})";
    EXPECT_EQ(namesOf(parseFailedTests(json, "r.json")), (std::vector<std::string>{"arm/grip"}));
}

TEST(RerunReport, AReportThatIsNotOneOfThisRunnersIsAnErrorNamingTheOption) {
    try {
        parseFailedTests("<testsuites name='other'/>", "r.xml");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("--rerun-failed r.xml", 0), 0u) << what;
    }
}

TEST(RerunReport, AMissingReportIsAnErrorNamingIt) {
    const std::string path = std::string(build_paths::unitTestTmpDir()) + "/rerun_report_missing_" +
                             std::to_string(::getpid()) + ".xml";
    try {
        readFailedTests(path);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("--rerun-failed " + path), std::string::npos)
            << e.what();
    }
}

TEST(RerunReport, AReportIsReadFromItsFile) {
    const fs::path dir =
        fs::path(build_paths::unitTestTmpDir()) / ("rerun_report_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "earlier.xml").string();
    std::ofstream(path) << everyState;
    const auto failed = readFailedTests(path);
    fs::remove_all(dir);
    EXPECT_EQ(failed.size(), 4u);
}

TEST(RerunReport, KeepsOnlyTheNamedTestsInTheirSuite) {
    std::vector<SuiteSpec> suites{suite("arm", {test("reach"), test("grip")}),
                                  suite("leg", {test("grip")})};
    keepFailedTests(suites, {{"arm", "grip"}});
    EXPECT_EQ(namesOf(suites), (std::vector<std::string>{"arm/grip"}));
}

TEST(RerunReport, ASuiteLeftWithoutATestIsDropped) {
    std::vector<SuiteSpec> suites{suite("arm", {test("reach")}), suite("leg", {test("walk")})};
    keepFailedTests(suites, {{"leg", "walk"}});
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(suites[0].name, "leg");
}

TEST(RerunReport, ATestWithoutANameIsFoundByItsPlugin) {
    std::vector<SuiteSpec> suites{suite("arm", {test("", "reach.so"), test("", "grip.so")})};
    keepFailedTests(suites, {{"arm", "grip.so"}});
    EXPECT_EQ(namesOf(suites), (std::vector<std::string>{"arm/grip.so"}));
}

TEST(RerunReport, ATestRunAgainNoLongerDependsOnTestsThatPassedBefore) {
    TestSpec grip = test("grip");
    grip.depends = {"reach"};
    std::vector<SuiteSpec> suites{suite("arm", {test("reach"), grip})};
    keepFailedTests(suites, {{"arm", "grip"}});
    ASSERT_EQ(suites.size(), 1u);
    ASSERT_EQ(suites[0].tests.size(), 1u);
    EXPECT_TRUE(suites[0].tests[0].depends.empty());
}

TEST(RerunReport, TheFixturesOfAKeptSuiteStay) {
    SuiteSpec arm = suite("arm", {test("reach"), test("grip")});
    arm.fixtures.push_back(FixtureSpec{"robot", "", "process", "--port 1", {}});
    std::vector<SuiteSpec> suites{arm};
    keepFailedTests(suites, {{"arm", "grip"}});
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(suites[0].fixtures.size(), 1u);
}

TEST(RerunReport, ATestOfAnotherSuiteWithTheSameNameIsNotKept) {
    std::vector<SuiteSpec> suites{suite("arm", {test("grip")})};
    keepFailedTests(suites, {{"hand", "grip"}, {"", "grip"}});
    EXPECT_TRUE(suites.empty());
}

TEST(RerunReport, AFailedStopOfItsWorldRunsTheWholeSuiteAgain) {
    std::vector<SuiteSpec> suites{suite("arm", {test("reach"), test("grip")}),
                                  suite("leg", {test("walk")})};
    keepFailedTests(suites, {{"arm", "world 'lab': stop of 'server'"}});
    EXPECT_EQ(namesOf(suites), (std::vector<std::string>{"arm/reach", "arm/grip"}));
    EXPECT_TRUE(isStopRecord("world 'lab': stop of 'server'"));
    EXPECT_FALSE(isStopRecord("world lab"));
}
