// Reading suite files: what is accepted, and that every error names file:line and the fix.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "runner/suites/suite_file.h"

using robottestingframework::runner::parseSuite;
using robottestingframework::runner::parseTestFile;
using robottestingframework::runner::readSuiteFile;
using robottestingframework::runner::SuiteFileError;
using robottestingframework::runner::SuiteSpec;

namespace {

SuiteSpec parse(const std::string& text, std::vector<std::string>* warnings = nullptr) {
    std::vector<std::string> ignored;
    return parseSuite(text, "/nowhere/suite.xml", warnings != nullptr ? *warnings : ignored);
}

// The error text parsing `text` gives; empty when it parses.
std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const SuiteFileError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(SuiteFile, ReadsEveryElementInDocumentOrder) {
    SuiteSpec suite = parse(R"(<?xml version="1.0"?>
<suite name="arm tests">
  <description> free text </description>
  <environment>--robot icubSim</environment>
  <timeout>30</timeout>
  <fixture param="--from sim.ini">libsimfixture.so</fixture>
  <fixture type="python">second.py</fixture>
  <test type="dll" param="--part left_arm">libmotortest.so</test>
  <test repetition="5" name="enc" timeout="2.5" depends="a, b" tags="arm,slow">checks/encoders.lua</test>
  <test>
     checks/camera.py
  </test>
</suite>)");
    EXPECT_EQ(suite.name, "arm tests");
    EXPECT_EQ(suite.description, "free text");
    EXPECT_EQ(suite.environment, "--robot icubSim");
    EXPECT_DOUBLE_EQ(suite.timeout, 30);
    ASSERT_EQ(suite.fixtures.size(), 2u);
    EXPECT_EQ(suite.fixtures[0].plugin, "libsimfixture.so");
    EXPECT_EQ(suite.fixtures[0].param, "--from sim.ini");
    EXPECT_EQ(suite.fixtures[1].type, "python");
    ASSERT_EQ(suite.tests.size(), 3u);
    EXPECT_EQ(suite.tests[0].type, "dll");
    EXPECT_EQ(suite.tests[0].param, "--part left_arm");
    EXPECT_EQ(suite.tests[0].where.line, 8u);
    EXPECT_EQ(suite.tests[1].repetition, 5u);
    EXPECT_EQ(suite.tests[1].name, "enc");
    EXPECT_DOUBLE_EQ(suite.tests[1].timeout, 2.5);
    EXPECT_EQ(suite.tests[1].depends, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(suite.tests[1].tags, (std::vector<std::string>{"arm", "slow"}));
    EXPECT_EQ(suite.tests[2].plugin, "checks/camera.py");
    EXPECT_EQ(suite.tests[2].repetition, 0u) << "not given: left to --repetition";
}

TEST(SuiteFile, UnresolvedPluginLeavesPathEmpty) {
    SuiteSpec suite = parse("<suite name='s'><test>no_such_plugin_anywhere</test></suite>");
    ASSERT_EQ(suite.tests.size(), 1u);
    EXPECT_TRUE(suite.tests[0].path.empty());
}

TEST(SuiteFile, NameDefaultsToTheFileStem) {
    EXPECT_EQ(parse("<suite><test>x.so</test></suite>").name, "suite");
}

TEST(SuiteFile, OldSuitRootIsAcceptedWithAWarningNamingTheFile) {
    std::vector<std::string> warnings;
    SuiteSpec suite = parse("<suit name='old'>\n<test>x.so</test></suit>", &warnings);
    EXPECT_EQ(suite.name, "old");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("/nowhere/suite.xml:1"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("suit"), std::string::npos);
}

TEST(SuiteFile, MalformedXmlNamesTheLine) {
    std::string error = errorOf("<suite name='s'>\n<test>a.so</test>\n<test>b.so</tset>\n</suite>");
    EXPECT_EQ(error.rfind("/nowhere/suite.xml:3: malformed XML", 0), 0u) << error;
}

TEST(SuiteFile, EmptyDocumentIsAnError) {
    EXPECT_NE(errorOf("").find("/nowhere/suite.xml:1:"), std::string::npos);
}

TEST(SuiteFile, WrongRootIsAnError) {
    std::string error = errorOf("<tests/>");
    EXPECT_NE(error.find(":1: the root element is <tests>"), std::string::npos) << error;
}

TEST(SuiteFile, UnknownElementNamesItAndWhatIsExpected) {
    std::string error = errorOf("<suite>\n\n<tset>a.so</tset>\n</suite>");
    EXPECT_NE(error.find("suite.xml:3: unknown element <tset>"), std::string::npos) << error;
    EXPECT_NE(error.find("test"), std::string::npos);
}

TEST(SuiteFile, UnknownAttributeIsAnError) {
    std::string error = errorOf("<suite>\n<test parm='x'>a.so</test>\n</suite>");
    EXPECT_NE(error.find("suite.xml:2: unknown attribute 'parm' on <test>"), std::string::npos)
        << error;
    EXPECT_NE(errorOf("<suite nme='x'/>").find("unknown attribute 'nme'"), std::string::npos);
    EXPECT_NE(errorOf("<suite><fixture repetition='2'>f.so</fixture></suite>")
                  .find("unknown attribute 'repetition' on <fixture>"),
              std::string::npos);
}

TEST(SuiteFile, NetworkIsPrivateOrHost) {
    EXPECT_EQ(parse("<suite><test>a.so</test></suite>").network, SuiteSpec::Network::Host);
    EXPECT_EQ(parse("<suite network='private'><test>a.so</test></suite>").network,
              SuiteSpec::Network::Private);
    EXPECT_EQ(parse("<suite network=' host '><test>a.so</test></suite>").network,
              SuiteSpec::Network::Host);
    for (const char* bad : {"Private", "none", "", "bridge"}) {
        std::string error =
            errorOf(std::string("<suite\n network='") + bad + "'><test>a.so</test></suite>");
        EXPECT_NE(error.find(std::string("suite.xml:1: network=\"") + bad +
                             "\": expected private (a network of its own) or host"),
                  std::string::npos)
            << bad << ": " << error;
    }
}

TEST(SuiteFile, RepetitionMustBeAPositiveWholeNumber) {
    for (const char* bad : {"abc", "0", "-1", "2.5", "", "3x", "99999999999999"}) {
        std::string error =
            errorOf(std::string("<suite>\n<test repetition='") + bad + "'>a.so</test></suite>");
        EXPECT_NE(error.find("suite.xml:2: repetition="), std::string::npos)
            << bad << ": " << error;
    }
    EXPECT_EQ(parse("<suite><test repetition=' 7 '>a.so</test></suite>").tests[0].repetition, 7u);
}

TEST(SuiteFile, TimeoutMustBeANonNegativeNumber) {
    for (const char* bad : {"abc", "-1", "", "1e999", "nan"}) {
        std::string error =
            errorOf(std::string("<suite>\n<test timeout='") + bad + "'>a.so</test></suite>");
        EXPECT_NE(error.find("suite.xml:2: timeout"), std::string::npos) << bad << ": " << error;
    }
    EXPECT_NE(errorOf("<suite>\n<timeout>soon</timeout></suite>").find("suite.xml:2: <timeout>"),
              std::string::npos);
}

TEST(SuiteFile, EmptyPluginNameIsAnError) {
    std::string error = errorOf("<suite>\n<test type='dll'>   </test>\n</suite>");
    EXPECT_NE(error.find("suite.xml:2: <test> without a plug-in"), std::string::npos) << error;
    EXPECT_NE(errorOf("<suite><fixture/></suite>").find("<fixture> without a plug-in"),
              std::string::npos);
}

TEST(SuiteFile, UnknownTypeIsAnError) {
    std::string error = errorOf("<suite>\n<test type='java'>a.jar</test>\n</suite>");
    EXPECT_NE(error.find("suite.xml:2: unknown test type 'java'"), std::string::npos) << error;
    EXPECT_NE(errorOf("<suite><fixture type='lua'>f.lua</fixture></suite>")
                  .find("unknown fixture type 'lua'"),
              std::string::npos);
}

TEST(SuiteFile, ElementsInsideATestAreAnError) {
    std::string error = errorOf("<suite>\n<test>a.so<param>x</param></test>\n</suite>");
    EXPECT_NE(error.find("suite.xml:2: <param> inside <test>"), std::string::npos) << error;
}

TEST(SuiteFile, StrayTextAndDuplicatesAreErrors) {
    EXPECT_NE(errorOf("<suite>\nliba.so\n</suite>").find("directly inside <suite>"),
              std::string::npos);
    EXPECT_NE(errorOf("<suite><description>a</description>\n<description>b</description></suite>")
                  .find("suite.xml:2: <description> given twice"),
              std::string::npos);
}

TEST(SuiteFile, CommentsAndCdataAreFine) {
    SuiteSpec suite =
        parse("<suite><!-- a comment --><test param='--x'><![CDATA[ a&b.so ]]></test></suite>");
    ASSERT_EQ(suite.tests.size(), 1u);
    EXPECT_EQ(suite.tests[0].plugin, "a&b.so");
}

TEST(SuiteFile, MissingFileIsAnErrorNamingIt) {
    std::vector<std::string> warnings;
    try {
        robottestingframework::runner::readSuiteFile("/no/such/suite.xml", warnings);
        FAIL() << "no error";
    } catch (const SuiteFileError& e) {
        EXPECT_NE(std::string(e.what()).find("/no/such/suite.xml: cannot read"), std::string::npos)
            << e.what();
    }
}

TEST(SuiteFile, OnlyARegularFileIsReadAsASuite) {
    std::vector<std::string> warnings;
    try {
        readSuiteFile("/dev/zero", warnings);
        FAIL() << "a device was read as a suite";
    } catch (const SuiteFileError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "/dev/zero: is a character device, not a suite file (a suite file is a "
                  "regular file)");
    }
}

TEST(SuiteFile, GivesProcessFixturesEveryVariableAroundTheirOwnParam) {
    std::vector<std::string> warnings;
    using robottestingframework::variables::Source;
    SuiteSpec suite = parseSuite(R"(<suite name="s">
  <variable name="robot">icubSim</variable>
  <variable name="text">it's $${literal}</variable>
  <fixture type="process" param="--var robot=mine">world.xml</fixture>
  <fixture param="--robot ${robot}">libplain.so</fixture>
</suite>)",
                                 "/nowhere/suite.xml", warnings,
                                 {{"port", "10001", Source::CommandLine, "--var"}});
    ASSERT_EQ(suite.fixtures.size(), 2u);
    // The suite's under the fixture's own --var, the command line's over it; values escaped
    // so the world file's expander gives them back as they are.
    EXPECT_EQ(suite.fixtures[0].param,
              "--var 'robot=icubSim' --var 'text=it'\\''s $${literal}' --var robot=mine "
              "--var 'port=10001'");
    EXPECT_EQ(suite.fixtures[1].param, "--robot icubSim");
    ASSERT_EQ(suite.variables.size(), 3u);
    EXPECT_EQ(suite.variables[1].name, "robot");
    EXPECT_EQ(suite.variables[1].origin, "/nowhere/suite.xml:2");
    EXPECT_EQ(suite.variables[2].value, "it's ${literal}");
}

