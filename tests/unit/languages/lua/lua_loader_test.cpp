// The Lua backend driven directly: loadTest("lua", ...) and a collector.
#include <gtest/gtest.h>

#include "language_test_helpers.h"

#ifdef RTF_HAVE_LUA

using namespace rtf_test;
using Kind = robottestingframework::ResultEvent::Kind;

TEST(LuaLoader, PassingTestReportsChecksWithChunkLine) {
    std::string path = writeScript(scriptFolder(), "passing.lua", R"(TestCase = {}
function TestCase.setup(param)
    robottestingframework.setName("lua passing")
    return true
end
function TestCase.run()
    robottestingframework.testReport("hello from lua")
    robottestingframework.testCheck(1 + 1 == 2, "arithmetic works")
end
)");
    ScriptRun run = runScript("lua", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Passed);
    EXPECT_EQ(run.name, "lua passing");
    const ResultEvent* check = run.find(Kind::Check, "arithmetic works");
    ASSERT_NE(check, nullptr);
    EXPECT_EQ(check->message.getSourceLocation(), path + ":8");
}

TEST(LuaLoader, FailedCheckNamesChunkAndLine) {
    std::string path = writeScript(scriptFolder(), "check.lua", R"(TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(false, "wrong")
    robottestingframework.testReport("still running")
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "wrong");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLocation(), path + ":3");
    EXPECT_NE(run.find(Kind::Report, "still running"), nullptr);
}

TEST(LuaLoader, TestFailWithTheConditionAsTextAlwaysFailsAsInRtf2) {
    // RTF 2.0.1's testFail(condition, message) reads the condition as text and always marks
    // the test failed ("checking (x > 0): x is not positive"); the test goes on. A boolean
    // condition fails it when false.
    std::string path = writeScript(scriptFolder(), "test_fail.lua", R"(TestCase = {}
function TestCase.run()
    robottestingframework.testFail("x > 0", "x is not positive")
    robottestingframework.testFail(true, "a true condition")
    robottestingframework.testReport("still running")
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "x is not positive");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getDetail(), "checking (x > 0)");
    EXPECT_EQ(failure->message.getSourceLocation(), path + ":3");
    EXPECT_EQ(run.find(Kind::Failure, "a true condition"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "still running"), nullptr);
}

TEST(LuaLoader, AssertFailStopsTheScript) {
    std::string path = writeScript(scriptFolder(), "fail.lua", R"(TestCase = {}
function TestCase.run()
    robottestingframework.assertFail("stop here")
    robottestingframework.testReport("not reached")
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "stop here");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLineNumber(), 3u);
    EXPECT_EQ(run.find(Kind::Report, "not reached"), nullptr);
}

TEST(LuaLoader, AssertFailCaughtByPcallStillFails) {
    std::string path = writeScript(scriptFolder(), "pcall.lua", R"(TestCase = {}
function TestCase.run()
    pcall(robottestingframework.assertFail, "caught")
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "caught"), nullptr);
}

TEST(LuaLoader, AssertErrorIsAnError) {
    std::string path = writeScript(scriptFolder(), "error.lua", R"(TestCase = {}
function TestCase.run()
    robottestingframework.assertError("no robot")
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "no robot"), nullptr);
}

TEST(LuaLoader, RuntimeErrorGivesChunkLineAndTraceback) {
    std::string path = writeScript(scriptFolder(), "raises.lua", R"(local function helper()
    return nil + 1
end
TestCase = {}
function TestCase.run()
    helper()
end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    const ResultEvent* error = run.find(Kind::Error, "attempt to perform arithmetic");
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->message.getSourceLocation(), path + ":2");
    EXPECT_NE(error->message.getDetail().find("stack traceback:"), std::string::npos);
    EXPECT_NE(error->message.getDetail().find(":6: in "), std::string::npos)
        << error->message.getDetail();
}

TEST(LuaLoader, SyntaxErrorNamesChunkAndLine) {
    std::string path = writeScript(scriptFolder(), "syntax.lua", "TestCase = {}\nfunction (\n");
    ScriptRun run = runScript("lua", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("syntax.lua:2:"), std::string::npos) << run.loadError;
}

TEST(LuaLoader, SetupReturningFalseIsAnError) {
    std::string path = writeScript(scriptFolder(), "setup.lua", R"(TestCase = {}
function TestCase.setup(param) return false end
function TestCase.run() robottestingframework.testReport("ran") end
)");
    ScriptRun run = runScript("lua", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_EQ(run.find(Kind::Report, "ran"), nullptr);
}

TEST(LuaLoader, ParamEnvironmentAndRepetition) {
    std::string path = writeScript(scriptFolder(), "param.lua", R"(TestCase = {}
local count = 0
function TestCase.setup(param)
    robottestingframework.testReport("setup got " .. param)
    return true
end
function TestCase.run()
    count = count + 1
    robottestingframework.testReport("run " .. count .. " " ..
        robottestingframework.getParam() .. " / " .. robottestingframework.getEnvironment())
end
)");
    ScriptRun run = runScript("lua", path, "--speed 3", "--robot sim", 2);
    EXPECT_NE(run.find(Kind::Report, "setup got --speed 3"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "run 2 --speed 3 / --robot sim"), nullptr);
}

TEST(LuaLoader, TwoScriptsDoNotShareGlobals) {
    auto folder = scriptFolder();
    const char* text = R"(TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(shared == nil, "fresh globals")
    shared = true
end
)";
    std::string first = writeScript(folder, "a.lua", text);
    std::string second = writeScript(folder, "b.lua", text);
    EXPECT_EQ(runScript("lua", first).status, TestStatus::Passed);
    EXPECT_EQ(runScript("lua", second).status, TestStatus::Passed);
}

TEST(LuaLoader, MissingTestCaseTableIsALoadError) {
    std::string path = writeScript(scriptFolder(), "empty.lua", "x = 1\n");
    ScriptRun run = runScript("lua", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("TestCase"), std::string::npos);
}

#endif  // RTF_HAVE_LUA
