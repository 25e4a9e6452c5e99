// The RTF 2.x script loaders (PythonPluginLoader, LuaPluginLoader, RubyPluginLoader): the test
// case they give runs with the caller's runner and result, and bad files give a clear error.
#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>

#include <robottestingframework/PluginLoader.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>

#include "language_test_helpers.h"

#ifdef RTF_HAVE_PYTHON
#include <robottestingframework/python/PythonPluginLoader.h>
#endif
#ifdef RTF_HAVE_LUA
#include <robottestingframework/lua/LuaPluginLoader.h>
#endif
#ifdef RTF_HAVE_RUBY
#include <robottestingframework/ruby/RubyPluginLoader.h>
#endif

using namespace rtf_test;
using robottestingframework::plugin::PluginLoader;

namespace {

// One language's loader and its scripts, written as RTF 2.x's documentation writes them.
struct Language {
    std::string extension;
    std::function<std::unique_ptr<PluginLoader>()> make;
    std::string passing;         // reports "param=<param> env=<env>", checks true
    std::string syntaxError;     // broken
    int syntaxLine;              // where the language says it is broken
    std::string otherExtension;  // a file of another language
};

// Names the parameter in test names and messages.
void PrintTo(const Language& language, std::ostream* out) {
    *out << language.extension;
}

// Runs `test` with a TestRunner of our own, `times` times, and returns what the collector saw.
struct Outcome {
    std::size_t tests = 0;
    std::size_t passed = 0;
    std::vector<std::string> reports;
};

Outcome runWithOwnRunner(TestCase* test, int times) {
    Outcome outcome;
    TestResultCollector collector;
    TestResult result;
    result.addListener(&collector);
    TestRunner runner;
    runner.addTest(test);
    for (int i = 0; i < times; ++i) {
        runner.run(result);
    }
    outcome.tests = collector.testCount();
    outcome.passed = collector.passedCount();
    for (const ResultEvent& event : collector.getResults()) {
        if (event.kind == ResultEvent::Kind::Report) {
            outcome.reports.push_back(event.message.getMessage());
        }
    }
    return outcome;
}

bool has(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& line : lines) {
        if (line.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

class ScriptPluginLoader : public ::testing::TestWithParam<Language> {};

TEST_P(ScriptPluginLoader, TestRunsWithTheCallersRunnerAndResultSeveralTimes) {
    const Language& language = GetParam();
    std::string path =
        writeScript(scriptFolder(), "rtf2_test" + language.extension, language.passing);
    std::unique_ptr<PluginLoader> loader = language.make();
    TestCase* test = loader->open(path);
    ASSERT_NE(test, nullptr) << loader->getLastError();
    EXPECT_EQ(loader->getLastError(), "");
    test->setParam("--speed 3");
    test->setEnvironment("sim");
    test->setRepetition(2);
    Outcome outcome = runWithOwnRunner(test, 2);
    EXPECT_EQ(outcome.tests, 2u);
    EXPECT_EQ(outcome.passed, 2u);
    EXPECT_TRUE(has(outcome.reports, "param=--speed 3 env=sim"))
        << ::testing::PrintToString(outcome.reports);
    // Two runs of two repetitions each.
    std::size_t runs = 0;
    for (const std::string& report : outcome.reports) {
        runs += report.find("param=") != std::string::npos ? 1 : 0;
    }
    EXPECT_EQ(runs, 4u);
    loader->close();
}

TEST_P(ScriptPluginLoader, MissingFileNamesTheFile) {
    std::unique_ptr<PluginLoader> loader = GetParam().make();
    std::string path = "/no/such/test" + GetParam().extension;
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(loader->open(path), nullptr);
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
    EXPECT_NE(loader->getLastError().find(path), std::string::npos) << loader->getLastError();
    EXPECT_NE(loader->getLastError().find("No such file"), std::string::npos)
        << loader->getLastError();
}

TEST_P(ScriptPluginLoader, FileOfAnotherLanguageIsRefused) {
    const Language& language = GetParam();
    std::string path = writeScript(scriptFolder(), "other" + language.otherExtension, "x\n");
    std::unique_ptr<PluginLoader> loader = language.make();
    EXPECT_EQ(loader->open(path), nullptr);
    EXPECT_NE(loader->getLastError().find(path), std::string::npos) << loader->getLastError();
    EXPECT_NE(loader->getLastError().find(" file, not a "), std::string::npos)
        << loader->getLastError();
}

TEST_P(ScriptPluginLoader, SyntaxErrorGivesTheLanguagesMessageWithFileAndLine) {
    const Language& language = GetParam();
    std::string path =
        writeScript(scriptFolder(), "broken" + language.extension, language.syntaxError);
    std::unique_ptr<PluginLoader> loader = language.make();
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(loader->open(path), nullptr);
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
    const std::string error = loader->getLastError();
    EXPECT_NE(error.find(path), std::string::npos) << error;
    // The language's own "file:line" (Lua shortens long paths, hence the file name only).
    const std::string where =
        "broken" + language.extension + ":" + std::to_string(language.syntaxLine);
    EXPECT_NE(error.find(where), std::string::npos) << error;
}

TEST_P(ScriptPluginLoader, LoaderCanBeReusedAfterAFailure) {
    const Language& language = GetParam();
    std::unique_ptr<PluginLoader> loader = language.make();
    EXPECT_EQ(loader->open("/no/such/test" + language.extension), nullptr);
    std::string path = writeScript(scriptFolder(), "ok" + language.extension, language.passing);
    ASSERT_NE(loader->open(path), nullptr) << loader->getLastError();
    EXPECT_EQ(loader->getLastError(), "");
}

std::vector<Language> scriptLanguages() {
    std::vector<Language> all;
#ifdef RTF_HAVE_PYTHON
    all.push_back(
        {".py",
         [] { return std::make_unique<robottestingframework::plugin::PythonPluginLoader>(); },
         "class TestCase:\n"
         "    def setup(self, param):\n"
         "        return True\n"
         "    def run(self):\n"
         "        robottestingframework.testReport('param=' + "
         "robottestingframework.getParam() + ' env=' + "
         "robottestingframework.getEnvironment())\n"
         "        robottestingframework.testCheck(True, 'holds')\n",
         "class TestCase:\n    def run(self)\n        pass\n", 2, ".lua"});
#endif
#ifdef RTF_HAVE_LUA
    all.push_back(
        {".lua", [] { return std::make_unique<robottestingframework::plugin::LuaPluginLoader>(); },
         "TestCase.setup = function(param) return true end\n"
         "TestCase.run = function()\n"
         "    robottestingframework.testReport('param=' .. "
         "robottestingframework.getParam() .. ' env=' .. "
         "robottestingframework.getEnvironment())\n"
         "    robottestingframework.testCheck(true, 'holds')\n"
         "end\n",
         "TestCase.run = function()\n    if then\nend\n", 2, ".py"});
#endif
#ifdef RTF_HAVE_RUBY
    all.push_back(
        {".rb", [] { return std::make_unique<robottestingframework::plugin::RubyPluginLoader>(); },
         "class TestCase\n"
         "  def setup(param)\n"
         "    return true\n"
         "  end\n"
         "  def run\n"
         "    RobotTestingFramework::testReport('param=' + "
         "RobotTestingFramework::getParam() + ' env=' + "
         "RobotTestingFramework::getEnvironment())\n"
         "    RobotTestingFramework::testCheck(true, 'holds')\n"
         "  end\n"
         "end\n",
         "class TestCase\n  def run(\nend\n", 3, ".lua"});
#endif
    return all;
}

std::string languageName(const ::testing::TestParamInfo<Language>& info) {
    return info.param.extension.substr(1);
}

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ScriptPluginLoader);
INSTANTIATE_TEST_SUITE_P(Languages, ScriptPluginLoader, ::testing::ValuesIn(scriptLanguages()),
                         languageName);
