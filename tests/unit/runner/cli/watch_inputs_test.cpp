// --watch: the files a run depends on, and the command line of each watched run.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/cli/watch_command.h"

using namespace robottestingframework::runner;

TEST(WatchInputs, TheSuiteTestFilesPluginsAndFixturesOnceEach) {
    SuiteSpec suite;
    suite.where.file = "robot/robot.xml";
    TestSpec a;
    a.where.file = "robot/robot.xml";
    a.path = "robot/t.sh";
    TestSpec b;
    b.where.file = "robot/tests/left.xml";  // a <test file="...">
    b.path = "robot/t.sh";
    TestSpec missing;  // a plug-in not found: nothing to watch
    missing.where.file = "robot/robot.xml";
    suite.tests = {a, b, missing};
    FixtureSpec fixture;
    fixture.path = "robot/world.toml";
    suite.fixtures = {fixture};
    EXPECT_EQ(watchedFiles({suite}),
              (std::vector<std::string>{"robot/robot.xml", "robot/t.sh", "robot/tests/left.xml",
                                        "robot/world.toml"}));
}

TEST(WatchInputs, TheRunIsTheCommandLineWithoutWatchAndWithTheReport) {
    char program[] = "rtf", suite[] = "--suite", file[] = "s.xml", watch[] = "--watch";
    char* argv[] = {program, suite, file, watch};
    EXPECT_EQ(watchedRunArguments(4, argv, ""),
              (std::vector<std::string>{"rtf", "--suite", "s.xml"}));
    // No output named: the default result.txt stays beside the report.
    EXPECT_EQ(watchedRunArguments(4, argv, "/tmp/w/last.xml"),
              (std::vector<std::string>{"rtf", "--suite", "s.xml", "--output", "result.txt",
                                        "--output", "junit:/tmp/w/last.xml"}));
    char output[] = "-o", junit[] = "junit:r.xml";
    char* named[] = {program, watch, output, junit};
    EXPECT_EQ(watchedRunArguments(4, named, "/tmp/w/last.xml"),
              (std::vector<std::string>{"rtf", "-o", "junit:r.xml", "--output",
                                        "junit:/tmp/w/last.xml"}));
}
