// Parametrized tests: the values, the matrix, ${NAME} substitution, the ids' labels, and a suite
// with <parametrize> read into one test per instance.
#include "runner/suites/parametrize.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/suites/suite_file.h"

using namespace robottestingframework::runner;

TEST(Parametrize, ValuesAreSplitAtCommasAndTrimmed) {
    EXPECT_EQ(parameterValues(" 10, 20 ,,30 "), (std::vector<std::string>{"10", "20", "30"}));
    EXPECT_EQ(parameterValues("--speed 10"), (std::vector<std::string>{"--speed 10"}));
    EXPECT_TRUE(parameterValues(" , ").empty());
}

TEST(Parametrize, AxesMakeEveryCombinationFirstAxisSlowest) {
    const auto instances = instancesOf({{"speed", {"10", "20"}}, {"mode", {"a", "b", "c"}}});
    ASSERT_EQ(instances.size(), 6u);
    EXPECT_EQ(instances[0], (ParameterInstance{{"speed", "10"}, {"mode", "a"}}));
    EXPECT_EQ(instances[2], (ParameterInstance{{"speed", "10"}, {"mode", "c"}}));
    EXPECT_EQ(instances[3], (ParameterInstance{{"speed", "20"}, {"mode", "a"}}));
    EXPECT_TRUE(instancesOf({{"speed", {}}}).empty());
}

TEST(Parametrize, SubstitutesOnlyTheAxes) {
    const ParameterInstance instance{{"speed", "10"}, {"mode", "a"}};
    EXPECT_EQ(substituteAxes("--speed ${speed} --robot ${robot} ${mode}${mode}", instance),
              "--speed 10 --robot ${robot} aa");
    EXPECT_EQ(substituteAxes("${speed", instance), "${speed");
    EXPECT_TRUE(usesAxis("x ${mode}", instance));
    EXPECT_FALSE(usesAxis("x ${robot} $mode", instance));
}

TEST(Parametrize, LabelsAreTheParamsWhenTheySayWhichIsWhich) {
    const auto instances = instancesOf({{"speed", {"10", "20"}}});
    EXPECT_EQ(instanceLabels({"--speed  10", "--speed\n20"}, instances),
              (std::vector<std::string>{"--speed 10", "--speed 20"}));
    EXPECT_EQ(instanceLabels({"same", "same"}, instances),
              (std::vector<std::string>{"speed=10", "speed=20"}));
    EXPECT_EQ(instanceLabels({"", ""}, instances),
              (std::vector<std::string>{"speed=10", "speed=20"}));
}

namespace {
SuiteSpec parse(const std::string& text) {
    std::vector<std::string> warnings;
    return parseSuite(text, "/nowhere/suite.xml", warnings);
}
}  // namespace

TEST(Parametrize, ASuiteGetsOneTestPerInstanceWithItsOwnId) {
    const SuiteSpec suite = parse(
        "<suite name=\"s\" tags=\"slow\"><variable name=\"robot\">sim</variable>\n"
        "<test type=\"exec\" param=\"--robot ${robot} --speed ${speed}\" tags=\"drive\">t.sh\n"
        "  <parametrize name=\"speed\">10, 20</parametrize>\n"
        "</test>\n<test type=\"exec\">t.sh</test></suite>");
    ASSERT_EQ(suite.tests.size(), 3u);
    EXPECT_EQ(suite.tests[0].param.str(), "--robot sim --speed 10");
    EXPECT_EQ(suite.tests[0].id, "t.sh[--robot sim --speed 10]");
    EXPECT_EQ(suite.tests[1].id, "t.sh[--robot sim --speed 20]");
    EXPECT_EQ(suite.tests[2].id, "t.sh");
    EXPECT_EQ(suite.tests[1].tags, (std::vector<std::string>{"drive", "slow"}));
    EXPECT_EQ(suite.tests[1].where.line, 2u);
}

TEST(Parametrize, BadInputNamesFileAndLine) {
    auto errorOf = [](const std::string& body) {
        try {
            parse("<suite name=\"s\">\n<test type=\"exec\">t.sh\n" + body + "</test></suite>");
        } catch (const SuiteFileError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(errorOf("<parametrize name=\"a\"/>").find("/nowhere/suite.xml:3: "),
              std::string::npos);
    EXPECT_NE(errorOf("<parametrize name=\"a\"/>").find("without values"), std::string::npos);
    EXPECT_NE(errorOf("<parametrize name=\"a\">1</parametrize><parametrize name=\"a\">2"
                      "</parametrize>")
                  .find("given twice"),
              std::string::npos);
    EXPECT_NE(errorOf("<parametrize name=\"\">1</parametrize>").find("a name is"),
              std::string::npos);
    EXPECT_NE(errorOf("<parametrize name=\"a\">1</parametrize><x/>").find("<x> inside <test>"),
              std::string::npos);
}
