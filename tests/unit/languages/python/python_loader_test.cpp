// The Python backend driven directly: loadTest("python", ...) and a collector.
#include <gtest/gtest.h>

#include "language_test_helpers.h"

#ifdef RTF_HAVE_PYTHON

using namespace rtf_test;
using Kind = robottestingframework::ResultEvent::Kind;

namespace {

const char* kPassing = R"(import robottestingframework as rtf

class TestCase:
    def setup(self, param):
        rtf.setName("python passing")
        return True

    def run(self):
        rtf.testReport("hello from python")
        rtf.testCheck(1 + 1 == 2, "arithmetic works")
)";

}  // namespace

TEST(PythonLoader, PassingTestReportsChecksWithScriptLine) {
    std::string path = writeScript(scriptFolder(), "passing.py", kPassing);
    ScriptRun run = runScript("python", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Passed);
    EXPECT_EQ(run.name, "python passing");
    const ResultEvent* check = run.find(Kind::Check, "arithmetic works");
    ASSERT_NE(check, nullptr);
    EXPECT_TRUE(check->passed);
    EXPECT_EQ(check->message.getSourceFileName(), path);
    EXPECT_EQ(check->message.getSourceLineNumber(), 10u);
    EXPECT_NE(run.find(Kind::Report, "hello from python"), nullptr);
}

TEST(PythonLoader, FailedCheckNamesFileAndLineAndGoesOn) {
    std::string path = writeScript(scriptFolder(), "check.py", R"(import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(False, "wrong")
        robottestingframework.testReport("still running")
)");
    ScriptRun run = runScript("python", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "wrong");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLocation(), path + ":4");
    EXPECT_NE(run.find(Kind::Report, "still running"), nullptr);
}

TEST(PythonLoader, AssertFailStopsTheScript) {
    std::string path = writeScript(scriptFolder(), "fail.py", R"(import robottestingframework
class TestCase:
    def run(self):
        try:
            robottestingframework.assertFail("stop here")
        except Exception:
            robottestingframework.testReport("swallowed")
        robottestingframework.testReport("not reached")
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    const ResultEvent* failure = run.find(Kind::Failure, "stop here");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->message.getSourceLineNumber(), 5u);
    EXPECT_EQ(run.find(Kind::Report, "swallowed"), nullptr);
    EXPECT_EQ(run.find(Kind::Report, "not reached"), nullptr);
}

TEST(PythonLoader, AssertFailCaughtByTheScriptStillFails) {
    std::string path = writeScript(scriptFolder(), "caught.py", R"(import robottestingframework
class TestCase:
    def run(self):
        try:
            robottestingframework.assertFail("caught")
        except BaseException:
            pass
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Failed);
    EXPECT_NE(run.find(Kind::Failure, "caught"), nullptr);
}

TEST(PythonLoader, AssertErrorIsAnError) {
    std::string path = writeScript(scriptFolder(), "error.py", R"(import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.assertError("no robot")
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "no robot"), nullptr);
}

TEST(PythonLoader, ExceptionGivesTheTraceback) {
    std::string path = writeScript(scriptFolder(), "raises.py", R"(def helper():
    return 1 / 0

class TestCase:
    def run(self):
        helper()
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    const ResultEvent* error = run.find(Kind::Error, "ZeroDivisionError");
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->message.getMessage(), "ZeroDivisionError: division by zero");
    EXPECT_NE(error->message.getDetail().find("Traceback (most recent call last)"),
              std::string::npos);
    EXPECT_NE(error->message.getDetail().find("line 6, in run"), std::string::npos);
    EXPECT_NE(error->message.getDetail().find("line 2, in helper"), std::string::npos);
    EXPECT_EQ(error->message.getSourceLocation(), path + ":2");
}

TEST(PythonLoader, SyntaxErrorNamesFileLineColumnAndCode) {
    std::string path = writeScript(scriptFolder(), "syntax.py", R"(class TestCase:
    def run(self)
        pass
)");
    ScriptRun run = runScript("python", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find(path + ":2:18"), std::string::npos) << run.loadError;
    EXPECT_NE(run.loadError.find("def run(self)"), std::string::npos) << run.loadError;
    EXPECT_NE(run.loadError.find("^"), std::string::npos) << run.loadError;
    EXPECT_NE(run.loadError.find("SyntaxError: expected ':'"), std::string::npos) << run.loadError;
}

