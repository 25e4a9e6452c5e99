// Reading what the command line names (cli/command_line_suites.h): --test files and --tests folders
// as one suite, then the --suite files and the suites of --suites folders, and the --var-file /
// --var variables they see.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "build_paths.h"
#include "runner/cli/command_line_suites.h"
#include "runner/suites/suite_file.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

class TestSources : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("test_sources_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text = "") {
        const fs::path path = dir_ / name;
        fs::create_directories(path.parent_path());
        std::ofstream(path) << text;
        return path.string();
    }
    std::string folder(const std::string& name) {
        fs::create_directories(dir_ / name);
        return (dir_ / name).string();
    }
    std::string suiteFile(const std::string& name, const std::string& suiteName) {
        return write(name, "<suite name=\"" + suiteName + "\">\n  <test>" + suiteName +
                               "_test.lua</test>\n</suite>\n");
    }
    std::vector<std::string> pluginsOf(const SuiteSpec& suite) {
        std::vector<std::string> plugins;
        for (const auto& test : suite.tests) {
            plugins.push_back(fs::path(test.plugin.str()).lexically_relative(dir_).string());
        }
        return plugins;
    }

    fs::path dir_;
};

std::vector<std::string> namesOf(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> names;
    for (const auto& suite : suites) {
        names.push_back(suite.name);
    }
    return names;
}

}  // namespace

TEST_F(TestSources, TestFilesGivenOneByOneAreOneSuiteInTheirOrder) {
    Options options;
    options.tests = {write("b.py"), write("a.lua")};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(suites[0].name, commandLineSuiteName);
    EXPECT_EQ(pluginsOf(suites[0]), (std::vector<std::string>{"b.py", "a.lua"}));
    // --repetition applies to them (0: not their own).
    EXPECT_EQ(suites[0].tests[0].repetition, 0u);
    EXPECT_TRUE(warnings.empty());
}

TEST_F(TestSources, ATestsFolderGivesItsTestFilesSortedWithoutHiddenOrOtherFiles) {
    write("tests/b.py");
    write("tests/a.lua");
    write("tests/notes.txt");
    write("tests/.hidden.lua");
    write("tests/sub/c.lua");
    Options options;
    options.testDirs = {folder("tests")};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(pluginsOf(suites[0]), (std::vector<std::string>{"tests/a.lua", "tests/b.py"}));
}

TEST_F(TestSources, RecursiveDescendsIntoSubFoldersButNotHiddenOnes) {
    write("tests/a.lua");
    write("tests/sub/c.lua");
    write("tests/.git/d.lua");
    Options options;
    options.testDirs = {folder("tests")};
    options.recursive = true;
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(pluginsOf(suites[0]), (std::vector<std::string>{"tests/a.lua", "tests/sub/c.lua"}));
}

TEST_F(TestSources, AnExecutableFileIsATestFile) {
    const std::string exec = write("tests/run_me");
    ::chmod(exec.c_str(), 0755);
    write("tests/not_me");
    Options options;
    options.testDirs = {folder("tests")};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(pluginsOf(suites[0]), (std::vector<std::string>{"tests/run_me"}));
}

TEST_F(TestSources, ATestsFolderPassesOverLibrariesThatAreNoTestPluginsWithAWarning) {
    // As RTF 2.x ran a build folder: its test plug-ins, not its fixture plug-ins or other
    // libraries.
    write("tests/libarm_test.so", std::string("ELF\0robottestingframework_dll_factory\0", 38));
    write("tests/librobot_fixture.so",
          std::string("ELF\0robottestingframework_fixture_factory\0", 42));
    write("tests/librobot_helper.so", std::string("ELF\0robot_helper_answer\0", 24));
    write("tests/a.lua");
    Options options;
    options.testDirs = {folder("tests")};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(pluginsOf(suites[0]),
              (std::vector<std::string>{"tests/a.lua", "tests/libarm_test.so"}));
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("librobot_fixture.so: warning: a fixture plug-in, not a test"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[1].find("librobot_helper.so: warning: not a test plug-in"),
              std::string::npos)
        << warnings[1];
}

TEST_F(TestSources, AFixturePluginNamedWithTestIsStillATest) {
    // Named one by one it runs, and fails saying what it is (RTF 2.x exited 1 as well).
    Options options;
    options.tests = {write("librobot_fixture.so",
                           std::string("ELF\0robottestingframework_fixture_factory\0", 42))};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    EXPECT_EQ(suites[0].tests.size(), 1u);
    EXPECT_TRUE(warnings.empty());
}

TEST_F(TestSources, ATestsFolderWithoutTestFilesWarnsAndAddsNoSuite) {
    write("tests/notes.txt");
    Options options;
    options.testDirs = {folder("tests")};
    std::vector<std::string> warnings;
    EXPECT_TRUE(readSources(options, warnings).empty());
    EXPECT_EQ(warnings, (std::vector<std::string>{options.testDirs[0] +
                                                  ": warning: no test files in this folder"}));
}

TEST_F(TestSources, ASuitesFolderWithoutSuiteFilesWarns) {
    write("suites/readme.md");
    Options options;
    options.suiteDirs = {folder("suites")};
    std::vector<std::string> warnings;
    EXPECT_TRUE(readSources(options, warnings).empty());
    EXPECT_EQ(warnings,
              (std::vector<std::string>{options.suiteDirs[0] +
                                        ": warning: no suite files (*.xml) in this folder"}));
}

