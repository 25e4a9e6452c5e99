// What --list and --list-vars print (listing.h): the suites as read, nothing loaded.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "build_paths.h"
#include "runner/cli/listing.h"

using namespace robottestingframework::runner;

namespace {

TestSpec test(const std::string& name) {
    TestSpec spec;
    spec.name = name;
    spec.plugin = name;
    spec.path = "/plugins/" + name + ".lua";
    spec.type = "lua";
    return spec;
}

SuiteSpec armSuite() {
    SuiteSpec suite;
    suite.name = "arm";
    suite.where.file = "arm.xml";
    suite.tests = {test("reach"), test("grip")};
    return suite;
}

}  // namespace

TEST(Listing, ASuiteIsABlockWithALineOfIdAndPluginPerTest) {
    EXPECT_EQ(listText({armSuite()}),
              "suite arm (arm.xml)\n"
              "  arm/reach\n"
              "      type lua, plug-in /plugins/reach.lua\n"
              "  arm/grip\n"
              "      type lua, plug-in /plugins/grip.lua\n"
              "2 tests in 1 suite\n");
}

TEST(Listing, ATestShowsItsParamTagsTimeoutAndRepetitionWhenGiven) {
    SuiteSpec suite = armSuite();
    suite.tests.resize(1);
    TestSpec& reach = suite.tests[0];
    reach.param = "--speed 2";
    reach.tags = {"slow", "arm"};
    reach.timeout = 2.5;
    reach.repetition = 3;
    EXPECT_EQ(listText({suite}),
              "suite arm (arm.xml)\n"
              "  arm/reach\n"
              "      type lua, plug-in /plugins/reach.lua\n"
              "      param --speed 2\n"
              "      tags slow,arm\n"
              "      timeout 2.5s\n"
              "      repetition 3\n"
              "1 test in 1 suite\n");
}

TEST(Listing, APluginNotFoundIsSaidAsWritten) {
    SuiteSpec suite = armSuite();
    suite.tests.resize(1);
    suite.tests[0].path = {};
    suite.tests[0].type = {};
    suite.tests[0].plugin = "reach_missing";
    const std::string text = listText({suite});
    EXPECT_NE(text.find("      type (unknown), plug-in reach_missing (not found)\n"),
              std::string::npos)
        << text;
}

TEST(Listing, ATestWithoutANameIsListedByItsPlugin) {
    SuiteSpec suite = armSuite();
    suite.tests.resize(1);
    suite.tests[0].name = {};
    EXPECT_NE(listText({suite}).find("  arm/reach\n"), std::string::npos);
}

TEST(Listing, APoolItemIsShownAsWrittenUntilTheSuiteStarts) {
    SuiteSpec suite = armSuite();
    suite.tests.resize(1);
    suite.tests[0].param = "--domain ${resource.ros_domain}";
    EXPECT_NE(listText({suite}).find("      param --domain ${resource.ros_domain}\n"),
              std::string::npos);
}

TEST(Listing, WhatASuiteTakesIsOneLine) {
    SuiteSpec suite = armSuite();
    suite.resources = {ResourceSpec{"robot:arm", "", 1, {}}, ResourceSpec{"", "ros_domain", 2, {}}};
    suite.exclusive = true;
    EXPECT_NE(listText({suite}).find("suite arm (arm.xml)\n  takes lock robot:arm, 2 of pool "
                                     "ros_domain, the machine alone (exclusive)\n"),
              std::string::npos);
}

