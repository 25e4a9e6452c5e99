#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core/text_safety.h"
#include "core_test_helpers.h"
#include "reporters/html_reporter.h"
#include "reporters/reporter_registry.h"
#include "reporters/summary.h"
#include "reporters/tap_reporter.h"

using namespace rtf_test;
using namespace robottestingframework::reporters;

namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(ReporterRegistry, OneRowPerFormatReadByNameWithTheListForMessages) {
    std::vector<std::string> names;
    TestResultCollector collector;
    for (const ReporterType& type : reporterTypes()) {
        names.push_back(type.name);
        EXPECT_EQ(findReporterType(type.name), &type);
        EXPECT_NE(type.make(collector, ReporterSettings{}), nullptr) << type.name;
        EXPECT_EQ(type.defaultFile.rfind("result.", 0), 0u) << type.defaultFile;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"text", "junit", "tap", "json", "html"}));
    EXPECT_EQ(reporterTypeList(), "text, junit, tap, json or html");
    EXPECT_EQ(findReporterType("xml"), nullptr);
}

TEST(StateTable, EachEventKindGivesOneState) {
    using Kind = ResultEvent::Kind;
    EXPECT_EQ(stateOf(Kind::Failure), TestStatus::Failed);
    EXPECT_EQ(stateOf(Kind::Error), TestStatus::Error);
    EXPECT_EQ(stateOf(Kind::Crash), TestStatus::Crashed);
    EXPECT_EQ(stateOf(Kind::Timeout), TestStatus::TimedOut);
    EXPECT_EQ(stateOf(Kind::Interrupted), TestStatus::Interrupted);
    EXPECT_EQ(stateOf(Kind::Skipped), TestStatus::Skipped);
    for (Kind kind : {Kind::Report, Kind::Check, Kind::Output, Kind::StartTest, Kind::EndTest}) {
        EXPECT_EQ(stateOf(kind), TestStatus::Passed) << toString(kind);
    }
}

TEST(TapReporter, EventsGoToTheTestTheyNameNotTheLastStarted) {
    TestResultCollector collector;
    TapReporter tap(collector, ReporterSettings{});
    TestResult result;  // the events reach the reporter as a run sends them: as records
    result.addListener(&tap);
    LambdaTest a("a");
    LambdaTest b("b");
    result.startTest(&a);
    result.startTest(&b);
    result.addFailure(&a, TestMessage("a went wrong"));
    result.endTest(&b);
    result.endTest(&a);
    const std::string text = tap.document();
    EXPECT_EQ(text.rfind("TAP version 14\n1..2\nok 1 - b\nnot ok 2 - a\n", 0), 0u) << text;
    EXPECT_TRUE(has(text, "message: \"a went wrong\"")) << text;
}

TEST(TapReporter, WhatIsStillOpenIsInterruptedAndEventsMayFollow) {
    TestResultCollector collector;
    TapReporter tap(collector, ReporterSettings{});
    TestSuite suite("s");
    LambdaTest a("a");
    tap.startTestSuite(&suite);
    tap.startTest(&a);
    const std::string cut = tap.document();
    EXPECT_TRUE(has(cut, "# Subtest: s\n    not ok 1 - a\n")) << cut;
    EXPECT_TRUE(has(cut, "severity: interrupted")) << cut;
    tap.endTest(&a);
    tap.endTestSuite(&suite);
    EXPECT_TRUE(has(tap.document(), "    ok 1 - a\n    1..1\nok 1 - s\n")) << tap.document();
}

