// RunView: what the live page is told, in what order, and that test text stays data.
#include <chrono>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_view.h"

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

}  // namespace

TEST(RunView, PlannedTestsAreNotRunUntilTheyStart) {
    RunView view(false);
    view.startRun();
    view.startSuite("arm", {"reach", "grasp"});
    view.startTest("reach");
    EXPECT_EQ(view.statusJson(), R"({"name":"arm","testStatus":[1,0]})");
    view.addMessage(false, "failure", TestMessage("missed", "by 2 cm", "reach.cpp", 12),
                    TestStatus::Failed);
    view.endTest();
    view.startTest("grasp");
    view.addMessage(false, "skipped", TestMessage("no gripper"), TestStatus::Skipped);
    view.endTest();
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

TEST(RunView, ARepeatedOrUnplannedTestGetsARowOfItsOwn) {
    RunView view(false);
    view.startSuite("s", {"t"});
    for (int i = 0; i < 2; ++i) {
        view.startTest("t");
        view.endTest();
    }
    view.startTest("extra");
    view.endTest();
    view.endSuite();
    EXPECT_EQ(view.statusJson(), R"({"name":"s","testStatus":[3,3,3]})");
}

TEST(RunView, ChangesAreNumberedAndReplayedAfterANumber) {
    RunView view(false);
    view.startRun();
    view.startSuite("s", {"t"});
    std::uint64_t last = 0;
    std::string all = changesAfter(view, 0, &last);
    EXPECT_EQ(all.rfind("id: 1\n", 0), 0u) << all;
    EXPECT_NE(all.find("id: " + std::to_string(last) + "\n"), std::string::npos);
    view.startTest("t");
    std::string more = changesAfter(view, last);
    EXPECT_EQ(more.rfind("id: " + std::to_string(last + 1) + "\n", 0), 0u) << more;
    EXPECT_NE(more.find(R"("state":"running")"), std::string::npos) << more;
    // A number beyond this run (a page left open on another run) gets everything again.
    EXPECT_EQ(changesAfter(view, 1000).rfind("id: 1\n", 0), 0u);
}

TEST(RunView, TestTextIsEscapedDataAndInvalidUtf8IsReplaced) {
    RunView view(true);
    view.startSuite("</script><img src=x onerror=alert(1)>", {});
    view.startTest("line\nbreak \"quoted\" \xff");
    view.addOutput("printed \xc3\x28\n");
    view.endTest();
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
    view.startSuite("s", {"chatty"});
    view.startTest("chatty");
    for (int i = 0; i < 1000; ++i) {
        view.addMessage(false, "report", TestMessage("step " + std::to_string(i)),
                        TestStatus::Passed);
    }
    std::uint64_t before = 0;
    changesAfter(view, 0, &before);
    view.addMessage(false, "failure", TestMessage("dropped the cup"), TestStatus::Failed);
    view.endTest();
    view.endSuite();
    auto chatty = nlohmann::json::parse(view.snapshotJson())["suites"][0]["tests"][0];
    EXPECT_EQ(chatty["messages"].size(), 201u);
    EXPECT_EQ(chatty["hiddenReports"], 800);
    EXPECT_EQ(chatty["messages"].back()["text"], "dropped the cup");
    EXPECT_EQ(chatty["state"], "failed");
    // Only the kept reports were changes of their own.
    EXPECT_LT(before, 220u);
}
