// Suites of one run that start one world file: each gets its own log folder (plan/world_logs.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/plan/world_logs.h"

using namespace robottestingframework::runner;

namespace {

SuiteSpec suiteStarting(const std::string& name, const std::string& world,
                        const std::string& param = "") {
    SuiteSpec suite;
    suite.name = name;
    FixtureSpec fixture;
    fixture.type = "process";
    fixture.plugin = world;
    fixture.path = "/lab/" + world;
    fixture.param = param;
    suite.fixtures.push_back(fixture);
    return suite;
}

}  // namespace

TEST(WorldLogs, SuitesSharingAWorldFileEachGetTheirInstance) {
    std::vector<SuiteSpec> suites{suiteStarting("left", "robot.xml", "--var 'a=1'"),
                                  suiteStarting("alone", "other.xml"),
                                  suiteStarting("right", "robot.xml")};
    separateWorldLogs(suites);
    EXPECT_EQ(suites[0].fixtures[0].param, "--var 'a=1' --instance 'left'");
    EXPECT_EQ(suites[1].fixtures[0].param, "");  // its world's logs stay where they were
    EXPECT_EQ(suites[2].fixtures[0].param, "--instance 'right'");
}

TEST(WorldLogs, SuitesOfOneNameAreNumbered) {
    std::vector<SuiteSpec> suites{suiteStarting("robot", "robot.xml"),
                                  suiteStarting("robot", "robot.xml"),
                                  suiteStarting("robot-2", "robot.xml")};
    separateWorldLogs(suites);
    EXPECT_EQ(suites[0].fixtures[0].param, "--instance 'robot'");
    EXPECT_EQ(suites[1].fixtures[0].param, "--instance 'robot-2'");
    EXPECT_EQ(suites[2].fixtures[0].param, "--instance 'robot-2-2'");
}

TEST(WorldLogs, OtherFixturesAreLeftAlone) {
    std::vector<SuiteSpec> suites{suiteStarting("a", "f.py"), suiteStarting("b", "f.py")};
    for (auto& suite : suites) {
        suite.fixtures[0].type = "python";
    }
    separateWorldLogs(suites);
    EXPECT_EQ(suites[0].fixtures[0].param, "");
    EXPECT_EQ(suites[1].fixtures[0].param, "");
}

// Issue 38's second trial: two suites' folders each with its world.xml, both <world
// name="robot"> (or both without a name: the stem), wrote rtf-logs/robot/ both; they are one
// world by its log folder, so each suite gets its instance.
TEST(WorldLogs, WorldFilesOfOneNameAreOneWorld) {
    SuiteSpec left = suiteStarting("left", "world.xml");
    left.fixtures[0].path = "/lab/left/world.xml";
    SuiteSpec right = suiteStarting("right", "world.xml");
    right.fixtures[0].path = "/lab/right/world.xml";
    std::vector<SuiteSpec> suites{left, right, suiteStarting("alone", "other.xml")};
    separateWorldLogs(suites);
    EXPECT_EQ(suites[0].fixtures[0].param, "--instance 'left'");
    EXPECT_EQ(suites[1].fixtures[0].param, "--instance 'right'");
    EXPECT_EQ(suites[2].fixtures[0].param, "");
}
