#include <cstring>

#include <gtest/gtest.h>

#include <robottestingframework/Arguments.h>

using robottestingframework::Arguments;
using robottestingframework::ArgumentVector;
using Words = std::vector<std::string>;

TEST(Arguments, SplitsOnAnyWhitespace) {
    EXPECT_EQ(Arguments::split("  --a 1\t--b\n2  "), (Words{"--a", "1", "--b", "2"}));
}

TEST(Arguments, EmptyLineHasNoWords) {
    EXPECT_TRUE(Arguments::split("   ").empty());
}

TEST(Arguments, DoubleQuotesKeepSpaces) {
    EXPECT_EQ(Arguments::split("--name \"left arm\" x"), (Words{"--name", "left arm", "x"}));
}

TEST(Arguments, SingleQuotesAreLiteral) {
    EXPECT_EQ(Arguments::split(R"('a \"b' c)"), (Words{R"(a \"b)", "c"}));
}

TEST(Arguments, BackslashEscapesOutsideQuotes) {
    EXPECT_EQ(Arguments::split(R"(a\ b c\"d)"), (Words{"a b", "c\"d"}));
}

TEST(Arguments, BackslashInDoubleQuotesEscapesOnlyQuoteAndBackslash) {
    EXPECT_EQ(Arguments::split(R"("x\"y\\z\n")"), (Words{R"(x"y\z\n)"}));
}

TEST(Arguments, AdjacentQuotedPartsJoinOneWord) {
    EXPECT_EQ(Arguments::split(R"(--from="a b"'c')"), (Words{"--from=a bc"}));
}

TEST(Arguments, EmptyQuotesAreAnEmptyWord) {
    EXPECT_EQ(Arguments::split(R"(a "" b)"), (Words{"a", "", "b"}));
}

TEST(Arguments, UnterminatedQuoteRunsToTheEnd) {
    EXPECT_EQ(Arguments::split("a \"b c"), (Words{"a", "b c"}));
}

TEST(Arguments, SplitInPlaceWritesPointersAndNull) {
    char line[] = "one \"two three\" four";
    char* args[8];
    ASSERT_EQ(Arguments::split(line, args, 8), 3);
    EXPECT_STREQ(args[0], "one");
    EXPECT_STREQ(args[1], "two three");
    EXPECT_STREQ(args[2], "four");
    EXPECT_EQ(args[3], nullptr);
}

TEST(Arguments, SplitInPlaceNeverWritesMoreThanMaxArgsSlots) {
    char line[] = "a b c d e";
    char* args[4] = {nullptr, nullptr, nullptr, reinterpret_cast<char*>(1)};
    ASSERT_EQ(Arguments::split(line, args, 3), 2);
    EXPECT_STREQ(args[1], "b");
    EXPECT_EQ(args[2], nullptr);
    EXPECT_EQ(args[3], reinterpret_cast<char*>(1));
}

TEST(Arguments, GetOptionReadsSpaceAndEqualsForms) {
    ArgumentVector args("test", "--robot icubSim --part=left_arm --flag");
    std::string value;
    ASSERT_TRUE(Arguments::getOption(args.argc(), args.argv(), "robot", value));
    EXPECT_EQ(value, "icubSim");
    ASSERT_TRUE(Arguments::getOption(args.argc(), args.argv(), "--part", value));
    EXPECT_EQ(value, "left_arm");
}

TEST(Arguments, GetOptionIsFalseWhenAbsent) {
    ArgumentVector args("test", "--robot icubSim");
    std::string value = "unchanged";
    EXPECT_FALSE(Arguments::getOption(args.argc(), args.argv(), "part", value));
    EXPECT_EQ(value, "unchanged");
}

TEST(Arguments, GetOptionDoesNotMatchAPrefixOfALongerName) {
    ArgumentVector args("test", "--robots 3");
    std::string value;
    EXPECT_FALSE(Arguments::getOption(args.argc(), args.argv(), "robot", value));
}