TEST(TapReporter, SeveralRunsAtOnceInOneProcessStayApart) {
    auto run = [](const std::string& name, std::string& out) {
        TestResultCollector collector;
        TapReporter tap(collector, ReporterSettings{});
        TestResult result;
        result.addListener(&tap);
        std::vector<std::unique_ptr<LambdaTest>> tests;
        TestSuite suite(name);
        for (int i = 0; i < 50; ++i) {
            tests.push_back(std::make_unique<LambdaTest>(name + std::to_string(i), [i] {
                ROBOTTESTINGFRAMEWORK_TEST_CHECK(i % 2 == 0, "even");
            }));
            suite.addTest(tests.back().get());
        }
        result.startTestRunner();
        suite.run(result);
        result.endTestRunner();
        out = tap.document();
    };
    std::string first;
    std::string second;
    std::thread one(run, "left", std::ref(first));
    std::thread two(run, "right", std::ref(second));
    one.join();
    two.join();
    for (const std::string* text : {&first, &second}) {
        EXPECT_TRUE(has(*text, "    1..50\n")) << *text;
        EXPECT_EQ(text->find(text == &first ? "right" : "left"), std::string::npos) << *text;
    }
    EXPECT_TRUE(has(first, "    not ok 2 - left1\n"));
    EXPECT_TRUE(has(second, "    ok 1 - right0\n"));
}

TEST(TextSafety, InvalidUtf8IsReplacedAndJsonStaysInertInHtml) {
    EXPECT_EQ(validUtf8("a\xff"
                        "b\xc3"),
              "a\xEF\xBF\xBD"
              "b\xEF\xBF\xBD");
    EXPECT_EQ(validUtf8("caf\xC3\xA9"), "caf\xC3\xA9");
    EXPECT_EQ(jsonString("</script>\n\"\\\x01"), "\"\\u003c/script\\u003e\\n\\\"\\\\\\u0001\"");
}

TEST(TextSafety, PlainTextIsValidUtf8WithoutControlCharacters) {
    EXPECT_EQ(plainText(std::string("a\0b\xff\tc\x1b[31m\r\n", 13)), "ab\xEF\xBF\xBD\tc[31m\r\n");
}

TEST(TextSafety, VisibleTextShowsControlCharactersEscaped) {
    // A window title, a cleared screen, a carriage return that rewrites the line.
    EXPECT_EQ(visibleText("a\x1b]0;pwned\x07"
                          "b\x1b[2J\rc\nd\te\x7f"),
              "a\\e]0;pwned\\x07b\\e[2J\\rc\\nd\te\\x7f");
    EXPECT_EQ(visibleText("csi\xC2\x9B"
                          "2J \xC3\xA9 \xff"),
              "csi\\u009b2J \xC3\xA9 \xEF\xBF\xBD");
    EXPECT_EQ(visibleText("plain name"), "plain name");
}

TEST(TextSafety, VisibleTextKeepsLineBreaksUnderAContinuation) {
    EXPECT_EQ(visibleText("one\n  passed      fake\r", "        "),
              "one\n          passed      fake\\r");
}

TEST(Summary, ANameShownOnTheConsoleCannotFakeALine) {
    EXPECT_EQ(shownAs("t.py", "x\n  passed      y"), "t.py (x\\n  passed      y)");
    EXPECT_EQ(shownAs("\x1b[2Jt.py", ""), "\\e[2Jt.py");
}

TEST(TextSafety, OneMarkupEscapingForEachPlaceTextGoes) {
    const std::string text = "<a href=\"x\">it's & \x01\xff\ttab\nline\r";
    EXPECT_EQ(escapeMarkup(text, Markup::Text), "&lt;a href=\"x\"&gt;it's &amp; \ttab\nline&#13;");
    EXPECT_EQ(escapeMarkup(text, Markup::Quoted),
              "&lt;a href=&quot;x&quot;&gt;it&#39;s &amp; \ttab\nline&#13;");
    EXPECT_EQ(escapeMarkup(text, Markup::Attribute),
              "&lt;a href=&quot;x&quot;&gt;it's &amp; &#9;tab&#10;line&#13;");
    EXPECT_EQ(escapeMarkup("caf\xC3\xA9", Markup::Quoted), "caf\xC3\xA9");
}

