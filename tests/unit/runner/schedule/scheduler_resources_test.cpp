// Resources of the scheduler: suite files' <resource>, the --resources file, who holds what,
// ${resource.NAME} markers, -j.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_paths.h"
#include "isolation/wire_format.h"
#include "runner/cli/options.h"
#include "runner/schedule/resources.h"
#include "runner/suites/suite_file.h"
#include "variables/variables.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

SuiteSpec parse(const std::string& text) {
    std::vector<std::string> warnings;
    return parseSuite(text, "/nowhere/suite.xml", warnings);
}

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const SuiteFileError& e) {
        return e.what();
    }
    return {};
}

SuiteSpec suiteWith(const std::string& name, std::vector<ResourceSpec> resources) {
    SuiteSpec suite;
    suite.name = name;
    suite.resources = std::move(resources);
    return suite;
}

ResourceSpec lock(const std::string& name) {
    ResourceSpec resource;
    resource.lock = name;
    return resource;
}

ResourceSpec pool(const std::string& name, unsigned int count = 1) {
    ResourceSpec resource;
    resource.pool = name;
    resource.count = count;
    resource.where = SourceLocation{"s.xml", 3};
    return resource;
}

std::string writeFile(const std::string& name, const std::string& text) {
    std::filesystem::create_directories(build_paths::unitTestTmpDir());
    const std::string path = std::string(build_paths::unitTestTmpDir()) + "/" + name;
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST(SchedulerResources, SuiteFileReadsLocksPoolsAndExclusive) {
    SuiteSpec suite = parse(R"(<suite name="s" exclusive="true">
  <resource lock="robot:left-arm"/>
  <resource pool="ros_domain" count="2"/>
  <test param="--domain ${resource.ros_domain}">x</test>
</suite>)");
    EXPECT_TRUE(suite.exclusive);
    ASSERT_EQ(suite.resources.size(), 2u);
    EXPECT_EQ(suite.resources[0].lock, "robot:left-arm");
    EXPECT_EQ(suite.resources[0].where.line, 2u);
    EXPECT_EQ(suite.resources[1].pool, "ros_domain");
    EXPECT_EQ(suite.resources[1].count, 2u);
    // Kept for the scheduler to fill in.
    EXPECT_EQ(variables::resourcesUsed(suite.tests[0].param),
              std::vector<std::string>{"ros_domain"});
    EXPECT_EQ(variables::fillResources(suite.tests[0].param,
                                       [](const std::string&) { return std::string("7"); }),
              "--domain 7");
}

TEST(SchedulerResources, SuiteFileReadsAPoolsDefaultItems) {
    SuiteSpec suite = parse(R"(<suite name="s">
  <resource pool="port" default=" 18831  18841 "/>
  <resource pool="gpu"/>
</suite>)");
    ASSERT_EQ(suite.resources.size(), 2u);
    EXPECT_EQ(suite.resources[0].defaults, (std::vector<std::string>{"18831", "18841"}));
    EXPECT_TRUE(suite.resources[1].defaults.empty());
}

TEST(SchedulerResources, SuiteFileRefusesBadResourcesWithFileAndLine) {
    EXPECT_EQ(errorOf("<suite name=\"s\">\n<resource lock=\"left arm\"/></suite>"),
              "/nowhere/suite.xml:2: <resource lock=\"left arm\">: a lock name has no spaces "
              "(e.g. robot:left-arm)");
    EXPECT_NE(errorOf("<suite name=\"s\">\n<resource/></suite>")
                  .find("suite.xml:2: <resource> "
                        "takes one of"),
              std::string::npos);
    EXPECT_NE(errorOf("<suite name=\"s\">\n<resource pool=\"p\" count=\"x\"/></suite>")
                  .find("suite.xml:2: count=\"x\""),
              std::string::npos);
    EXPECT_NE(errorOf("<suite name=\"s\">\n<resource pool=\"1p\"/></suite>")
                  .find("suite.xml:2: <resource pool=\"1p\">"),
              std::string::npos);
    EXPECT_NE(errorOf("<suite name=\"s\" exclusive=\"1\"></suite>")
                  .find("suite.xml:1: exclusive=\"1\": expected true or false"),
              std::string::npos);
    EXPECT_NE(errorOf("<suite name=\"s\">\n<test param=\"${resource.gpu}\">x</test></suite>")
                  .find("suite.xml:2: ${resource.gpu} but the suite takes no item of pool gpu"),
              std::string::npos);
}

TEST(SchedulerResources, SuiteFileRefusesAPoolTakenTwiceSayingWhatToWrite) {
    // Each alone fits a one-item pool; together they never would (the run waited for ever).
    EXPECT_EQ(errorOf("<suite name=\"s\">\n<resource pool=\"p\" default=\"1\"/>\n"
                      "<resource pool=\"p\" count=\"2\" default=\"1\"/></suite>"),
              "/nowhere/suite.xml:3: pool \"p\" is taken a second time (first at line 2); write "
              "one <resource pool=\"p\" count=\"3\"/> for 3 items");
    // A lock named twice is one lock: harmless.
    EXPECT_EQ(errorOf("<suite name=\"s\">\n<resource lock=\"a\"/>\n<resource lock=\"a\"/>"
                      "</suite>"),
              "");
}

TEST(SchedulerResources, SuiteFileRefusesAnItemRepeatedInDefault) {
    EXPECT_EQ(errorOf("<suite name=\"s\">\n<resource pool=\"p\" default=\"7 7\"/></suite>"),
              "/nowhere/suite.xml:2: default=\"...\": item \"7\" is given twice (each item of a "
              "pool once: two suites would hold it at once)");
    EXPECT_NE(errorOf("<suite name=\"s\">\n\n<resource pool=\"p\" count=\"2\" "
                      "default=\"1 2 1\"/></suite>")
                  .find("suite.xml:3: default=\"...\": item \"1\" is given twice"),
              std::string::npos);
}

TEST(SchedulerResources, AProcessFixtureGetsTheItemsOfEveryPoolForItsWorldFile) {
    SuiteSpec suite = parse(R"(<suite name="s">
  <fixture type="process">world.xml</fixture>
  <fixture type="python">other.py</fixture>
  <resource pool="port" count="2"/>
  <resource lock="arm"/>
</suite>)");
    ASSERT_EQ(suite.fixtures.size(), 2u);
    EXPECT_EQ(variables::resourcesUsed(suite.fixtures[0].param), std::vector<std::string>{"port"});
    EXPECT_EQ(variables::fillResources(suite.fixtures[0].param,
                                       [](const std::string&) { return std::string("7,8"); }),
              "--var 'resource.port=7,8'");
    EXPECT_EQ(suite.fixtures[1].param, "");
}

TEST(SchedulerResources, LocksAreTakenAllOrNothing) {
    ResourceTable table{ResourcePools()};
    ResourceTable::Held a, b, c;
    std::string busyLock, busyPool;
    ASSERT_TRUE(table.take(suiteWith("a", {lock("y"), lock("x")}), "a", a, busyLock, busyPool));
    EXPECT_EQ(a.locks, (std::vector<std::string>{"x", "y"}));  // sorted
    EXPECT_FALSE(table.take(suiteWith("b", {lock("z"), lock("y")}), "b", b, busyLock, busyPool));
    EXPECT_EQ(busyLock, "y");
    EXPECT_EQ(table.holderOf("y"), "a");
    EXPECT_EQ(table.holderOf("z"), "");  // nothing taken by the suite that waits
    ASSERT_TRUE(table.take(suiteWith("c", {lock("z")}), "c", c, busyLock, busyPool));
    table.release(a);
    EXPECT_EQ(table.holderOf("y"), "");
}

TEST(SchedulerResources, PoolItemsAreDistinctUpToTheirSlots) {
    ResourcePools pools;
    pools.pools["port"] = {PoolItem{"1", 1}, PoolItem{"2", 2}};
    ResourceTable table(pools);
    std::string busyLock, busyPool;
    ResourceTable::Held a, b, c, d;
    ASSERT_TRUE(table.take(suiteWith("a", {pool("port", 2)}), "a", a, busyLock, busyPool));
    EXPECT_EQ(a.items["port"], (std::vector<std::string>{"1", "2"}));
    ASSERT_TRUE(table.take(suiteWith("b", {pool("port")}), "b", b, busyLock, busyPool));
    EXPECT_EQ(b.items["port"], std::vector<std::string>{"2"});  // its second slot
    EXPECT_FALSE(table.take(suiteWith("c", {pool("port")}), "c", c, busyLock, busyPool));
    EXPECT_EQ(busyPool, "port");
    table.release(a);
    ASSERT_TRUE(table.take(suiteWith("d", {pool("port")}), "d", d, busyLock, busyPool));
    EXPECT_EQ(d.items["port"], std::vector<std::string>{"1"});
}

TEST(SchedulerResources, ResourceFileIsReadLikeCTestsAndCheckedAgainstSuites) {
    const std::string path = writeFile("resources.json",
                                       R"({"version": {"major": 1, "minor": 0},
            "local": [{"gpus": [{"id": "0", "slots": 2}, {"id": "1"}], "ros_domain": []}]})");
    ResourcePools pools = readResourceFile(path);
    ASSERT_EQ(pools.pools["gpus"].size(), 2u);
    EXPECT_EQ(pools.pools["gpus"][0].slots, 2u);
    EXPECT_EQ(pools.pools["gpus"][1].slots, 1u);
    EXPECT_EQ(checkPools({suiteWith("s", {pool("gpus", 2)})}, pools), "");
    EXPECT_NE(checkPools({suiteWith("s", {pool("gpus", 3)})}, pools).find("s.xml:3: pool \"gpus\""),
              std::string::npos);
    EXPECT_NE(checkPools({suiteWith("s", {pool("cameras")})}, pools)
                  .find("s.xml:3: pool \"cameras\" does not exist in " + path +
                        " (it has gpus, ros_domain)"),
              std::string::npos);
    for (const char* bad :
         {"[]", R"({"version": {"major": 1}, "local": []})",
          R"({"version": {"major": 1}, "local": [{"gpus": [{"slots": 1}]}]})",
          R"({"version": {"major": 1}, "local": [{"gpus": [{"id": "0", "slots": 0}]}]})",
          R"({"version": {"major": 1e999}, "local": []})"}) {
        writeFile("bad.json", bad);
        EXPECT_THROW(readResourceFile(std::string(build_paths::unitTestTmpDir()) + "/bad.json"),
                     std::runtime_error)
            << bad;
    }
}

