// A program that links the library and drives it itself, as RTF 2.x users do in their own
// main(): runner, suite, fixture, console, collector and a text report.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/TextOutputter.h>

#include "core_test_helpers.h"

namespace {

using namespace robottestingframework;

class EncoderTest : public TestCase {
public:
    EncoderTest() : TestCase("EncoderTest", "--joints 6") {}
    bool setup(int argc, char** argv) override {
        std::string value;
        if (!Arguments::getOption(argc, argv, "joints", value)) {
            return false;
        }
        joints_ = std::stoi(value);
        return true;
    }
    void run() override {
        for (int j = 0; j < joints_; ++j) {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(j < 5, Asserter::format("joint %d in range", j));
        }
    }

private:
    int joints_ = 0;
};

class CameraTest : public TestCase {
public:
    CameraTest() : TestCase("CameraTest") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_REPORT("image received"); }
};

class Simulator : public FixtureManager {
public:
    bool setup(int, char**) override {
        ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("simulator started");
        return true;
    }
};

}  // namespace

TEST(UserMain, RunnerSuiteConsoleCollectorAndTextReportWorkTogether) {
    const auto dir = rtf_test::scratchDir();
    const std::string consolePath = (dir / "console.txt").string();
    std::FILE* consoleFile = std::fopen(consolePath.c_str(), "w");
    ASSERT_NE(consoleFile, nullptr);

    EncoderTest encoders;
    CameraTest camera;
    Simulator simulator;
    simulator.setName("simulator");
    TestSuite suite("robot checks");
    suite.addFixtureManager(&simulator);
    suite.addTest(&encoders);
    suite.addTest(&camera);

    ConsoleListener console(true);
    console.setStream(consoleFile);
    TestResultCollector collector;
    TestResult result;
    result.addListener(&console);
    result.addListener(&collector);
    TestRunner runner;
    runner.addTest(&suite);
    runner.run(result);
    std::fclose(consoleFile);

    EXPECT_EQ(collector.testCount(), 2u);
    EXPECT_EQ(collector.passedCount(), 1u);
    EXPECT_EQ(collector.failedCount(), 1u);
    EXPECT_EQ(collector.failedSuiteCount(), 1u);
    EXPECT_FALSE(suite.succeeded());

    TextOutputter text(collector, true);
    const std::string reportPath = (dir / "report.txt").string();
    ASSERT_TRUE(text.write(reportPath, true));
    std::ifstream in(reportPath);
    std::stringstream report;
    report << in.rdbuf();
    EXPECT_NE(report.str().find("failure: joint 5 in range: j < 5"), std::string::npos)
        << report.str();
    EXPECT_NE(report.str().find("report: simulator started"), std::string::npos);

    std::ifstream consoleIn(consolePath);
    std::stringstream consoleText;
    consoleText << consoleIn.rdbuf();
    EXPECT_NE(consoleText.str().find("report: image received"), std::string::npos);
    EXPECT_NE(consoleText.str().find("1 passed, 1 failed\n"), std::string::npos);
}
