#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <robottestingframework/JUnitOutputter.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>

#include "build_paths.h"
#include "core_test_helpers.h"
#include "reporters/summary.h"

using namespace rtf_test;
namespace fs = std::filesystem;

namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// xmllint's verdict on `file` against the project's JUnit schema; its messages go to `log`.
bool validates(const fs::path& file) {
    const fs::path log = file.string() + ".xmllint.log";
    const std::string command = "xmllint --noout --schema '" +
                                std::string(build_paths::junitSchema()) + "' '" + file.string() +
                                "' > '" + log.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    if (status != 0) {
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        ADD_FAILURE() << "xmllint: " << text.str();
    }
    return status == 0;
}

// A run with every kind of outcome: passed, failed, error, crash, timeout, interrupted,
// skipped, and a suite whose fixture failed.
struct MixedRun {
    TestResultCollector collector;
    MixedRun() {
        TestResult result;
        result.addListener(&collector);
        LambdaTest pass("pass", [] { ROBOTTESTINGFRAMEWORK_TEST_REPORT("all good"); });
        LambdaTest fail("fail", [] {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(false, "first <problem>");
            ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("second & last");
        });
        LambdaTest error("error", [] { throw std::runtime_error("no robot"); });
        LambdaTest critical("critical", [] { ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL("fell"); });
        LambdaTest skipped("skipped");
        TestSuite first("first suite");
        for (Test* t : std::vector<Test*>{&pass, &fail, &error, &critical, &skipped}) {
            first.addTest(t);
        }
        std::vector<std::string> log;
        LoggingFixture broken("sim", log);
        broken.setupResult = false;
        LambdaTest never("never");
        TestSuite second("second suite");
        second.addFixtureManager(&broken);
        second.addTest(&never);
        TestRunner runner;
        runner.addTest(&first);
        runner.addTest(&second);
        runner.run(result);
        // What a worker process reports for tests that died or hung.
        TestSuite third("third suite");
        LambdaTest crashed("crashed"), hung("hung"), stopped("stopped");
        collector.startTestSuite(&third);
        collector.startTest(&crashed);
        collector.addOutput(&crashed, "last words\n");
        collector.addCrash(&crashed, TestMessage("killed by signal 11 (SIGSEGV)"));
        collector.endTest(&crashed);
        collector.startTest(&hung);
        collector.addTimeout(&hung, TestMessage("ran past 5 s"));
        collector.endTest(&hung);
        collector.startTest(&stopped);
        collector.addInterrupted(&stopped, TestMessage("Ctrl-C"));
        collector.endTest(&stopped);
        collector.endTestSuite(&third);
    }
};

}  // namespace

TEST(JUnitOutputter, MixedRunValidatesAgainstTheJUnitSchema) {
    MixedRun run;
    const fs::path file = scratchDir() / "results.xml";
    JUnitOutputter out(run.collector, true);
    TestMessage error;
    ASSERT_TRUE(out.write(file.string(), &error)) << error.getMessage();
    EXPECT_TRUE(validates(file));
}

TEST(JUnitOutputter, OneTestsuitePerSuiteAndOneTestcasePerTest) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml,
                    "<testsuite name=\"first suite\" tests=\"5\" failures=\"1\" errors=\"2\" "
                    "skipped=\"1\""));
    EXPECT_TRUE(has(xml, "<testcase name=\"pass\" classname=\"first suite\" time=\""));
    EXPECT_TRUE(has(xml, "hostname=\""));
    EXPECT_TRUE(has(xml, "timestamp=\""));
}

TEST(JUnitOutputter, FailureListsEveryMessageWithItsLocation) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml, "<failure message=\"first &lt;problem&gt;: false\" type=\"failure\">"));
    EXPECT_TRUE(has(xml, "failure: second &amp; last [")) << xml;
    EXPECT_TRUE(has(xml, "junit_outputter_test.cpp:"));
}

TEST(JUnitOutputter, ErrorTypesNameTheCause) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml, "type=\"error\""));
    // The signal is the one-line message; the details keep the whole reason.
    EXPECT_TRUE(has(xml, "<error message=\"SIGSEGV\" type=\"crash\">crash: killed by signal 11"))
        << xml;
    // A test that timed out failed (it did not finish what it checks).
    EXPECT_TRUE(has(xml, "<failure message=\"ran past 5 s\" type=\"timeout\">")) << xml;
    EXPECT_TRUE(has(xml, "<error message=\"Ctrl-C\" type=\"interrupted\">")) << xml;
    EXPECT_TRUE(has(xml, "<system-out>last words\n</system-out>"));
}

TEST(JUnitOutputter, WritesOnlyWhatTheStrictReadersAccept) {
    // Jenkins' xUnit plug-in (junit-10.xsd) refuses both; schemas/junit.xsd says why.
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_FALSE(has(xml, "status=")) << xml;
    // The totals as readers recount them: the fixtures' <testcase> is a test, a timeout a failure.
    EXPECT_TRUE(has(xml,
                    "<testsuites name=\"RobotTestingFramework\" tests=\"10\" failures=\"2\" "
                    "errors=\"5\" time=\""))
        << xml;
    const std::size_t root = xml.find("<testsuites");
    const std::size_t firstSuite = xml.find("<testsuite ");
    EXPECT_EQ(xml.substr(root, firstSuite - root).find("<properties>"), std::string::npos) << xml;
}