TEST(SchedulerResources, APoolNoFileGivesTakesTheSuitesDefault) {
    ResourceSpec port = pool("port");
    port.defaults = {"18831", "18841"};
    ResourcePools none;
    EXPECT_EQ(addSuiteDefaults({suiteWith("robot", {port})}, none), "");
    ASSERT_EQ(none.pools["port"].size(), 2u);
    EXPECT_EQ(none.pools["port"][1].id, "18841");
    EXPECT_EQ(checkPools({suiteWith("robot", {port})}, none), "");
    // Too few items: the message says where they came from.
    ResourceSpec three = pool("port", 3);
    three.defaults = port.defaults;
    EXPECT_NE(checkPools({suiteWith("robot", {three})}, none).find("(default= at s.xml:3) has 2"),
              std::string::npos);

    // A --resources file that gives the pool wins.
    ResourcePools file;
    file.file = "ports.json";
    file.pools["port"] = {PoolItem{"1", 1}};
    EXPECT_EQ(addSuiteDefaults({suiteWith("robot", {port})}, file), "");
    ASSERT_EQ(file.pools["port"].size(), 1u);
    EXPECT_EQ(file.pools["port"][0].id, "1");
}

TEST(SchedulerResources, TwoDifferentDefaultsForOnePoolAreAnError) {
    ResourceSpec first = pool("port");
    first.defaults = {"1"};
    ResourceSpec same = first;
    ResourceSpec other = pool("port");
    other.defaults = {"2"};
    other.where = SourceLocation{"t.xml", 5};
    ResourcePools pools;
    EXPECT_EQ(addSuiteDefaults({suiteWith("a", {first}), suiteWith("b", {same})}, pools), "");
    ResourcePools clash;
    EXPECT_EQ(addSuiteDefaults({suiteWith("a", {first}), suiteWith("b", {other})}, clash),
              "t.xml:5: pool \"port\" has another default at s.xml:3; give one default, or the "
              "pool in a --resources file");
}

