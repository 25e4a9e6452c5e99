// Reports of this runner read back (report_reader.h): strict, errors naming FILE:LINE.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_paths.h"
#include "runner/reports/report_reader.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

class ReportReader : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("report_reader_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& text) {
        const std::string path = (dir_ / "report").string();
        std::ofstream(path) << text;
        return path;
    }
    std::string errorOf(const std::string& text) {
        const std::string path = write(text);
        try {
            readReport("--durations", path);
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "(no error)";
    }

    fs::path dir_;
};

const char* const junit = R"(<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="RobotTestingFramework" tests="2" failures="1" errors="0" time="1.5">
  <properties>
    <property name="rtf.shard.index" value="1"/>
    <property name="rtf.shard.count" value="3"/>
  </properties>
  <testsuite name="arm" tests="2" time="1.250" id="4">
    <testcase name="reach" classname="arm" time="0.5" status="passed"/>
    <testcase name="grip" classname="arm" time="0.5" status="failed"/>
  </testsuite>
</testsuites>
)";

}  // namespace

TEST_F(ReportReader, ReadsAJUnitReportWithItsShard) {
    const Report report = readReport("--durations", write(junit));
    EXPECT_EQ(report.format, ReportFormat::JUnit);
    EXPECT_TRUE(report.shard.known);
    EXPECT_EQ(report.shard.index, 1u);
    EXPECT_EQ(report.shard.count, 3u);
    ASSERT_EQ(report.suites.size(), 1u);
    EXPECT_EQ(report.suites[0].name, "arm");
    EXPECT_DOUBLE_EQ(report.suites[0].seconds, 1.25);
    ASSERT_EQ(report.tests.size(), 2u);
    EXPECT_EQ(report.tests[1].name, "grip");
    EXPECT_EQ(report.tests[1].state, "failed");
}

// As the runner writes it now: no status=, the states in the elements, the shard on each suite.
const char* const junitOfNow = R"(<?xml version="1.0" encoding="UTF-8"?>
<testsuites name="RobotTestingFramework" tests="8" failures="2" errors="4" time="1.5">
  <testsuite name="arm" tests="8" failures="2" errors="4" skipped="1" time="1.250" id="4">
    <properties>
      <property name="rtf.shard.index" value="1"/>
      <property name="rtf.shard.count" value="3"/>
      <property name="rtf.rerun" value="true"/>
    </properties>
    <testcase name="reach" classname="arm" time="0.5"/>
    <testcase name="grip" classname="arm" time="0.5"><failure type="failure"/></testcase>
    <testcase name="wait" classname="arm" time="0.5"><failure type="timeout"/></testcase>
    <testcase name="throw" classname="arm" time="0.5"><error type="error"/></testcase>
    <testcase name="segv" classname="arm" time="0.5"><error type="crash" message="SIGSEGV"/></testcase>
    <testcase name="stop" classname="arm" time="0.5"><error type="interrupted"/></testcase>
    <testcase name="skip" classname="arm" time="0.5"><skipped/></testcase>
    <testcase name="flake" classname="arm" time="0.5">
      <flakyFailure type="failed"><stackTrace>x</stackTrace></flakyFailure>
    </testcase>
    <testcase name="fixtures" classname="arm" time="0.000"><error type="fixture"/></testcase>
  </testsuite>
</testsuites>
)";

TEST_F(ReportReader, ReadsTheStatesFromTheElementsAndTheShardFromTheSuites) {
    const Report report = readReport("--durations", write(junitOfNow));
    EXPECT_TRUE(report.shard.known && report.shard.rerun);
    EXPECT_EQ(report.shard.index, 1u);
    EXPECT_EQ(report.shard.count, 3u);
    std::vector<std::string> states;
    for (const auto& test : report.tests) {
        states.push_back(test.name + ":" + test.state);
    }
    EXPECT_EQ(states, (std::vector<std::string>{"reach:passed", "grip:failed", "wait:timed out",
                                                "throw:error", "segv:crashed", "stop:interrupted",
                                                "skip:skipped", "flake:flaky"}));
}

TEST_F(ReportReader, AnEmptyShardSaysWhichItIsInASuiteOfNoPlace) {
    const Report report = readReport(
        "--merge", write("<testsuites name=\"RobotTestingFramework\" tests=\"0\">\n"
                         "<testsuite name=\"RobotTestingFramework\" tests=\"0\" failures=\"0\" "
                         "errors=\"0\" skipped=\"0\" time=\"0.000\"><properties>"
                         "<property name=\"rtf.shard.index\" value=\"3\"/>"
                         "<property name=\"rtf.shard.count\" value=\"4\"/></properties>"
                         "</testsuite></testsuites>\n"));
    EXPECT_TRUE(report.shard.known);
    EXPECT_EQ(report.shard.index, 3u);
    EXPECT_TRUE(report.suites.empty());
    EXPECT_TRUE(report.tests.empty());
}