TEST(JUnitOutputter, SuitePropertiesNameTheStatesJUnitHasNoWordFor) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml,
                    "<testsuite name=\"third suite\" tests=\"3\" failures=\"1\" "
                    "errors=\"2\" skipped=\"0\""))
        << xml;
    // "rtf.state.S.T": the test's place (as CTRF's testId), unique in the document.
    EXPECT_TRUE(has(xml,
                    "<property name=\"rtf.state.3.1\" value=\"crashed\"/>\n"
                    "      <property name=\"rtf.state.3.2\" value=\"timed out\"/>\n"
                    "      <property name=\"rtf.state.3.3\" value=\"interrupted\"/>"))
        << xml;
}

TEST(JUnitOutputter, SkippedTestsCarryTheReason) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml,
                    "<skipped message=\"critical error in critical: fell\">critical error in "
                    "critical: fell</skipped>"))
        << xml;
}

TEST(JUnitOutputter, FixtureFailureIsAnErrorOfTheSuite) {
    MixedRun run;
    const std::string xml = JUnitOutputter(run.collector).xml();
    EXPECT_TRUE(has(xml, "<testcase name=\"fixtures\" classname=\"second suite\""));
    // Counted in tests= as in errors=, as readers recount the <testcase> elements.
    EXPECT_TRUE(has(xml,
                    "<testsuite name=\"second suite\" tests=\"2\" failures=\"0\" errors=\"1\" "
                    "skipped=\"1\""))
        << xml;
    EXPECT_TRUE(has(xml, "type=\"fixture\""));
    EXPECT_TRUE(has(xml, "<system-err>error: fixture sim failed: setup returned false\n"));
}

TEST(JUnitOutputter, DropsCharactersXmlForbidsAndKeepsValidUtf8) {
    TestResultCollector collector;
    LambdaTest t("t");
    collector.startTest(&t);
    collector.addFailure(&t, TestMessage(std::string("bell\x07 nul") + '\0' +
                                         "x esc\x1b ok\t\xC3\xA9 bad\xC3 \xFF\xED\xA0\x80 end"));
    collector.endTest(&t);
    const std::string xml = JUnitOutputter(collector).xml();
    EXPECT_TRUE(has(xml, "message=\"bell nulx esc ok&#9;\xC3\xA9 bad  end\"")) << xml;
    const fs::path file = scratchDir() / "escaped.xml";
    ASSERT_TRUE(JUnitOutputter(collector).write(file.string()));
    EXPECT_TRUE(validates(file));
}

TEST(JUnitOutputter, WriteFailureNamesTheFileAndLeavesNothingBehind) {
    MixedRun run;
    const fs::path dir = scratchDir();
    const fs::path target = dir / "missing" / "r.xml";
    TestMessage error;
    EXPECT_FALSE(JUnitOutputter(run.collector).write(target.string(), &error));
    EXPECT_TRUE(has(error.getMessage(), target.string()));
    EXPECT_TRUE(has(error.getMessage(), "No such file or directory"));
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(JUnitOutputter, WriteReplacesAnOldFileWhole) {
    MixedRun run;
    const fs::path file = scratchDir() / "r.xml";
    std::ofstream(file) << "old content";
    ASSERT_TRUE(JUnitOutputter(run.collector).write(file.string()));
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator()),
              1);
}

TEST(JUnitOutputter, FailedRenameRemovesTheTemporaryFile) {
    MixedRun run;
    const fs::path dir = scratchDir();
    const fs::path target = dir / "taken";
    fs::create_directories(target / "inside");  // a non-empty folder cannot be replaced
    TestMessage error;
    EXPECT_FALSE(JUnitOutputter(run.collector).write(target.string(), &error));
    EXPECT_TRUE(has(error.getMessage(), target.string()));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// Issue 38, friction 6: the summary said "2 failed" and the closing line "3 failed" (a fixture
// failure counted in one only). The summary says the closing line's number and its parts.
TEST(JUnitOutputter, TheSummaryCountsTheFailuresAsTheClosingLineDoes) {
    MixedRun run;
    const std::size_t failed = run.collector.failedCount() + run.collector.failedFixtureCount();
    ASSERT_GT(run.collector.failedFixtureCount(), 0u);
    const std::string closing = robottestingframework::reporters::closingLine(run.collector);
    EXPECT_TRUE(has(closing, std::to_string(failed) + " failed")) << closing;
    std::string summary;
    for (const std::string& line : robottestingframework::reporters::summaryLines(run.collector)) {
        summary += line + "\n";
    }
    EXPECT_TRUE(has(summary, "  failed: " + std::to_string(failed) + " (" +
                                 std::to_string(run.collector.failedCount()) +
                                 " tests, 1 fixture)"))
        << summary;
}

// Issue 38, friction 6 (through ctest: "1 interrupted" against "0 passed, 2 failed"): an
// interrupted test counts as failed, and the closing line says how many were interrupted.
TEST(JUnitOutputter, TheClosingLineSaysTheInterruptedTestsAmongTheFailed) {
    MixedRun run;
    ASSERT_EQ(run.collector.countOf(robottestingframework::TestStatus::Interrupted), 1u);
    const std::string closing = robottestingframework::reporters::closingLine(run.collector);
    const std::size_t failed = run.collector.failedCount() + run.collector.failedFixtureCount();
    EXPECT_TRUE(has(closing, std::to_string(failed) + " failed (1 interrupted)")) << closing;
}