TEST(TapReporter, KeepsEveryReportAndCheckWithItsTimeAndAFixturesAsComments) {
    TestResultCollector collector;
    TapReporter tap(collector, ReporterSettings{});
    TestResult result;
    result.addListener(&tap);
    TestSuite suite("s");
    LambdaTest a("a");
    result.startTestSuite(&suite);
    result.addReport(&suite, TestMessage("world is ready"));
    result.startTest(&a);
    result.addReport(&a, TestMessage("moved the arm"));
    result.addCheck(&a, TestMessage("joint in range"), true);
    result.endTest(&a);
    result.endTestSuite(&suite);
    const std::string text = tap.document();
    EXPECT_TRUE(has(text, "    # [")) << text;
    EXPECT_TRUE(has(text, " s] report: world is ready\n")) << text;
    EXPECT_TRUE(has(text, "    ok 1 - a\n      ---\n      messages:\n        - \"[")) << text;
    EXPECT_TRUE(has(text, " s] report: moved the arm\"\n")) << text;
    EXPECT_TRUE(has(text, " s] check ok: joint in range\"\n      ...\n")) << text;
}

TEST(TextReporter, KeepsReportsChecksAndOutputWithTheirTimeByDefault) {
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    LambdaTest pass("pass", [] {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("all good");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "fine");
    });
    TestSuite suite("arm");
    suite.addTest(&pass);
    result.startTestRunner();
    suite.run(result);
    result.endTestRunner();
    const std::string text = findReporterType("text")->make(collector, {})->document();
    EXPECT_TRUE(has(text, " s] report: all good")) << text;
    EXPECT_TRUE(has(text, " s] check ok: fine")) << text;
}

TEST(HtmlReporter, ASuitesFixtureTimesAreBeforeItsFirstTestAndAfterItsLast) {
    TestResultCollector collector;
    TestSuite suite("arm");
    LambdaTest a("a");
    a.setKey("a.py");
    collector.startTestSuite(&suite);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    collector.startTest(&a);
    collector.endTest(&a);
    std::this_thread::sleep_for(std::chrono::milliseconds(40));
    collector.endTestSuite(&suite);
    ReporterSettings settings;
    settings.testFacts["arm/a.py"] = {"python", "a.py", "--speed 30", {"slow", "arm"}};
    HtmlReporter html(collector, settings);
    const SuiteRecord& record = collector.suites().at(0);
    const std::string data = html.suiteData(record);
    const auto field = [&data](const std::string& name) {
        const std::size_t at = data.find("\"" + name + "\":");
        return at == std::string::npos ? -1.0 : std::stod(data.substr(at + name.size() + 3));
    };
    EXPECT_GE(field("setup"), 0.05) << data;
    EXPECT_GE(field("teardown"), 0.03) << data;
    EXPECT_LT(field("setup") + field("teardown"), record.duration + 1e-6) << data;
    const std::string test = html.testData(record.tests.at(0), record);
    EXPECT_TRUE(has(test,
                    "\"fullId\":\"arm/a.py\",\"type\":\"python\",\"param\":\"--speed 30\","
                    "\"tags\":[\"slow\",\"arm\"]"))
        << test;
}

// Issue 38's second trial: a failed check and the failure it makes were two lines of a test's
// details ("check failed: at target", "failure: at target"); the failure says it once.
TEST(HtmlReporter, AFailedCheckAndItsFailureAreOneLine) {
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    LambdaTest fail("fail", [] {
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(false, "at target");
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("gripper stuck");
    });
    TestSuite suite("arm");
    suite.addTest(&fail);
    result.startTestRunner();
    suite.run(result);
    result.endTestRunner();
    HtmlReporter html(collector, {});
    const SuiteRecord& record = collector.suites().at(0);
    const std::string test = html.testData(record.tests.at(0), record);
    const auto count = [&test](const std::string& part) {
        std::size_t n = 0;
        for (std::size_t at = test.find(part); at != std::string::npos;
             at = test.find(part, at + 1)) {
            ++n;
        }
        return n;
    };
    EXPECT_EQ(count("\"text\":\"at target"), 1u) << test;
    EXPECT_EQ(count("\"label\":\"check failed\""), 0u) << test;
    EXPECT_EQ(count("\"text\":\"gripper stuck"), 1u) << test;
}