TEST_F(ReportReader, ReadsTheNamespacedAndTheOldCtrfExtensionKey) {
    for (const char* key : {"robotology.rtf", "rtf"}) {
        const Report report = readReport(
            "--durations",
            write(std::string(
                      R"({"reportFormat":"CTRF","generatedBy":"robottestingframework-testrunner",
"results":{"tests":[
{"testId":"1.1","name":"reach","duration":300,"suite":["arm"],"extra":{")") +
                  key + R"(":{"state":"timed out"}},"status":"failed"}],
"extra":{")" + key +
                  R"(":{"suites":[{"place":1,"name":"arm","duration":2500}]}}}})"));
        ASSERT_EQ(report.tests.size(), 1u) << key;
        EXPECT_EQ(report.tests[0].state, "timed out") << key;
        ASSERT_EQ(report.suites.size(), 1u) << key;
        EXPECT_DOUBLE_EQ(report.suites[0].seconds, 2.5) << key;
        EXPECT_TRUE(report.json["results"]["tests"][0]["extra"].contains("robotology.rtf")) << key;
    }
}

TEST_F(ReportReader, ReadsAJsonReportWithItsSuitesTimes) {
    const Report report =
        readReport("--durations",
                   write(R"({"reportFormat":"CTRF","generatedBy":"robottestingframework-testrunner",
"results":{"tests":[
{"testId":"1.1","name":"reach","duration":300,"suite":["arm"],"extra":{"rtf":{"state":"passed"}},"status":"passed"}],
"extra":{"rtf":{"suites":[{"place":1,"name":"arm","duration":2500}],
"shard":{"index":0,"count":2},"rerun":true}}}})"));
    EXPECT_EQ(report.format, ReportFormat::Json);
    EXPECT_TRUE(report.shard.known && report.shard.rerun);
    EXPECT_EQ(report.shard.count, 2u);
    ASSERT_EQ(report.suites.size(), 1u);
    EXPECT_DOUBLE_EQ(report.suites[0].seconds, 2.5);
}

TEST_F(ReportReader, AJsonReportWithoutSuiteTimesAddsItsTests) {
    const Report report =
        readReport("--durations",
                   write(R"({"reportFormat":"CTRF","generatedBy":"robottestingframework-testrunner",
"results":{"tests":[
{"testId":"1.1","name":"a","duration":300,"suite":["arm"],"extra":{"rtf":{"state":"passed"}},"status":"passed"},
{"testId":"1.2","name":"b","duration":200,"suite":["arm"],"extra":{"rtf":{"state":"failed"}},"status":"failed"}]}})"));
    ASSERT_EQ(report.suites.size(), 1u);
    EXPECT_DOUBLE_EQ(report.suites[0].seconds, 0.5);
    EXPECT_FALSE(report.shard.known);
}

TEST_F(ReportReader, ErrorsNameTheFileAndLine) {
    std::string bad = junit;
    bad.replace(bad.find("status=\"failed\""), 15, "status=\"broken\"");
    const std::string error = errorOf(bad);
    EXPECT_NE(error.find("--durations " + (dir_ / "report").string() + ":9: expected <testcase>"),
              std::string::npos)
        << error;
}

TEST_F(ReportReader, RefusesWhatThisRunnerDoesNotWrite) {
    EXPECT_NE(errorOf("<testsuites name='other'/>").find("not a JUnit output of this runner"),
              std::string::npos);
    EXPECT_NE(errorOf("<testsuites name=\"RobotTestingFramework\">\n<testsuite name=\"a\" "
                      "tests=\"0\" time=\"x\" id=\"0\"/></testsuites>")
                  .find(":2: expected <testsuite> with a name, a time"),
              std::string::npos);
    EXPECT_NE(errorOf("{\n\n  \"reportFormat\": ").find(":3: not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf("TAP version 14\n").find("not a JUnit (XML) or JSON (CTRF)"),
              std::string::npos);
    std::string shardTooHigh = junit;
    shardTooHigh.replace(shardTooHigh.find("value=\"1\""), 9, "value=\"3\"");
    EXPECT_NE(errorOf(shardTooHigh).find("shard 3 of 3: expected an index below"),
              std::string::npos);
    std::string halfShard = junit;
    halfShard.erase(halfShard.find("    <property name=\"rtf.shard.count\""),
                    std::string("    <property name=\"rtf.shard.count\" value=\"3\"/>\n").size());
    EXPECT_NE(errorOf(halfShard).find(":3: expected both properties"), std::string::npos);
    EXPECT_NE(errorOf("{\"reportFormat\":\"CTRF\",\"generatedBy\":\"robottestingframework-"
                      "testrunner\",\"results\":{\"tests\":[{\"name\":\"a\"}]}}")
                  .find("results.tests[0]: expected a test with a name, a CTRF status, a testId"),
              std::string::npos);
}