TEST(PythonLoader, ExceptionAtImportIsALoadErrorWithTraceback) {
    std::string path = writeScript(scriptFolder(), "import_error.py",
                                   "import no_such_module_here\nclass TestCase:\n    pass\n");
    ScriptRun run = runScript("python", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("line 1, in <module>"), std::string::npos) << run.loadError;
    EXPECT_NE(run.loadError.find("ModuleNotFoundError"), std::string::npos) << run.loadError;
}

TEST(PythonLoader, MissingTestCaseClassIsALoadError) {
    std::string path = writeScript(scriptFolder(), "empty.py", "x = 1\n");
    ScriptRun run = runScript("python", path);
    ASSERT_FALSE(run.loaded);
    EXPECT_NE(run.loadError.find("no class TestCase"), std::string::npos);
}

TEST(PythonLoader, SetupReturningFalseIsAnErrorAndSkipsRun) {
    std::string path = writeScript(scriptFolder(), "setup.py", R"(import robottestingframework
class TestCase:
    def setup(self, param):
        return False
    def run(self):
        robottestingframework.testReport("ran")
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "setup failed"), nullptr);
    EXPECT_EQ(run.find(Kind::Report, "ran"), nullptr);
}

TEST(PythonLoader, ParamAndEnvironmentReachTheScript) {
    std::string path = writeScript(scriptFolder(), "param.py", R"(import robottestingframework
class TestCase:
    def setup(self, param):
        robottestingframework.testReport("setup got " + param)
        return True
    def run(self):
        robottestingframework.testReport("param " + robottestingframework.getParam())
        robottestingframework.testReport("env " + robottestingframework.getEnvironment())
)");
    ScriptRun run = runScript("python", path, "--speed 3", "--robot sim");
    EXPECT_NE(run.find(Kind::Report, "setup got --speed 3"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "param --speed 3"), nullptr);
    EXPECT_NE(run.find(Kind::Report, "env --robot sim"), nullptr);
}

TEST(PythonLoader, RepetitionRunsRunSeveralTimesOnOneInstance) {
    std::string path = writeScript(scriptFolder(), "repeat.py", R"(import robottestingframework
class TestCase:
    def __init__(self):
        self.count = 0
    def run(self):
        self.count += 1
        robottestingframework.testReport("run %d" % self.count)
)");
    ScriptRun run = runScript("python", path, "", "", 3);
    EXPECT_NE(run.find(Kind::Report, "run 3"), nullptr);
    EXPECT_EQ(run.find(Kind::Report, "run 4"), nullptr);
}

