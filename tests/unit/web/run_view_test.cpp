// RunView: what the live page is told, in what order, and that test text stays data.
#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "web/run_view.h"

using robottestingframework::TestMessage;
using robottestingframework::TestStatus;
using robottestingframework::web::RunView;

namespace {

std::string changesAfter(const RunView& view, std::uint64_t since, std::uint64_t* last = nullptr) {
    std::string out;
    bool closed = false;
    std::uint64_t got = view.waitForChanges(since, std::chrono::milliseconds(0), out, closed);
    if (last != nullptr) {
        *last = got;
    }
    return out;
}

// The changes with each one's "now" (the clock as it was sent) left out.
std::string withoutClock(std::string changes) {
    for (std::size_t at = changes.find("\"now\":"); at != std::string::npos;
         at = changes.find("\"now\":", at)) {
        changes.erase(at, changes.find(',', at) + 1 - at);
    }
    return changes;
}

}  // namespace

TEST(RunView, PlannedTestsAreNotRunUntilTheyStart) {
    RunView view(false);
    view.startRun();
    view.startSuite("arm", {{1, "reach"}, {2, "grasp"}});
    view.startTest(1, "reach");
    EXPECT_EQ(view.statusJson(), R"({"name":"arm","testStatus":[1,0]})");
    view.addMessage(1, "failure", TestMessage("missed", "by 2 cm", "reach.cpp", 12),
                    TestStatus::Failed);
    view.endTest(1);
    view.startTest(2, "grasp");
    view.addMessage(2, "skipped", TestMessage("no gripper"), TestStatus::Skipped);
    view.endTest(2);
    view.endSuite();
    view.endRun();
    EXPECT_EQ(view.statusJson(), R"({"name":"arm","testStatus":[2,0]})");
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    EXPECT_EQ(snapshot["run"]["state"], "finished");
    EXPECT_EQ(snapshot["run"]["failed"], 1);
    EXPECT_EQ(snapshot["run"]["skipped"], 1);
    EXPECT_EQ(snapshot["suites"][0]["state"], "failed");
    const auto& reach = snapshot["suites"][0]["tests"][0];
    EXPECT_EQ(reach["state"], "failed");
    EXPECT_EQ(reach["messages"][0]["text"], "missed: by 2 cm");
    EXPECT_EQ(reach["messages"][0]["where"], "reach.cpp:12");
}

// Issue 38, friction 9: a message's diagnostics (a TAP point's YAML keys) reach the page apart
// from its text, which the page shows as a block under the line.
TEST(RunView, AMessagesDiagnosticsAreApartFromItsText) {
    RunView view(false);
    view.startRun();
    view.startSuite("arm", {{1, "grip"}});
    view.startTest(1, "grip");
    TestMessage message("not ok 1 - gripper closes", "", "grip.sh", 3);
    message.setDiagnostics({{"found", "3"}, {"wanted", "4"}});
    view.addMessage(1, "failure", message, TestStatus::Failed);
    view.addMessage(1, "report", TestMessage("plain"), TestStatus::Passed);
    view.endTest(1);
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    const auto& messages = snapshot["suites"][0]["tests"][0]["messages"];
    EXPECT_EQ(messages[0]["text"], "not ok 1 - gripper closes");
    EXPECT_EQ(messages[0]["diagnostics"], "found: 3\nwanted: 4\n");
    EXPECT_FALSE(messages[1].contains("diagnostics"));
}

TEST(RunView, ARepeatedOrUnplannedTestGetsARowOfItsOwn) {
    RunView view(false);
    view.startSuite("s", {{1, "t"}});
    for (int i = 0; i < 2; ++i) {
        view.startTest(1, "t");
        view.endTest(1);
    }
    view.startTest(2, "extra");
    view.endTest(2);
    view.endSuite();
    EXPECT_EQ(view.statusJson(), R"({"name":"s","testStatus":[3,3,3]})");
}

TEST(RunView, ChangesAreNumberedAndReplayedAfterANumber) {
    RunView view(false);
    view.startRun();
    view.startSuite("s", {{1, "t"}});
    std::uint64_t last = 0;
    std::string all = changesAfter(view, 0, &last);
    EXPECT_EQ(all.rfind("id: ", 0), 0u) << all;
    EXPECT_NE(all.find("id: " + std::to_string(last) + "\n"), std::string::npos);
    view.startTest(1, "t");
    std::string more = changesAfter(view, last);
    EXPECT_EQ(more.rfind("id: " + std::to_string(last + 1) + "\n", 0), 0u) << more;
    EXPECT_NE(more.find(R"("state":"running")"), std::string::npos) << more;
    // A number beyond this run (a page left open on another run) gets everything again, each
    // change with the clock as it is sent ("now"), which alone differs.
    EXPECT_EQ(withoutClock(changesAfter(view, 1000)), withoutClock(changesAfter(view, 0)));
}