TEST(Arguments, OptionsAreFoundInArgvZeroWhereAFixtureParamStarts) {
    ArgumentVector args("--robot icubSim --flag");
    std::string value;
    ASSERT_TRUE(Arguments::getOption(args.argc(), args.argv(), "robot", value));
    EXPECT_EQ(value, "icubSim");
    EXPECT_TRUE(Arguments::hasOption(args.argc(), args.argv(), "flag"));
    EXPECT_TRUE(Arguments::hasOption(args.argc(), args.argv(), "robot"));
    EXPECT_FALSE(Arguments::hasOption(args.argc(), args.argv(), "verbose"));
}

TEST(Arguments, ParseSplitsInPlaceWithTheFirstWordInArgvZero) {
    char line[] = "MY_FIXTURE_TEST_PARAM --x 1";
    char* argv[64];
    int argc = -1;
    Arguments::parse(line, &argc, argv);
    ASSERT_EQ(argc, 3);
    EXPECT_STREQ(argv[0], "MY_FIXTURE_TEST_PARAM");
    EXPECT_STREQ(argv[1], "--x");
    EXPECT_STREQ(argv[2], "1");
    EXPECT_EQ(argv[3], nullptr);
}

TEST(ArgumentVector, AFixtureArgvHoldsTheParamWordsOnly) {
    ArgumentVector args("MY_FIXTURE_TEST_PARAM --x 1");
    ASSERT_EQ(args.argc(), 3);
    EXPECT_STREQ(args.argv()[0], "MY_FIXTURE_TEST_PARAM");
    EXPECT_STREQ(args.argv()[2], "1");
    EXPECT_EQ(args.argv()[3], nullptr);
    ArgumentVector none("");
    EXPECT_EQ(none.argc(), 0);
    EXPECT_EQ(none.argv()[0], nullptr);
}

TEST(ArgumentVector, FirstArgumentIsTheNameThenTheParamWords) {
    ArgumentVector args("mytest", "--a \"b c\"");
    ASSERT_EQ(args.argc(), 3);
    EXPECT_STREQ(args.argv()[0], "mytest");
    EXPECT_STREQ(args.argv()[1], "--a");
    EXPECT_STREQ(args.argv()[2], "b c");
    EXPECT_EQ(args.argv()[3], nullptr);
}

namespace {

// The words of a plug-in's argv for `param` (a fixture's layout: the param's words only).
Words pluginArgv(const std::string& param) {
    ArgumentVector args(param);
    return Words(args.argv(), args.argv() + args.argc());
}

}  // namespace

// RTF 2.0.1's own runner gave a plug-in these argv (tests/e2e/test_rtf2_side_by_side.py runs
// it beside this one): spaces separate, double quotes group, nothing else is special.
TEST(ArgumentVector, BackslashesAndSingleQuotesArePlainCharactersAsInRtf2) {
    EXPECT_EQ(pluginArgv(R"(C:\robots\arm --label robot's arm --re a\d+)"),
              (Words{R"(C:\robots\arm)", "--label", "robot's", "arm", "--re", R"(a\d+)"}));
}

TEST(ArgumentVector, DoubleQuotesGroupAndEndTheWordBeforeThemAsInRtf2) {
    EXPECT_EQ(pluginArgv(R"(--name "my robot" a"b c"d)"),
              (Words{"--name", "my robot", "a", "b c", "d"}));
    EXPECT_EQ(pluginArgv(R"("quoted \"inner\" end")"), (Words{R"(quoted \)", R"(inner\)", " end"}));
    EXPECT_EQ(pluginArgv(R"("unterminated x)"), (Words{"unterminated x"}));
}

TEST(ArgumentVector, OnlySpacesSeparateAndEmptyWordsAreDroppedAsInRtf2) {
    EXPECT_EQ(pluginArgv("  --x\t1  \"\" --empty \"\"  "), (Words{"--x\t1", "--empty"}));
}

TEST(Arguments, ParseSplitsByRtf2sRulesInPlace) {
    char line[] = R"(C:\robots\arm "my robot" it's)";
    char* argv[64];
    int argc = -1;
    Arguments::parse(line, &argc, argv);
    ASSERT_EQ(argc, 3);
    EXPECT_STREQ(argv[0], R"(C:\robots\arm)");
    EXPECT_STREQ(argv[1], "my robot");
    EXPECT_STREQ(argv[2], "it's");
    EXPECT_EQ(argv[3], nullptr);
}
