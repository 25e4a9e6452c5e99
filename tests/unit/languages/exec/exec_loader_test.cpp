// The exec backend driven directly: programs with and without TAP.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "language_test_helpers.h"

using namespace rtf_test;
using Kind = robottestingframework::ResultEvent::Kind;

namespace {

ScriptRun runShell(const std::string& body, const std::string& param = "",
                   const std::string& environment = "") {
    std::string path = writeScript(scriptFolder(), "test.sh", "#!/bin/sh\n" + body, true);
    return runScript("exec", path, param, environment);
}

}  // namespace

TEST(ExecLoader, ExitZeroPasses) {
    ScriptRun run = runShell("echo working\nexit 0\n");
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Passed);
    EXPECT_NE(run.find(Kind::Output, "working"), nullptr);
}

TEST(ExecLoader, ExitStatus77Skips) {
    ScriptRun run = runShell("echo 'no robot here' >&2\nexit 77\n");
    EXPECT_EQ(run.status, TestStatus::Skipped);
    const ResultEvent* skipped = run.find(Kind::Skipped);
    ASSERT_NE(skipped, nullptr);
    EXPECT_EQ(skipped->message.getDetail(), "no robot here");
}

TEST(ExecLoader, OtherExitStatusFailsWithStderr) {
    ScriptRun run = runShell("echo 'motor 3 stalled' >&2\nexit 3\n");
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "exited with status 3"), nullptr);
    EXPECT_NE(run.find(Kind::Output, "motor 3 stalled"), nullptr);
}

TEST(ExecLoader, DeathBySignalIsACrash) {
    ScriptRun run = runShell("kill -SEGV $$\n");
    EXPECT_EQ(run.status, TestStatus::Crashed);
    EXPECT_NE(run.find(Kind::Crash, "killed by SIGSEGV"), nullptr);
}

TEST(ExecLoader, ParamIsArgvAndEnvironmentIsAVariable) {
    ScriptRun run = runShell(
        "echo \"args=$# [$1] [$2]\"\necho \"env=$RTF_ENVIRONMENT name=$(basename "
        "$RTF_TEST_NAME)\"\n",
        "--part 'left arm'", "--robot sim");
    EXPECT_NE(run.find(Kind::Output, "args=2 [--part] [left arm]"), nullptr);
    EXPECT_NE(run.find(Kind::Output, "env=--robot sim name=test.sh"), nullptr);
}

TEST(ExecLoader, TapPointsBecomeChecks) {
    ScriptRun run = runShell(
        "echo 'TAP version 13'\necho '1..3'\necho 'ok 1 - first'\n"
        "echo 'not ok 2 - second'\necho '  ---'\necho '  got: 4'\necho '  ...'\n"
        "echo 'not ok 3 - later # TODO not yet'\necho '# a comment'\nexit 1\n");
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_EQ(run.count(Kind::Check), 2u);
    const ResultEvent* first = run.find(Kind::Check, "ok 1 - first");
    ASSERT_NE(first, nullptr);
    EXPECT_TRUE(first->passed);
    const ResultEvent* failure = run.find(Kind::Failure, "not ok 2 - second");
    ASSERT_NE(failure, nullptr);
    // Its YAML block is diagnostics, not text after the point's (issue 38, friction 9).
    EXPECT_EQ(failure->message.getDetail(), "");
    EXPECT_EQ(failure->message.getDiagnostics(),
              (robottestingframework::TestMessage::Diagnostics{{"got", "4"}}));
    EXPECT_EQ(failure->message.getSourceLineNumber(), 4u);
    EXPECT_NE(run.find(Kind::Report, "not ok 3 - later # TODO not yet"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "# a comment"), nullptr);
    EXPECT_EQ(run.count(Kind::Failure), 1u);  // the exit status adds nothing
}

TEST(ExecLoader, FailingTodoDoesNotFail) {
    ScriptRun run = runShell("echo '1..2'\necho 'ok 1'\necho 'not ok 2 # TODO later'\n");
    EXPECT_EQ(run.status, TestStatus::Passed);
}

TEST(ExecLoader, TapPlanMismatchFails) {
    ScriptRun run = runShell("echo '1..3'\necho 'ok 1'\necho 'ok 2'\n");
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "planned 3 test(s) but ran 2"), nullptr);
}

TEST(ExecLoader, TapBailOutIsAnError) {
    ScriptRun run = runShell("echo '1..2'\necho 'ok 1'\necho 'Bail out! robot gone'\n");
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "Bail out! robot gone"), nullptr);
}

TEST(ExecLoader, TapSkipAllSkips) {
    ScriptRun run = runShell("echo '1..0 # SKIP no camera'\n");
    EXPECT_EQ(run.status, TestStatus::Skipped);
    EXPECT_NE(run.find(Kind::Skipped, "no camera"), nullptr);
}

TEST(ExecLoader, AllTapPassingButNonZeroExitFails) {
    ScriptRun run = runShell("echo '1..1'\necho 'ok 1'\nexit 2\n");
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "exited with status 2"), nullptr);
}

TEST(ExecLoader, NotExecutableIsALoadError) {
    std::string path = writeScript(scriptFolder(), "plain.txt", "hello\n");
    ScriptRun run = runScript("exec", path);
    EXPECT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("not an executable"), std::string::npos);
}

TEST(ExecLoader, ProgramsOutlivingBackgroundChildrenDoNotHang) {
    // The background sleep keeps the pipes open; the test ends with the program, not with it.
    ScriptRun run = runShell("sleep 3 &\necho done\nexit 0\n");
    EXPECT_EQ(run.status, TestStatus::Passed);
}

TEST(ExecLoader, InterruptTerminatesTheProgram) {
    std::string path = writeScript(scriptFolder(), "hang.sh", "#!/bin/sh\nexec sleep 30\n", true);
    std::string error;
    auto loaded = robottestingframework::languages::loadTest("exec", path, error);
    ASSERT_NE(loaded, nullptr) << error;
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    auto start = std::chrono::steady_clock::now();
    std::thread stopper([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        loaded->get()->interrupt();
    });
    loaded->get()->run(result);
    stopper.join();
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    ASSERT_FALSE(collector.suites().empty());
    EXPECT_EQ(collector.suites().back().tests.back().status, TestStatus::Interrupted);
}
