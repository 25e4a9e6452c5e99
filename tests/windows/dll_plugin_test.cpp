// C++ plug-ins on Windows: DLLs opened with LoadLibrary, found by bare name beside the suite and
// along PATH, with and without MinGW's "lib" prefix, and run like any test.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/dll/DllPluginLoader.h>

#include "build_paths.h"

using namespace robottestingframework;
using plugin::DllFixturePluginLoader;
using plugin::DllPluginLoader;
using plugin::findPlugin;
namespace fs = std::filesystem;

namespace {

// build_paths::windowsPluginDir() holds passing_test.dll, order_fixture.dll and not_a_plugin.dll
// (no prefix, as MSVC names them) and libfailing_test.dll (MinGW's name).
const std::string pluginDir = build_paths::windowsPluginDir();

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

bool sameFile(const std::string& found, const std::string& expected) {
    return !found.empty() && fs::equivalent(found, expected);
}

}  // namespace

TEST(WindowsPlugin, OpensADllAndMakesItsTest) {
    DllPluginLoader loader;
    TestCase* test = loader.open(pluginDir + "/passing_test.dll");
    ASSERT_NE(test, nullptr) << loader.getLastError();
    EXPECT_EQ(test->getName(), "PassingTest");
}

TEST(WindowsPlugin, RunsAPassingAndAFailingTest) {
    DllPluginLoader passing;
    DllPluginLoader failing;
    TestCase* passingTest = passing.open(pluginDir + "/passing_test.dll");
    TestCase* failingTest = failing.open(pluginDir + "/libfailing_test.dll");
    ASSERT_NE(passingTest, nullptr) << passing.getLastError();
    ASSERT_NE(failingTest, nullptr) << failing.getLastError();
    TestResult result;
    TestResultCollector collector;
    result.addListener(&collector);
    TestRunner runner;
    runner.addTest(passingTest);
    runner.addTest(failingTest);
    runner.run(result);
    EXPECT_EQ(collector.testCount(), 2u);
    EXPECT_EQ(collector.passedCount(), 1u);
    EXPECT_EQ(collector.failedCount(), 1u);
}

TEST(WindowsPlugin, BareNameIsFoundBesideTheSuiteWithAndWithoutLibPrefix) {
    std::string searched;
    EXPECT_TRUE(
        sameFile(findPlugin("passing_test", pluginDir, &searched), pluginDir + "/passing_test.dll"))
        << searched;
    EXPECT_TRUE(sameFile(findPlugin("failing_test", pluginDir, &searched),
                         pluginDir + "/libfailing_test.dll"))
        << searched;
    EXPECT_TRUE(sameFile(findPlugin("libfailing_test.dll", pluginDir, &searched),
                         pluginDir + "/libfailing_test.dll"))
        << searched;
}

TEST(WindowsPlugin, BareNameIsFoundAlongPath) {
    std::string searched;
    EXPECT_TRUE(findPlugin("failing_test", "", &searched).empty()) << "not on PATH yet";
    const char* old = std::getenv("PATH");
    const std::string path = pluginDir + ";" + (old != nullptr ? old : "");
    ASSERT_EQ(_putenv_s("PATH", path.c_str()), 0);
    EXPECT_TRUE(
        sameFile(findPlugin("failing_test", "", &searched), pluginDir + "/libfailing_test.dll"))
        << searched;
    EXPECT_TRUE(
        sameFile(findPlugin("passing_test", "", &searched), pluginDir + "/passing_test.dll"))
        << searched;
}

TEST(WindowsPlugin, NotFoundSaysWhereItLooked) {
    std::string searched;
    EXPECT_TRUE(findPlugin("no_such_plugin", pluginDir, &searched).empty());
    EXPECT_TRUE(has(searched, "no_such_plugin.dll")) << searched;
    EXPECT_TRUE(has(searched, "libno_such_plugin.dll")) << searched;
}

TEST(WindowsPlugin, MissingDllGivesTheLoadersWordsAndTheFile) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(pluginDir + "/no_such_plugin.dll"), nullptr);
    EXPECT_TRUE(has(loader.getLastError(), "no_such_plugin.dll")) << loader.getLastError();
    EXPECT_TRUE(has(loader.getLastError(), "error 126")) << loader.getLastError();
}

TEST(WindowsPlugin, DllWithoutFactoryIsNotAPlugin) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(pluginDir + "/not_a_plugin.dll"), nullptr);
    EXPECT_TRUE(has(loader.getLastError(), "is not a Robot Testing Framework plug-in"))
        << loader.getLastError();
}

TEST(WindowsPlugin, FixtureDllIsOpenedAsAFixture) {
    DllPluginLoader tests;
    EXPECT_EQ(tests.open(pluginDir + "/order_fixture.dll"), nullptr);
    EXPECT_TRUE(has(tests.getLastError(), "it is a fixture plug-in")) << tests.getLastError();
    DllFixturePluginLoader fixtures;
    EXPECT_NE(fixtures.open(pluginDir + "/order_fixture.dll"), nullptr) << fixtures.getLastError();
}
