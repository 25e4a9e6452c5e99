// The model's shared strings (shared_string.h): a suite of many tests of one plug-in holds the
// plug-in's path and the suite file's name once, from reading the suite through the plan.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <robottestingframework/TestResult.h>

#include "build_paths.h"
#include "runner/model/shared_string.h"
#include "runner/model/test_executor.h"
#include "runner/plan/run_plan.h"
#include "runner/suites/suite_file.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

class IdleExecutor : public TestExecutor {
public:
    TestStatus run(const TestSpec&, Test&, TestResult&) override { return TestStatus::Passed; }
    void interrupt() override {}
    std::unique_ptr<FixtureManager> makeFixture(const FixtureSpec&, std::string&) override {
        return nullptr;
    }
};

SuiteSpec threeTestsOfTwoPlugins() {
    std::vector<std::string> warnings;
    return parseSuite(R"(<suite name="arm">
  <fixture>/opt/arm/libarmfixture.so</fixture>
  <test>/opt/arm/libreach.so</test>
  <test param="--far">/opt/arm/libreach.so</test>
  <test>/opt/arm/libgrasp.so</test>
</suite>)",
                      "/nowhere/arm.xml", warnings);
}

}  // namespace

TEST(SharedString, ACopySharesTheTextAndANewTextSharesNothing) {
    SharedString path = std::string("/opt/arm/libreach.so");
    SharedString copy = path;
    EXPECT_TRUE(copy.sharesWith(path));
    EXPECT_EQ(&copy.str(), &path.str());
    copy = "/opt/arm/libgrasp.so";
    EXPECT_FALSE(copy.sharesWith(path));
    EXPECT_EQ(path, "/opt/arm/libreach.so");
    EXPECT_EQ(copy, "/opt/arm/libgrasp.so");
}

TEST(SharedString, ReadsAsTheStringItHolds) {
    SharedString none;
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(none.str(), "");
    SharedString empty = std::string();
    EXPECT_EQ(empty, none);
    const SharedString plugin = "libreach.so";
    EXPECT_EQ("cannot load " + plugin, "cannot load libreach.so");
    EXPECT_EQ(plugin + " (not found)", "libreach.so (not found)");
    const std::string& text = plugin;
    EXPECT_EQ(text.size(), plugin.size());
    EXPECT_NE(plugin, std::string("libgrasp.so"));
}

TEST(StringPool, GivesOneStringPerText) {
    StringPool pool;
    const SharedString a = pool.intern(std::string("suite.xml"));
    const SharedString b = pool.intern(std::string("suite") + ".xml");
    const SharedString c = pool.intern("other.xml");
    EXPECT_TRUE(a.sharesWith(b));
    EXPECT_FALSE(a.sharesWith(c));
    EXPECT_EQ(c, "other.xml");
}

TEST(SharedString, TestsOfOnePluginShareItsPathAndTheirSuiteFile) {
    const SuiteSpec suite = threeTestsOfTwoPlugins();
    ASSERT_EQ(suite.tests.size(), 3u);
    const TestSpec& first = suite.tests[0];
    const TestSpec& second = suite.tests[1];
    const TestSpec& other = suite.tests[2];
    EXPECT_EQ(first.plugin, "/opt/arm/libreach.so");
    EXPECT_TRUE(first.plugin.sharesWith(second.plugin));
    EXPECT_FALSE(first.plugin.sharesWith(other.plugin));
    // Not found here, so no path; a found one is shared the same way (a file on disk below).
    EXPECT_TRUE(first.where.file.sharesWith(second.where.file));
    EXPECT_TRUE(first.where.file.sharesWith(other.where.file));
    EXPECT_TRUE(first.where.file.sharesWith(suite.where.file));
    EXPECT_TRUE(first.where.file.sharesWith(suite.fixtures.at(0).where.file));
    EXPECT_EQ(first.where.toString(), "/nowhere/arm.xml:3");
}

TEST(SharedString, TestsOfOneFoundPluginShareItsResolvedPath) {
    std::vector<std::string> warnings;
    // The test plug-ins of this build are found by their full path.
    const std::string plugin = std::string(build_paths::testPluginDir()) + "/passing_test.so";
    const SuiteSpec suite =
        parseSuite("<suite><test>" + plugin + "</test><test>" + plugin + "</test></suite>",
                   "/nowhere/found.xml", warnings);
    ASSERT_EQ(suite.tests.size(), 2u);
    ASSERT_FALSE(suite.tests[0].path.empty());
    EXPECT_TRUE(suite.tests[0].path.sharesWith(suite.tests[1].path));
}

TEST(SharedString, ThePlanKeepsTheSharing) {
    IdleExecutor executor;
    RunPlan plan(executor);
    SuiteSpec suite = threeTestsOfTwoPlugins();
    Overrides overrides;
    overrides.param = "--near";
    overrides.environment = "--robot sim";
    applyOverrides(suite, overrides);
    plan.addSuite(std::move(suite));
    const std::vector<PluginTest*> standIns = plan.tests(0);
    ASSERT_EQ(standIns.size(), 3u);
    EXPECT_TRUE(standIns[0]->spec().plugin.sharesWith(standIns[1]->spec().plugin));
    EXPECT_TRUE(standIns[0]->spec().where.file.sharesWith(standIns[2]->spec().where.file));
    EXPECT_TRUE(standIns[0]->spec().where.file.sharesWith(plan.spec(0).where.file));
    // --param for the tests without one, and the environment of the suite and the command line,
    // are one string for all.
    EXPECT_EQ(standIns[0]->spec().param, "--near");
    EXPECT_EQ(standIns[1]->spec().param, "--far");
    EXPECT_TRUE(standIns[0]->spec().param.sharesWith(standIns[2]->spec().param));
    EXPECT_EQ(standIns[0]->spec().environment, "--robot sim");
    EXPECT_TRUE(standIns[0]->spec().environment.sharesWith(standIns[1]->spec().environment));
    EXPECT_TRUE(standIns[0]->spec().environment.sharesWith(standIns[2]->spec().environment));
}

TEST(SharedString, ATestsOwnEnvironmentComesBetweenTheSuitesAndTheCommandLines) {
    SuiteSpec suite = threeTestsOfTwoPlugins();
    suite.environment = "--suite";
    suite.tests[1].environment = "--own";
    Overrides overrides;
    overrides.environment = "--line";
    applyOverrides(suite, overrides);
    EXPECT_EQ(suite.tests[0].environment, "--suite --line");
    EXPECT_EQ(suite.tests[1].environment, "--suite --own --line");
    EXPECT_FALSE(suite.tests[0].environment.sharesWith(suite.tests[1].environment));
    EXPECT_TRUE(suite.tests[0].environment.sharesWith(suite.tests[2].environment));
}
