// The one expander of ${...} (src/variables): precedence, escapes, cycles, errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "variables/variables.h"

using namespace robottestingframework::variables;

namespace {

VariableTable table(std::initializer_list<Variable> variables) {
    VariableTable result;
    for (const auto& variable : variables) {
        result.define(variable);
    }
    return result;
}

ExpandError expandError(VariableTable& variables, const std::string& text) {
    try {
        variables.expand(text);
    } catch (const ExpandError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for " << text;
    return {};
}

}  // namespace

TEST(Variables, AStrongerSourceWinsWhateverTheOrder) {
    VariableTable variables = table({{"robot", "cli", Source::CommandLine, "--var"},
                                     {"robot", "suite", Source::Suite, "s.xml:2"},
                                     {"port", "1", Source::VarFile, "a.env:1"},
                                     {"port", "2", Source::VarFile, "b.env:1"},
                                     {"port", "3", Source::WorldFile, "w.xml:3"}});
    EXPECT_EQ(variables.expand("${robot}:${port}"), "cli:2");  // a later --var-file wins
    EXPECT_EQ(variables.find("robot")->origin, "--var");
}

TEST(Variables, ValuesUseOtherVariablesDefinedLater) {
    VariableTable variables = table(
        {{"name", "/${robot}/state", Source::Suite, ""}, {"robot", "icubSim", Source::Suite, ""}});
    EXPECT_EQ(variables.valueOf("name"), "/icubSim/state");
}

TEST(Variables, BothEscapesWriteALiteralDollarBrace) {
    VariableTable variables;
    EXPECT_EQ(variables.expand("$${a} ${{b} $x {}"), "${a} ${b} $x {}");
    EXPECT_EQ(variables.expand(escape("keep ${this} and $${that}")), "keep ${this} and $${that}");
}

TEST(Variables, CopiesTheTextAroundUsesAndLoneDollarsAsItIs) {
    VariableTable variables = table({{"a", "A", Source::Suite, ""}});
    EXPECT_EQ(variables.expand(""), "");
    EXPECT_EQ(variables.expand("no use at all"), "no use at all");
    EXPECT_EQ(variables.expand("${a}"), "A");
    EXPECT_EQ(variables.expand("$"), "$");
    EXPECT_EQ(variables.expand("x$"), "x$");
    EXPECT_EQ(variables.expand("$$$${a}$"), "$$${a}$");
    EXPECT_EQ(variables.expand("before ${a} $ between ${a}${a} after$"),
              "before A $ between AA after$");
}

TEST(Variables, ReadsTheEnvironment) {
    ::setenv("RTF_VARIABLES_TEST", "here", 1);
    ::unsetenv("RTF_VARIABLES_TEST_UNSET");
    VariableTable variables;
    EXPECT_EQ(variables.expand("${env:RTF_VARIABLES_TEST}"), "here");
    EXPECT_EQ(expandError(variables, "${env:RTF_VARIABLES_TEST_UNSET}").kind,
              ExpandError::Kind::EnvironmentUnset);
}

TEST(Variables, NamesTheCycleOfAVariableThatRefersToItself) {
    VariableTable variables = table({{"a", "x${b}", Source::Suite, ""},
                                     {"b", "${c}", Source::Suite, ""},
                                     {"c", "${a}", Source::Suite, ""}});
    ExpandError error = expandError(variables, "${a}");
    EXPECT_EQ(error.kind, ExpandError::Kind::Cycle);
    EXPECT_NE(error.message.find("a -> b -> c -> a"), std::string::npos) << error.message;
}

TEST(Variables, SuggestsTheDefinedNamesCloseToAnUndefinedOne) {
    VariableTable variables =
        table({{"robot_port", "1", Source::Suite, ""}, {"camera", "2", Source::Suite, ""}});
    ExpandError error = expandError(variables, "port ${robot_prot}");
    EXPECT_EQ(error.kind, ExpandError::Kind::Undefined);
    EXPECT_EQ(error.name, "robot_prot");
    EXPECT_NE(error.message.find("did you mean ${robot_port}?"), std::string::npos)
        << error.message;
    EXPECT_EQ(error.message.find("camera"), std::string::npos) << error.message;
}

TEST(Variables, ThrowsOnAnUnterminatedBraceWithItsColumn) {
    VariableTable variables;
    ExpandError error = expandError(variables, "ab ${x");
    EXPECT_EQ(error.kind, ExpandError::Kind::Unterminated);
    EXPECT_NE(error.message.find("column 4"), std::string::npos) << error.message;
}

TEST(Variables, CapsWhatOneValueGrowsTo) {
    VariableTable variables = table({{"v0", std::string(1000, 'x'), Source::Suite, ""}});
    for (int level = 1; level <= 4; ++level) {
        std::string value;
        for (int i = 0; i < 10; ++i) {
            value += "${v" + std::to_string(level - 1) + "}";
        }
        variables.define({"v" + std::to_string(level), value, Source::Suite, ""});
    }
    EXPECT_EQ(variables.valueOf("v3").size(), 1000000u);
    EXPECT_EQ(expandError(variables, "${v4}").kind, ExpandError::Kind::TooLong);
}

TEST(Variables, ParsesAnAssignmentAndPointsAtWhatIsWrong) {
    std::string name;
    std::string value;
    std::string error;
    ASSERT_TRUE(parseAssignment("robot=icub=sim", name, value, error)) << error;
    EXPECT_EQ(name, "robot");
    EXPECT_EQ(value, "icub=sim");
    EXPECT_FALSE(parseAssignment("robot", name, value, error));
    EXPECT_NE(error.find("no '='"), std::string::npos) << error;
    EXPECT_FALSE(parseAssignment("=x", name, value, error));
    EXPECT_NE(error.find("no name"), std::string::npos) << error;
    EXPECT_FALSE(parseAssignment("ro bot=x", name, value, error));
    EXPECT_NE(error.find("' ' at column 3"), std::string::npos) << error;
}

TEST(Variables, ReadsAVariableFileWithCommentsAndNamesABadLine) {
    const std::string path = ::testing::TempDir() + "rtf_variables_test.env";
    {
        std::ofstream out(path);
        out << "# the robot\n\nrobot = icubSim \n  port=10001\r\n";
    }
    std::vector<Variable> found;
    std::string error;
    ASSERT_TRUE(readVariableFile(path, found, error)) << error;
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].value, "icubSim");
    EXPECT_EQ(found[1].value, "10001");
    EXPECT_EQ(found[1].origin, path + ":4");
    {
        std::ofstream out(path);
        out << "robot=a\nnot an assignment\n";
    }
    EXPECT_FALSE(readVariableFile(path, found, error));
    EXPECT_NE(error.find(path + ":2: no '='"), std::string::npos) << error;
    std::remove(path.c_str());
}

// The stream entry point (the fuzz target's) reads as the file does.
TEST(Variables, ReadsVariablesFromAStreamNamingTheLineOfAnError) {
    std::istringstream in("# c\nrobot = icubSim\n\nbad line\n");
    std::vector<Variable> found;
    std::string error;
    EXPECT_FALSE(readVariables(in, "vars.env", found, error));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].origin, "vars.env:2");
    EXPECT_NE(error.find("vars.env:4: no '='"), std::string::npos) << error;
}