TEST(SuiteFile, AVariableNameMustBeAName) {
    EXPECT_NE(errorOf("<suite>\n<variable name=\"1 a\">x</variable></suite>")
                  .find("/nowhere/suite.xml:2: <variable name=\"1 a\">: a name is letters"),
              std::string::npos);
    EXPECT_NE(errorOf("<suite>\n<variable name=\"a\">x</variable>\n<variable name=\"a\">y"
                      "</variable></suite>")
                  .find(":3: <variable name=\"a\"> given twice (first at line 2)"),
              std::string::npos);
}

// The text entry point of test files (the fuzz target's): the suite's variables win over the
// file's defaults, and errors name the test file.
TEST(SuiteFile, ParsesATestFileOnItsOwnWithTheSuitesVariables) {
    using robottestingframework::variables::Source;
    std::vector<std::string> warnings;
    const auto test = parseTestFile(
        "<test param=\"--robot ${robot} --speed ${speed}\">\n"
        "  <variable name=\"robot\">default</variable><variable name=\"speed\">1</variable>\n"
        "  arm_test\n</test>\n",
        "/nowhere/tests/arm.xml", warnings, {{"robot", "icubSim", Source::Suite, "suite.xml:2"}});
    EXPECT_EQ(test.plugin, "arm_test");
    EXPECT_EQ(test.param, "--robot icubSim --speed 1");
    try {
        parseTestFile("<test>\n<fixture/></test>", "/nowhere/tests/arm.xml", warnings);
        FAIL() << "a <fixture> inside a test file's <test> was accepted";
    } catch (const SuiteFileError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nowhere/tests/arm.xml:2: <fixture>", 0), 0u)
            << e.what();
    }
}
