#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/TextOutputter.h>

#include "core_test_helpers.h"

using namespace rtf_test;

namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

struct TextRun {
    TestResultCollector collector;
    TextRun() {
        TestResult result;
        result.addListener(&collector);
        LambdaTest pass("pass", [] {
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("all good");
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "fine");
        });
        LambdaTest fail("fail", [] { ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("wrong"); });
        TestSuite suite("arm");
        suite.addTest(&pass);
        suite.addTest(&fail);
        result.startTestRunner();
        suite.run(result);
        result.endTestRunner();
    }
};

}  // namespace

TEST(TextOutputter, ListsSuitesTestsAndFailuresWithLocation) {
    TextRun run;
    const std::string text = TextOutputter(run.collector).text();
    EXPECT_TRUE(has(text, "Suite arm: FAILED"));
    EXPECT_TRUE(has(text, "  passed      pass  ("));
    EXPECT_TRUE(has(text, "  FAILED      fail  ("));
    EXPECT_TRUE(has(text, "failure: wrong [")) << text;
    EXPECT_TRUE(has(text, "text_outputter_test.cpp:"));
    EXPECT_FALSE(has(text, "all good"));
}

TEST(TextOutputter, VerboseAddsReportsAndChecks) {
    TextRun run;
    const std::string text = TextOutputter(run.collector, true).text();
    EXPECT_TRUE(has(text, "report: all good"));
    EXPECT_TRUE(has(text, "check ok: fine"));
}

TEST(TextOutputter, SummaryEndsWithTheClosingLine) {
    TextRun run;
    const std::string text = TextOutputter(run.collector).text(true);
    EXPECT_TRUE(has(text, "\n1 passed, 1 failed\n"));
    EXPECT_FALSE(has(TextOutputter(run.collector).text(false), "1 passed, 1 failed"));
}

TEST(TextOutputter, WriteWritesTheTextToTheFile) {
    TextRun run;
    const auto file = scratchDir() / "report.txt";
    TestMessage error;
    ASSERT_TRUE(TextOutputter(run.collector).write(file.string(), true, &error))
        << error.getMessage();
    std::ifstream in(file);
    std::stringstream content;
    content << in.rdbuf();
    EXPECT_EQ(content.str(), TextOutputter(run.collector).text(true));
}

TEST(TextOutputter, WriteFailureSaysWhichFileAndWhy) {
    TextRun run;
    const auto file = scratchDir() / "no" / "such" / "report.txt";
    TestMessage error;
    EXPECT_FALSE(TextOutputter(run.collector).write(file.string(), true, &error));
    EXPECT_TRUE(has(error.getMessage(), file.string()));
    EXPECT_TRUE(has(error.getMessage(), "No such file or directory"));
}
