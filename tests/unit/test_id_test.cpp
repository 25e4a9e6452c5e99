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
    EXPECT_EQ(pluginIdPart("../tests/arith.lua", "suites"), "../tests/arith.lua");
    EXPECT_EQ(pluginIdPart("a//b.py", "suites"), "a/b.py");
    EXPECT_EQ(pluginIdPart("ArmTest", "suites"), "ArmTest");
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