TEST_F(TestSources, TheCommandLineTestsComeFirstThenSuiteFilesThenSuitesFolders) {
    suiteFile("suites/b.xml", "bee");
    suiteFile("suites/a.xml", "ay");
    write("suites/.hidden.xml", "not xml at all");
    Options options;
    options.suiteDirs = {folder("suites")};
    options.suites = {suiteFile("one.xml", "one")};
    options.tests = {write("t.lua")};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    EXPECT_EQ(namesOf(suites), (std::vector<std::string>{"tests", "one", "ay", "bee"}));
}

TEST_F(TestSources, AFolderThatIsNotOneIsAnErrorNamingIt) {
    Options options;
    options.testDirs = {write("file.lua")};
    std::vector<std::string> warnings;
    try {
        readSources(options, warnings);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), options.testDirs[0] + ": not a folder");
    }
}

TEST_F(TestSources, AMalformedSuiteFileIsAnErrorNamingIt) {
    Options options;
    options.suites = {write("bad.xml", "<suite>\n<nonsense/>\n</suite>\n")};
    std::vector<std::string> warnings;
    try {
        readSources(options, warnings);
        FAIL() << "no error";
    } catch (const SuiteFileError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(options.suites[0] + ":2:", 0), 0u) << e.what();
    }
}

TEST_F(TestSources, VarFilesComeInOrderThenTheVarOptions) {
    Options options;
    options.variableFiles = {write("one.env", "robot=first\n# a comment\nspeed=1\n"),
                             write("two.env", "robot=second\n")};
    options.variables = {{"robot", "third"}};
    const auto found = commandLineVariables(options);
    ASSERT_EQ(found.size(), 4u);
    EXPECT_EQ(found[0].value, "first");
    EXPECT_EQ(found[1].name, "speed");
    EXPECT_EQ(found[2].value, "second");
    EXPECT_EQ(found[3].value, "third");
    EXPECT_EQ(found[3].origin, "--var");
}

TEST_F(TestSources, ABadVarFileIsAnErrorEvenWhenNoSuiteReadsIt) {
    Options options;
    options.variableFiles = {write("bad.env", "robot=icub\nno value here\n")};
    options.tests = {write("t.lua")};
    std::vector<std::string> warnings;
    try {
        readSources(options, warnings);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--var-file " + options.variableFiles[0] + ":2", 0),
                  0u)
            << e.what();
    }
}

TEST_F(TestSources, TheSuitesSeeTheCommandLinesVariables) {
    Options options;
    options.suites = {write("s.xml",
                            "<suite name=\"s\">\n  <test param=\"--robot ${robot}\">t.lua</test>\n"
                            "</suite>\n")};
    options.variables = {{"robot", "icubSim"}};
    std::vector<std::string> warnings;
    const auto suites = readSources(options, warnings);
    ASSERT_EQ(suites.size(), 1u);
    ASSERT_EQ(suites[0].tests.size(), 1u);
    EXPECT_EQ(suites[0].tests[0].param, "--robot icubSim");
}

// Issue 38's second trial: the tutorial's folder holds suite.xml beside its world.xml, and a
// run with -o junit:lab.xml leaves lab.xml there; `--suites .` then stopped with exit 2 at
// "the root element is <world>" (or <testsuites>). A --suites folder passes over XML files
// whose root says they are another format this runner reads or writes; any other root is
// passed over with a warning (RTF 2.x passed it over: a robot's XML configuration beside the
// suites), a malformed file is an error, and a file named with --suite is read whatever it
// holds.
TEST_F(TestSources, ASuitesFolderPassesOverWorldFilesAndJUnitReports) {
    suiteFile("suites/suite.xml", "lab");
    write("suites/world.xml",
          "<?xml version=\"1.0\"?>\n<!-- a world -->\n<world name=\"lab\">\n"
          "  <process name=\"p\" command=\"true\"/>\n</world>\n");
    write("suites/lab.xml",
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"1\">"
          "<testsuite name=\"lab\"/></testsuites>\n");
    write("suites/one.xml", "<testsuite name=\"x\" tests=\"0\"/>\n");
    Options options;
    options.suiteDirs = {folder("suites")};
    std::vector<std::string> warnings;
    EXPECT_EQ(namesOf(readSources(options, warnings)), (std::vector<std::string>{"lab"}));
    EXPECT_TRUE(warnings.empty());

    write("suites/typo.xml", "<suiet name=\"x\"/>\n");
    write("suites/icub.xml", "<?xml version=\"1.0\"?>\n<robot name=\"icub\"><part/></robot>\n");
    EXPECT_EQ(namesOf(readSources(options, warnings)), (std::vector<std::string>{"lab"}));
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("icub.xml: warning: the root element is <robot>, not <suite>: "
                               "passed over"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[1].find("typo.xml: warning: the root element is <suiet>"), std::string::npos)
        << warnings[1];
    write("suites/broken.xml", "<suite name=\"x\">\n  <test>a.lua</test>\n");
    EXPECT_THROW(readSources(options, warnings), SuiteFileError);
    Options named;
    named.suites = {(dir_ / "suites" / "world.xml").string()};
    EXPECT_THROW(readSources(named, warnings), SuiteFileError);
}