TEST(Listing, EachSuiteShowsItsShardWhenSharded) {
    SuiteSpec leg = armSuite();
    leg.name = "leg";
    leg.where.file = {};
    const std::string text = listText({armSuite(), leg}, {1, 0}, 2);
    EXPECT_NE(text.find("suite arm (arm.xml)  [shard 1 of 2]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("suite leg  [shard 0 of 2]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("4 tests in 2 suites\n"), std::string::npos) << text;
}

TEST(Listing, NothingSelectedIsZeroTestsInZeroSuites) {
    EXPECT_EQ(listText({}), "0 tests in 0 suites\n");
}

TEST(Listing, TheJsonListHasEverySuiteAndTestWithTheirFields) {
    SuiteSpec suite = armSuite();
    suite.fixtures.push_back(FixtureSpec{"robot", "/bin/robot", "process", "--port 1", {}});
    suite.tests[0].depends = {"grip"};
    suite.tests[0].where = SourceLocation{"arm.xml", 4};
    const nlohmann::json list = nlohmann::json::parse(listJson({suite}, {3}));
    ASSERT_EQ(list["suites"].size(), 1u);
    const auto& arm = list["suites"][0];
    EXPECT_EQ(arm["name"], "arm");
    EXPECT_EQ(arm["file"], "arm.xml");
    EXPECT_EQ(arm["shard"], 3);
    EXPECT_EQ(arm["fixtures"][0]["param"], "--port 1");
    ASSERT_EQ(arm["tests"].size(), 2u);
    EXPECT_EQ(arm["tests"][0]["id"], "arm/reach");
    EXPECT_EQ(arm["tests"][0]["type"], "lua");
    EXPECT_EQ(arm["tests"][0]["path"], "/plugins/reach.lua");
    EXPECT_EQ(arm["tests"][0]["depends"], nlohmann::json::array({"grip"}));
    EXPECT_EQ(arm["tests"][0]["where"], "arm.xml:4");
}

TEST(Listing, TheJsonListHasNoShardWhenNotSharded) {
    const nlohmann::json list = nlohmann::json::parse(listJson({armSuite()}));
    EXPECT_FALSE(list["suites"][0].contains("shard"));
}

// discover_tests gives the suites sharing a world one CTest fixture: it needs each fixture's
// scope, and a shared world's name, file and identity (docs/how-to/ctest-shared-worlds.md).
TEST(Listing, TheJsonListSaysWhichFixturesAreSharedWorldsAndTheirIdentity) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("rtf_listing_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::string world = (folder / "lab.xml").string();
    std::ofstream(world) << "<world name=\"the lab\"><process name=\"p\"><command>true"
                            "</command></process></world>\n";
    SuiteSpec suite = armSuite();
    suite.network = SuiteSpec::Network::Private;
    FixtureSpec own;
    own.plugin = "own.xml";
    own.path = "own.xml";
    own.type = "process";
    FixtureSpec shared = own;
    shared.plugin = world;
    shared.path = world;
    shared.param = "--var port=1";
    shared.scope = FixtureSpec::Scope::Run;
    suite.fixtures = {own, shared};
    const nlohmann::json list = nlohmann::json::parse(listJson({suite}));
    std::filesystem::remove_all(folder);
    const nlohmann::json& listed = list["suites"][0];
    EXPECT_EQ(listed["network"], "private");
    EXPECT_EQ(listed["fixtures"][0]["scope"], "suite");
    EXPECT_FALSE(listed["fixtures"][0].contains("identity"));
    EXPECT_EQ(listed["fixtures"][1]["scope"], "run");
    EXPECT_EQ(listed["fixtures"][1]["world"], "the lab");
    EXPECT_EQ(listed["fixtures"][1]["world_file"], world);
    EXPECT_EQ(listed["fixtures"][1]["identity"], world + "\n--var port=1");
    EXPECT_EQ(list["suites"][0]["fixtures"][1]["param"], "--var port=1");
    suite.network = SuiteSpec::Network::Host;
    EXPECT_EQ(nlohmann::json::parse(listJson({suite}))["suites"][0]["network"], "host");
}

TEST(Listing, InvalidUtf8InAParamIsReplacedNotFatal) {
    SuiteSpec suite = armSuite();
    suite.tests[0].param = "caf\xE9";
    const std::string json = listJson({suite});
    EXPECT_NO_THROW(nlohmann::json::parse(json));
    EXPECT_NE(json.find("caf\xEF\xBF\xBD"), std::string::npos);
}

TEST(Listing, TheJsonListIsWrittenToItsFile) {
    const std::string file = std::string(build_paths::unitTestTmpDir()) + "/listing_" +
                             std::to_string(::getpid()) + ".json";
    std::filesystem::create_directories(build_paths::unitTestTmpDir());
    std::string error;
    ASSERT_TRUE(writeListJson(file, {armSuite()}, error)) << error;
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(file);
    EXPECT_EQ(text.str(), listJson({armSuite()}));
}

TEST(Listing, AListThatCannotBeWrittenSaysWhy) {
    std::string error;
    EXPECT_FALSE(
        writeListJson(std::string(build_paths::unitTestTmpDir()) + "/no/such/folder/list.json",
                      {armSuite()}, error));
    EXPECT_FALSE(error.empty());
}

TEST(Listing, VariablesAreListedWithWhereTheyCameFrom) {
    SuiteSpec suite = armSuite();
    suite.variables = {VariableValue{"robot", "icub", "--var"},
                       VariableValue{"speed", "2", "arm.xml:3"}};
    SuiteSpec leg = armSuite();
    leg.name = "leg";
    leg.where.file = {};
    EXPECT_EQ(listVariablesText({suite, leg}),
              "suite arm (arm.xml)\n"
              "  robot = icub  (--var)\n"
              "  speed = 2  (arm.xml:3)\n"
              "suite leg\n"
              "  (no variables)\n");
}