// write() hands the document on to its file 64 KiB at a time (the runner never holds a whole
// report): every format's file is its document() byte for byte, pieces longer than a block
// (a test's big output) included, and a file that cannot be written leaves nothing behind.
TEST(Reporter, WritesTheSameTextAsItsDocumentABlockAtATime) {
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    std::vector<std::unique_ptr<Reporter>> reporters;
    for (const ReporterType& type : reporterTypes()) {
        reporters.push_back(type.make(collector, ReporterSettings{}));
        result.addListener(reporters.back().get());
    }
    std::vector<std::unique_ptr<LambdaTest>> tests;
    for (int i = 0; i < 1500; ++i) {
        tests.push_back(std::make_unique<LambdaTest>("test" + std::to_string(i), [] {
            ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "nothing to do");
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("tracking error", 0.012, "rad", 0, 0.05);
        }));
    }
    const std::string talk(200 * 1024, 'x');  // longer than a block, in one piece
    tests[700]->body = [&result, &talk, test = tests[700].get()] { result.addOutput(test, talk); };
    TestSuite suite("arm");
    for (const auto& test : tests) {
        suite.addTest(test.get());
    }
    result.startTestRunner();
    suite.run(result);
    result.endTestRunner();

    const std::filesystem::path dir = scratchDir();
    for (std::size_t i = 0; i < reporters.size(); ++i) {
        const std::string name = reporterTypes()[i].name;
        const std::string document = reporters[i]->document();
        EXPECT_GT(document.size(), 3 * 64 * 1024u) << name;
        const std::filesystem::path file = dir / ("report." + name);
        TestMessage error;
        ASSERT_TRUE(reporters[i]->write(file.string(), &error)) << error.toString();
        std::ifstream in(file, std::ios::binary);
        const std::string written((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
        EXPECT_EQ(written.size(), document.size()) << name;
        EXPECT_TRUE(written == document) << name;

        const std::filesystem::path nowhere = dir / "missing" / ("report." + name);
        EXPECT_FALSE(reporters[i]->write(nowhere.string(), &error)) << name;
        EXPECT_TRUE(has(error.getMessage(), "cannot write " + nowhere.string() + ": "))
            << error.getMessage();
    }
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        left.push_back(entry.path().filename().string());
    }
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"report.html", "report.json", "report.junit",
                                              "report.tap", "report.text"}));
}

// Issue 38, friction 9: a message's diagnostics are a block of lines under its one-line text
// (the console, the text and JUnit reports), never pasted into it.
TEST(Summary, DiagnosticsAreABlockUnderTheMessageLine) {
    robottestingframework::TestMessage message("not ok 2 - gripper closes", "", "g.sh", 4);
    message.setDiagnostics({{"found", "3"}, {"at", "file: g.c\nline: 12"}});
    EXPECT_EQ(robottestingframework::reporters::messageLine(message),
              "not ok 2 - gripper closes [g.sh:4]");
    EXPECT_EQ(robottestingframework::reporters::messageText(message),
              "not ok 2 - gripper closes [g.sh:4]\n  found: 3\n  at:\n    file: g.c\n    line: 12");
    EXPECT_EQ(robottestingframework::reporters::shownMessage(message, "    "),
              "not ok 2 - gripper closes [g.sh:4]\n      found: 3\n      at:\n        file: g.c\n"
              "        line: 12");
    robottestingframework::TestMessage plain("ok 1", "x > 0");
    EXPECT_EQ(robottestingframework::reporters::messageText(plain), "ok 1: x > 0");
}