TEST(SchedulerResources, VariableNameOfAPool) {
    EXPECT_EQ(resourceVariable("ros_domain"), "RTF_RESOURCE_ROS_DOMAIN");
    EXPECT_EQ(resourceVariable("Gpu2"), "RTF_RESOURCE_GPU2");
}

TEST(SchedulerResources, JobsAreAWholeNumberOrAuto) {
    unsigned int jobs = 0;
    EXPECT_EQ(checkJobs("4", jobs), "");
    EXPECT_EQ(jobs, 4u);
    EXPECT_EQ(checkJobs("auto", jobs), "");
    EXPECT_GE(jobs, 1u);
    for (const char* bad : {"0", "", "-2", "1.5", "two", "1025", "99999999"}) {
        EXPECT_NE(checkJobs(bad, jobs), "") << bad;
    }
}

TEST(SchedulerResources, WorkRequestCarriesEnvironmentVariables) {
    isolation::WorkRequest request;
    request.path = "/x.so";
    request.variables = {"RTF_RESOURCE_A=1", "RTF_RESOURCE_B=2,3"};
    isolation::WorkRequest back;
    ASSERT_TRUE(isolation::decodeRequest(isolation::encodeRequest(request), back));
    EXPECT_EQ(back.variables, request.variables);
    std::string cut = isolation::encodeRequest(request);
    cut.pop_back();
    EXPECT_FALSE(isolation::decodeRequest(cut, back));
}
