// A test's id (runner/model/test_id.h): made from the suite file alone, one per test.
#include <gtest/gtest.h>

#include <filesystem>

#include "runner/model/test_id.h"

using namespace robottestingframework::runner;

namespace {

TestSpec test(const std::string& plugin, const std::string& param = "",
              const std::string& name = "") {
    TestSpec spec;
    spec.plugin = plugin;
    spec.param = param;
    spec.name = name;
    return spec;
}

std::vector<std::string> idsOf(std::vector<TestSpec> tests, const std::string& folder = "suites") {
    SuiteSpec suite;
    suite.name = "arm";
    suite.tests = std::move(tests);
    assignTestIds(suite, folder);
    std::vector<std::string> ids;
    for (const auto& spec : suite.tests) {
        ids.push_back(testId(suite, spec));
    }
    return ids;
}

}  // namespace

TEST(TestId, IsThePluginAsWrittenMadeLexicallyNormal) {
    EXPECT_EQ(pluginIdPart("tests/../tests/arith.lua", "suites"), "tests/arith.lua");
    EXPECT_EQ(pluginIdPart("./a/./b.py", "suites"), "a/b.py");
    EXPECT_EQ(pluginIdPart("a//b.py", "suites"), "a/b.py");
    EXPECT_EQ(pluginIdPart("ArmTest", "suites"), "ArmTest");
}

TEST(TestId, APathBesideTheSuiteFolderIsSaidFromTheFolderTheyShare) {
    // No ".." in an id: "../tests/x" of a suite in suites/ is said from their common folder.
    EXPECT_EQ(pluginIdPart("../tests/arith.lua", "suites"), "tests/arith.lua");
    EXPECT_EQ(pluginIdPart("../../lab/tests/arm.py", "proj/suites"), "lab/tests/arm.py");
    EXPECT_EQ(pluginIdPart("./../tests/../tests/arith.lua", "suites"), "tests/arith.lua");
    // Out and back in is inside.
    EXPECT_EQ(pluginIdPart("../suites/arith.lua", "proj/suites"), "arith.lua");
    EXPECT_EQ(pluginIdPart("../suites/arith.lua", "proj/suites/"), "arith.lua");
}

TEST(TestId, APathBesideTheSuiteFolderKeepsItsIdUniqueInTheSuite) {
    EXPECT_EQ(idsOf({test("tests/gripper.py"), test("../tests/gripper.py")}),
              (std::vector<std::string>{"arm/tests/gripper.py", "arm/tests/gripper.py[2]"}));
}

TEST(TestId, AnAbsolutePathBelowTheSuiteFolderIsMadeRelativeToIt) {
    const std::string folder = std::filesystem::current_path().string() + "/proj/suites";
    EXPECT_EQ(pluginIdPart(folder + "/tests/../tests/arm.py", "proj/suites"), "tests/arm.py");
    EXPECT_EQ(pluginIdPart(folder + "/arm.py", folder + "/"), "arm.py");
}

TEST(TestId, AnAbsolutePathElsewhereKeepsOnlyItsFileName) {
    EXPECT_EQ(pluginIdPart("/tmp/proj/build/libArmTest.so", "suites"), "libArmTest.so");
    EXPECT_EQ(pluginIdPart("/tmp/proj/suites-other/x.lua", "/tmp/proj/suites"), "x.lua");
}

TEST(TestId, IsTheSuiteThenTheNameWhenTheSuiteGivesOne) {
    EXPECT_EQ(idsOf({test("/abs/build/libArm.so", "", "gripper"), test("tests/arith.lua")}),
              (std::vector<std::string>{"arm/gripper", "arm/tests/arith.lua"}));
}

TEST(TestId, SaysTheParamOnlyWhenOnePluginRunsWithSeveralParams) {
    EXPECT_EQ(idsOf({test("my.so", "--fast"), test("my.so", "--slow  --x\n1"), test("my.so"),
                     test("other.so", "--fast")}),
              (std::vector<std::string>{"arm/my.so[--fast]", "arm/my.so[--slow --x 1]", "arm/my.so",
                                        "arm/other.so"}));
}

TEST(TestId, NumbersASecondTestOfTheSameIdFromTwo) {
    EXPECT_EQ(
        idsOf({test("a.py"), test("a.py"), test("a.py", "", "a.py"), test("b.py", "", "x"),
               test("c.py", "", "x")}),
        (std::vector<std::string>{"arm/a.py", "arm/a.py[2]", "arm/a.py[3]", "arm/x", "arm/x[2]"}));
}

TEST(TestId, NeverRepeatsEvenWhenAParamLooksLikeANumber) {
    EXPECT_EQ(
        idsOf({test("a.py", "2"), test("a.py"), test("a.py"), test("a.py", "", "a.py[2]")}),
        (std::vector<std::string>{"arm/a.py[2]", "arm/a.py", "arm/a.py[3]", "arm/a.py[2][2]"}));
}