TEST(PythonLoader, ImportsNeighbourModuleAndForgetsItAfterwards) {
    auto folder = scriptFolder();
    writeScript(folder, "neighbour.py", "VALUE = 42\n");
    std::string path = writeScript(folder, "uses.py", R"(import sys
import robottestingframework
import neighbour
class TestCase:
    def run(self):
        robottestingframework.testCheck(neighbour.VALUE == 42, "neighbour imported")
)");
    ScriptRun run = runScript("python", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    EXPECT_EQ(run.status, TestStatus::Passed);
    // A second script in the same process sees neither the neighbour nor the folder.
    std::string probe = writeScript(scriptFolder(), "probe.py", R"(import sys
import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck("neighbour" not in sys.modules, "neighbour dropped")
        robottestingframework.testCheck(
            not [m for m in sys.modules if m.startswith("_rtf_script_") and "uses" in m],
            "script module dropped")
)");
    ScriptRun second = runScript("python", probe);
    EXPECT_EQ(second.status, TestStatus::Passed);
}

TEST(PythonLoader, ScriptsLoadedTogetherKeepTheirOwnNeighbours) {
    // The runner may load every test before running the first.
    auto folder = scriptFolder();
    std::vector<std::string> paths;
    for (int value : {1, 2}) {
        auto sub = folder / std::to_string(value);
        std::filesystem::create_directories(sub);
        writeScript(sub, "helper.py", "VALUE = " + std::to_string(value) + "\n");
        paths.push_back(writeScript(sub, "check.py",
                                    R"(import robottestingframework
import helper
class TestCase:
    def run(self):
        import helper as again
        robottestingframework.testCheck(helper.VALUE == )" +
                                        std::to_string(value) +
                                        R"( and again is helper, "own helper")
)"));
    }
    std::string error;
    auto first = robottestingframework::languages::loadTest("python", paths[0], error);
    ASSERT_NE(first, nullptr) << error;
    auto second = robottestingframework::languages::loadTest("python", paths[1], error);
    ASSERT_NE(second, nullptr) << error;
    for (auto* test : {second->get(), first->get()}) {
        TestResultCollector collector;
        TestResult result;
        result.addListener(&collector);
        test->run(result);
        EXPECT_EQ(collector.passedCount(), 1u) << test->getName();
    }
}

TEST(PythonLoader, TwoScriptsDoNotShareGlobals) {
    auto folder = scriptFolder();
    const char* text = R"(import robottestingframework
counter = 0
class TestCase:
    def run(self):
        global counter
        counter += 1
        robottestingframework.testCheck(counter == 1, "fresh globals")
)";
    std::string first = writeScript(folder, "a.py", text);
    std::string second = writeScript(folder, "b.py", text);
    EXPECT_EQ(runScript("python", first).status, TestStatus::Passed);
    EXPECT_EQ(runScript("python", second).status, TestStatus::Passed);
    EXPECT_EQ(runScript("python", first).status, TestStatus::Passed);
}

// A thread a test starts carries that test (its id and name), stamped where threading starts it:
// through _thread's start function, wrapped before any test imports threading, and by a thread
// of a thread too.
TEST(PythonLoader, AThreadATestStartsCarriesTheTest) {
    std::string path = writeScript(scriptFolder(), "threads.py", R"(import threading
import robottestingframework

class TestCase:
    def run(self):
        seen = []
        def inner():
            seen.append(getattr(threading.current_thread(), "_rtf_test", None))
        def outer():
            seen.append(getattr(threading.current_thread(), "_rtf_test", None))
            thread = threading.Thread(target=inner)
            thread.start()
            thread.join()
        thread = threading.Thread(target=outer)
        thread.start()
        thread.join()
        robottestingframework.testCheck(len(seen) == 2 and seen[0] is not None, "stamped")
        robottestingframework.testCheck(seen[0] == seen[1], "its thread's thread too")
        robottestingframework.testCheck(str(seen[0][1]).endswith("threads.py"), str(seen))
)");
    ScriptRun run = runScript("python", path);
    ASSERT_TRUE(run.loaded) << run.loadError;
    const ResultEvent* failure = run.find(Kind::Failure);
    EXPECT_EQ(failure, nullptr) << failure->message.getMessage();
    EXPECT_EQ(run.status, TestStatus::Passed);
}

TEST(PythonLoader, ExceptionInTearDownIsAnError) {
    std::string path = writeScript(scriptFolder(), "teardown.py", R"(class TestCase:
    def run(self):
        pass
    def tearDown(self):
        raise RuntimeError("cleanup broke")
)");
    ScriptRun run = runScript("python", path);
    EXPECT_EQ(run.status, TestStatus::Error);
    EXPECT_NE(run.find(Kind::Error, "RuntimeError: cleanup broke"), nullptr);
}

TEST(PythonLoader, FixtureManagerSetsUpChecksAndTearsDown) {
    auto folder = scriptFolder();
    std::string log = (folder / "log.txt").string();
    std::string path = writeScript(folder, "fixture.py", R"(import robottestingframework
class FixtureManager:
    def setup(self, param):
        open(")" + log + R"(", "a").write("setup " + param + "\n")
        return True
    def check(self):
        return False
    def tearDown(self):
        open(")" + log + R"(", "a").write("tearDown\n")
)");
    std::string error;
    auto loaded = robottestingframework::languages::loadFixture("python", path, error);
    ASSERT_NE(loaded, nullptr) << error;
    FixtureManager* fixture = loaded->get();
    fixture->setParam("--world empty");
    EXPECT_TRUE(fixture->setup(0, nullptr));
    EXPECT_FALSE(fixture->check());
    fixture->tearDown();
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "setup --world empty\ntearDown\n");
}

#endif  // RTF_HAVE_PYTHON