TEST(RunView, AChangeReplacedByALaterOneOfTheSameThingIsNotKept) {
    // Each change of a test carries its whole state: an older one is not kept nor sent again.
    // A test failing a check 4 000 times made the runner hold 3 GB (each change re-sent every
    // message) and take 3 minutes.
    RunView view(false);
    view.startRun();
    view.startSuite("s", {{1, "t"}, {2, "u"}});
    view.startTest(1, "t");
    for (int i = 0; i < 5000; ++i) {
        view.addMessage(1, "failure", TestMessage("check " + std::to_string(i) + " failed"),
                        TestStatus::Failed);
    }
    std::uint64_t last = 0;
    const std::string all = changesAfter(view, 0, &last);
    EXPECT_GE(last, 200u);  // a change for each kept message
    std::size_t tests = 0;
    for (std::size_t at = all.find(R"("type":"test")"); at != std::string::npos;
         at = all.find(R"("type":"test")", at + 1)) {
        ++tests;
    }
    EXPECT_EQ(tests, 1u) << "one change per test, its latest";
    EXPECT_LT(all.size(), 64u * 1024) << "200 messages at most";
    auto t = nlohmann::json::parse(view.snapshotJson())["suites"][0]["tests"][0];
    EXPECT_EQ(t["messages"].size(), 200u);
    EXPECT_EQ(t["messages"][0]["text"], "check 0 failed");
    EXPECT_EQ(t["hiddenReports"], 4800);
    // A long message keeps its first 4 KiB on the page.
    view.startTest(2, "u");
    view.addMessage(2, "failure", TestMessage(std::string(1 << 20, 'x')), TestStatus::Failed);
    auto u = nlohmann::json::parse(view.snapshotJson())["suites"][0]["tests"][1];
    EXPECT_LT(u["messages"][0]["text"].get<std::string>().size(), 4200u);
    EXPECT_LT(view.logText().size(), 3u * 1024 * 1024);
}

TEST(RunView, TestTextIsEscapedDataAndInvalidUtf8IsReplaced) {
    RunView view(true);
    view.startSuite("</script><img src=x onerror=alert(1)>", {});
    view.startTest(1, "line\nbreak \"quoted\" \xff");
    view.addOutput(1, "printed \xc3\x28\n");
    view.endTest(1);
    view.endSuite();
    std::string stream = changesAfter(view, 0);
    // One line per event: a newline in a name cannot end the event early.
    for (std::size_t at = stream.find("data: "); at != std::string::npos;
         at = stream.find("data: ", at + 1)) {
        std::size_t end = stream.find('\n', at);
        EXPECT_NO_THROW(nlohmann::json::parse(stream.substr(at + 6, end - at - 6)));
    }
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    EXPECT_EQ(snapshot["suites"][0]["name"], "</script><img src=x onerror=alert(1)>");
    EXPECT_EQ(snapshot["suites"][0]["tests"][0]["name"], "line\nbreak \"quoted\" \xef\xbf\xbd");
    EXPECT_EQ(view.logText().find('<'), std::string::npos) << view.logText();
    EXPECT_NE(view.logText().find("&lt;/script&gt;"), std::string::npos);
    // Escaped as the reports are: what XML cannot hold is not served either.
    EXPECT_EQ(view.logText().find('\xff'), std::string::npos) << view.logText();
    EXPECT_NE(view.logText().find("&quot;quoted&quot;"), std::string::npos) << view.logText();
}