TEST(TestId, NumbersTheRunsOfOnePluginInOrderSkippingNumbersANameTook) {
    // The numbering goes on from the last number given (not from 2 again for each run), and
    // passes over an id a test's name= already took.
    std::vector<TestSpec> tests{test("p.so", "", "p.so[3]"), test("p.so")};
    std::vector<std::string> expected{"arm/p.so[3]", "arm/p.so"};
    for (unsigned int k = 2; k <= 1000; ++k) {
        tests.push_back(test("p.so"));
        expected.push_back("arm/p.so[" + std::to_string(k < 3 ? k : k + 1) + "]");
    }
    tests.push_back(test("p.so"));
    expected.push_back("arm/p.so[1002]");
    EXPECT_EQ(idsOf(tests), expected);
}

namespace {

SuiteSpec suiteOf(const std::string& name, const std::string& file, std::vector<TestSpec> tests) {
    SuiteSpec suite;
    suite.name = name;
    suite.where.file = file;
    suite.where.line = 1;
    for (auto& spec : tests) {
        spec.where.file = file;
        spec.where.line = 2;
    }
    suite.tests = std::move(tests);
    assignTestIds(suite, std::filesystem::path(file).parent_path().string());
    return suite;
}

std::vector<std::string> allIds(const std::vector<SuiteSpec>& suites) {
    std::vector<std::string> ids;
    for (const auto& suite : suites) {
        for (const auto& spec : suite.tests) {
            ids.push_back(testId(suite, spec));
        }
    }
    return ids;
}

}  // namespace

TEST(TestId, TwoSuiteFilesOfOneNameAreQualifiedByTheirPaths) {
    std::vector<SuiteSpec> suites{suiteOf("arm", "suites/left/arm.xml", {test("t.py")}),
                                  suiteOf("arm", "suites/right/arm.xml", {test("t.py")}),
                                  suiteOf("leg", "suites/leg.xml", {test("t.py")})};
    EXPECT_EQ(makeIdsUniqueAcrossSuites(suites), "");
    EXPECT_EQ(allIds(suites), (std::vector<std::string>{"arm[left/arm.xml]/t.py",
                                                        "arm[right/arm.xml]/t.py", "leg/t.py"}));
}

TEST(TestId, ASuiteNameAndATestPathThatJoinToOneIdAreQualified) {
    std::vector<SuiteSpec> suites{suiteOf("a", "x.xml", {test("b/c.py")}),
                                  suiteOf("a/b", "y.xml", {test("c.py")})};
    EXPECT_EQ(makeIdsUniqueAcrossSuites(suites), "");
    EXPECT_EQ(allIds(suites), (std::vector<std::string>{"a[x.xml]/b/c.py", "a/b[y.xml]/c.py"}));
}

TEST(TestId, SuitesWhoseIdsDifferKeepTheirNames) {
    std::vector<SuiteSpec> suites{suiteOf("arm", "left/arm.xml", {test("a.py")}),
                                  suiteOf("arm", "right/arm.xml", {test("b.py")})};
    EXPECT_EQ(makeIdsUniqueAcrossSuites(suites), "");
    EXPECT_EQ(allIds(suites), (std::vector<std::string>{"arm/a.py", "arm/b.py"}));
}

TEST(TestId, TheCopiesOfOneSuiteFileGivenTwiceAreNumbered) {
    std::vector<SuiteSpec> suites{
        suiteOf("arm", "arm.xml", {test("t.py")}), suiteOf("arm", "./arm.xml", {test("t.py")}),
        suiteOf("arm", "other/arm.xml", {test("t.py")}), suiteOf("arm", "arm.xml", {test("t.py")})};
    EXPECT_EQ(makeIdsUniqueAcrossSuites(suites), "");
    EXPECT_EQ(allIds(suites),
              (std::vector<std::string>{"arm[arm.xml]/t.py", "arm[arm.xml][2]/t.py",
                                        "arm[other/arm.xml]/t.py", "arm[arm.xml][3]/t.py"}));
    std::vector<SuiteSpec> copies{suiteOf("robot", "robot/robot.xml", {test("t.py")}),
                                  suiteOf("robot", "robot/robot.xml", {test("t.py")})};
    EXPECT_EQ(makeIdsUniqueAcrossSuites(copies), "");
    EXPECT_EQ(allIds(copies), (std::vector<std::string>{"robot/t.py", "robot[2]/t.py"}));
}

TEST(TestId, IdsStillSharedAfterQualifyingAreAnErrorNamingBothPlaces) {
    // Suite "a[x.xml]" (written so) beside the suite "a" of x.xml and "a" of y.xml.
    std::vector<SuiteSpec> suites{suiteOf("a", "x.xml", {test("t.py")}),
                                  suiteOf("a", "y.xml", {test("t.py")}),
                                  suiteOf("a[x.xml]", "z.xml", {test("t.py")})};
    const std::string error = makeIdsUniqueAcrossSuites(suites);
    EXPECT_NE(error.find("two tests have the id a[x.xml]/t.py: x.xml:2 and z.xml:2"),
              std::string::npos)
        << error;
}