TEST(RunView, CloseEndsAWaitingReader) {
    RunView view(false);
    view.close();
    std::string out;
    bool closed = false;
    auto start = std::chrono::steady_clock::now();
    view.waitForChanges(0, std::chrono::seconds(30), out, closed);
    EXPECT_TRUE(closed);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(RunView, ReportsBeyondTheCapAreCountedButFailuresAlwaysKept) {
    RunView view(false);
    view.startSuite("s", {{1, "chatty"}});
    view.startTest(1, "chatty");
    for (int i = 0; i < 1000; ++i) {
        view.addMessage(1, "report", TestMessage("step " + std::to_string(i)), TestStatus::Passed);
    }
    std::uint64_t before = 0;
    changesAfter(view, 0, &before);
    view.addMessage(1, "failure", TestMessage("dropped the cup"), TestStatus::Failed);
    view.endTest(1);
    view.endSuite();
    auto chatty = nlohmann::json::parse(view.snapshotJson())["suites"][0]["tests"][0];
    EXPECT_EQ(chatty["messages"].size(), 201u);
    EXPECT_EQ(chatty["hiddenReports"], 800);
    EXPECT_EQ(chatty["messages"].back()["text"], "dropped the cup");
    EXPECT_EQ(chatty["state"], "failed");
    // Only the kept reports were changes of their own.
    EXPECT_LT(before, 220u);
}

TEST(RunView, TwoTestsOfOneNameAreToldApartByIdAndARenameIsFollowed) {
    RunView view(true);
    view.startSuite("s", {{7, "twin"}, {8, "twin"}});
    // The second one runs first: the rows follow the ids, not the names or the order.
    view.startTest(8, "twin");
    view.addMessage(8, "failure", TestMessage("second broke"), TestStatus::Failed);
    view.renameTest(8, "renamed");
    view.addOutput(8, "said by the second\n");
    view.endTest(8);
    view.startTest(7, "twin");
    view.addMessage(99, "report", TestMessage("a fixture"), TestStatus::Passed);
    view.endTest(7);
    view.endSuite();
    EXPECT_EQ(view.statusJson(), R"({"name":"s","testStatus":[3,2]})");
    auto tests = nlohmann::json::parse(view.snapshotJson())["suites"][0]["tests"];
    ASSERT_EQ(tests.size(), 2u);
    EXPECT_EQ(tests[0]["id"], 7);
    EXPECT_EQ(tests[0]["name"], "twin");
    EXPECT_EQ(tests[0]["messages"].size(), 0u);
    EXPECT_EQ(tests[1]["id"], 8);
    EXPECT_EQ(tests[1]["name"], "renamed");
    EXPECT_EQ(tests[1]["state"], "failed");
    EXPECT_EQ(tests[1]["messages"][0]["text"], "second broke");
    EXPECT_EQ(tests[1]["output"], "said by the second\n");
    auto suite = nlohmann::json::parse(view.snapshotJson())["suites"][0];
    EXPECT_EQ(suite["messages"][0]["text"], "a fixture");
}

TEST(RunView, RunningTestsAndSuitesSayWhenTheyStartedOnTheClockEveryChangeCarries) {
    RunView view(false);
    view.startRun();
    view.startSuite("arm", {{1, "reach"}});
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    view.startTest(1, "reach");
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    const double suiteStarted = snapshot["suites"][0]["startedAt"];
    const double testStarted = snapshot["suites"][0]["tests"][0]["startedAt"];
    EXPECT_GE(testStarted, suiteStarted + 0.015);
    EXPECT_GE(snapshot["now"].get<double>(), testStarted);
    // Each change says the clock as it is sent, after the thing it is about started.
    const std::string stream = changesAfter(view, 0);
    const std::size_t data = stream.rfind("data: ");
    ASSERT_NE(data, std::string::npos) << stream;
    auto change =
        nlohmann::json::parse(stream.substr(data + 6, stream.find('\n', data) - data - 6));
    EXPECT_EQ(change["type"], "test");
    EXPECT_GE(change["now"].get<double>(), change["test"]["startedAt"].get<double>());
}

TEST(RunView, ATestsHistoryIsShownWithItByItsId) {
    RunView view(false);
    view.setTestHistory("arm/reach", R"({"states":["passed","failed"],"durations":[1,2],)"
                                     R"("flakyRate":0.5})");
    view.startRun();
    view.startSuite("arm", {{1, "reach"}, {2, "grasp"}});
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    const auto& tests = snapshot["suites"][0]["tests"];
    EXPECT_EQ(tests[0]["history"]["states"][1], "failed");
    EXPECT_EQ(tests[0]["history"]["flakyRate"], 0.5);
    EXPECT_FALSE(tests[1].contains("history"));
}

// Issue 38, friction 5: with -j 2 the page showed one suite of two and "of 5" of 6 tests.
// The plan puts every suite and test on the page before anything starts, and suites side by
// side (their events interleaved) each keep their own tests, messages and end.
TEST(RunView, ThePlanShowsEverySuiteAndTestFromTheStart) {
    RunView view(false);
    view.setPlan({{"arm", {{1, "reach"}, {2, "grasp"}}}, {"base", {{3, "drive"}}}});
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    ASSERT_EQ(snapshot["suites"].size(), 2u);
    EXPECT_EQ(snapshot["run"]["tests"], 3);
    EXPECT_EQ(snapshot["suites"][0]["state"], "waiting");
    EXPECT_EQ(snapshot["suites"][1]["state"], "waiting");
    EXPECT_EQ(snapshot["suites"][1]["tests"][0]["state"], "not run");

    view.startRun();
    view.startSuite("arm", {{1, "reach"}, {2, "grasp"}}, 10);
    view.startSuite("base", {{3, "drive"}}, 11);
    view.startTest(1, "reach");
    view.startTest(3, "drive");
    view.addMessage(11, "error", TestMessage("base fixture lost"), TestStatus::Error);
    view.addMessage(3, "failure", TestMessage("stuck"), TestStatus::Failed);
    view.endTest(3);
    view.endTest(1);
    view.startTest(2, "grasp");  // arm's, though base started later
    view.endTest(2);
    view.endSuite("arm");  // before base, which started later
    view.endSuite("base");
    view.endRun();
    snapshot = nlohmann::json::parse(view.snapshotJson());
    ASSERT_EQ(snapshot["suites"].size(), 2u);
    const auto& arm = snapshot["suites"][0];
    const auto& base = snapshot["suites"][1];
    EXPECT_EQ(arm["state"], "passed");
    EXPECT_EQ(arm["tests"][0]["state"], "passed");
    EXPECT_EQ(arm["tests"][1]["state"], "passed");
    EXPECT_EQ(base["tests"].size(), 1u);
    EXPECT_EQ(base["state"], "failed");
    EXPECT_EQ(base["tests"][0]["state"], "failed");
    ASSERT_EQ(base["messages"].size(), 1u);
    EXPECT_EQ(base["messages"][0]["text"], "base fixture lost");
    EXPECT_EQ(arm["messages"].size(), 0u);
}

TEST(RunView, ASuiteThePlanDidNotNameIsAddedAsItStarts) {
    RunView view(false);
    view.setPlan({{"arm", {{1, "reach"}}}});
    view.startRun();
    view.startSuite("extra", {{5, "other"}});
    view.startTest(5, "other");
    view.endTest(5);
    view.endSuite("extra");
    view.endRun();
    const auto snapshot = nlohmann::json::parse(view.snapshotJson());
    ASSERT_EQ(snapshot["suites"].size(), 2u);
    EXPECT_EQ(snapshot["suites"][0]["state"], "waiting");
    EXPECT_EQ(snapshot["suites"][1]["name"], "extra");
    EXPECT_EQ(snapshot["suites"][1]["tests"][0]["state"], "passed");
    EXPECT_EQ(snapshot["run"]["tests"], 2);
}

// Issue 38's second trial: a failed check and the failure it makes, with the same words, were
// two lines of the page ("check failed: ..." then "failure: ..."); they are one, the failure.
// A failure with other words stays a line of its own.
TEST(RunView, AFailedCheckAndItsFailureAreOneLine) {
    RunView view(false);
    view.startRun();
    view.startSuite("arm", {{1, "reach"}});
    view.startTest(1, "reach");
    view.addMessage(1, "check failed", TestMessage("at target", "", "reach.cpp", 12),
                    TestStatus::Passed);
    view.addMessage(1, "failure", TestMessage("at target", "", "reach.cpp", 12),
                    TestStatus::Failed);
    view.addMessage(1, "check failed", TestMessage("gripper open", "", "reach.cpp", 13),
                    TestStatus::Passed);
    view.addMessage(1, "failure", TestMessage("gripper stuck", "", "reach.cpp", 14),
                    TestStatus::Failed);
    view.endTest(1);
    view.endSuite();
    view.endRun();
    auto snapshot = nlohmann::json::parse(view.snapshotJson());
    const auto& reach = snapshot["suites"][0]["tests"][0];
    EXPECT_EQ(reach["state"], "failed");
    ASSERT_EQ(reach["messages"].size(), 3u) << reach.dump();
    EXPECT_EQ(reach["messages"][0]["kind"], "failure");
    EXPECT_EQ(reach["messages"][0]["text"], "at target");
    EXPECT_EQ(reach["messages"][1]["kind"], "check failed");
    EXPECT_EQ(reach["messages"][2]["text"], "gripper stuck");
}
