// The runner's command line: every RTF 2.x option with its short form, and usage errors.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "runner/cli/options.h"

using robottestingframework::runner::Isolation;
using robottestingframework::runner::Options;
using robottestingframework::runner::parseOptions;
using robottestingframework::runner::ParseResult;

namespace {

ParseResult parse(std::initializer_list<const char*> args, Options& options) {
    std::vector<const char*> argv{"robottestingframework-testrunner"};
    argv.insert(argv.end(), args.begin(), args.end());
    return parseOptions(static_cast<int>(argv.size()), argv.data(), options);
}

bool runs(const ParseResult& result) {
    return result.outcome == ParseResult::Outcome::Run;
}

}  // namespace

TEST(Options, ShortFormsMeanTheLongOnes) {
    Options options;
    ParseResult result =
        parse({"-t", "a.so", "-t", "b.so", "-s", "s.xml", "-r", "-p", "--part left", "-e",
               "--robot sim", "-o", "out.txt", "-w", "-d", "-v"},
              options);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(options.tests, (std::vector<std::string>{"a.so", "b.so"}));
    EXPECT_EQ(options.suites, (std::vector<std::string>{"s.xml"}));
    EXPECT_TRUE(options.recursive);
    EXPECT_EQ(options.param, "--part left");
    EXPECT_EQ(options.environment, "--robot sim");
    ASSERT_EQ(options.outputs.size(), 1u);
    EXPECT_EQ(options.outputs[0].file, "out.txt");
    EXPECT_EQ(options.outputs[0].type, "text");
    EXPECT_TRUE(options.webReporter);
    EXPECT_TRUE(options.detail);
    EXPECT_TRUE(options.verbose);
}

TEST(Options, LongForms) {
    Options options;
    ParseResult result = parse({"--test",
                                "a.so",
                                "--tests",
                                "dir",
                                "--suite",
                                "s.xml",
                                "--suites",
                                "sdir",
                                "--recursive",
                                "--param",
                                "x",
                                "--environment",
                                "y",
                                "--repetition",
                                "3",
                                "--output",
                                "r.xml",
                                "--output-type",
                                "junit",
                                "--no-summary",
                                "--web-reporter",
                                "--web-port",
                                "9000",
                                "--detail",
                                "--verbose",
                                "--isolation",
                                "none",
                                "--var",
                                "robot=icub"},
                               options);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(options.testDirs, (std::vector<std::string>{"dir"}));
    EXPECT_EQ(options.suiteDirs, (std::vector<std::string>{"sdir"}));
    EXPECT_EQ(options.repetition, 3u);
    ASSERT_EQ(options.outputs.size(), 1u);
    EXPECT_EQ(options.outputs[0].type, "junit");
    EXPECT_TRUE(options.noSummary);
    EXPECT_EQ(options.webPort, 9000);
    ASSERT_EQ(options.variables.size(), 1u);
    EXPECT_EQ(options.variables[0].first, "robot");
    EXPECT_EQ(options.variables[0].second, "icub");
}

TEST(Options, WebReporterDefaultsAndItsOwnOptions) {
    Options defaults;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "-w"}, defaults)));
    EXPECT_EQ(defaults.webPort, 8080);
    EXPECT_EQ(defaults.webHost, "127.0.0.1");
    EXPECT_EQ(defaults.webLinger, 0);
    Options options;
    ParseResult result =
        parse({"-t", "a.so", "-w", "--web-port", "0", "--web-host", "::1", "--web-linger", "2.5"},
              options);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(options.webPort, 0);
    EXPECT_EQ(options.webHost, "::1");
    EXPECT_EQ(options.webLinger, 2.5);
}

TEST(Options, ParamThatLooksLikeAnOptionIsAValue) {
    Options options;
    ParseResult result = parse({"-t", "a.so", "-p", "--robot icubSim", "-e", "-x"}, options);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(options.param, "--robot icubSim");
    EXPECT_EQ(options.environment, "-x");
    EXPECT_FALSE(options.verbose);
}

// RTF 2.x's CMake helper writes `-p ${PARAM} -e "${ENV}"`; an empty PARAM vanishes.
TEST(Options, ParamFollowedByAnOptionOfTheRunnerIsEmpty) {
    Options options;
    ParseResult result = parse({"-v", "-p", "-e", "", "--test", "a.so"}, options);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(options.param, "");
    EXPECT_EQ(options.environment, "");
    EXPECT_EQ(options.tests, std::vector<std::string>{"a.so"});
    Options flag;
    result = parse({"-t", "a.so", "-p", "--verbose", "-e", "robot=x"}, flag);
    ASSERT_TRUE(runs(result)) << result.text;
    EXPECT_EQ(flag.param, "");
    EXPECT_TRUE(flag.verbose);
    EXPECT_EQ(flag.environment, "robot=x");
}

TEST(Options, TypedOutputsAndDefaults) {
    Options options;
    ParseResult result = parse(
        {"-t", "a.so", "-o", "junit:results.xml", "--output", "text:r.txt", "-o", "plain.txt"},
        options);
    ASSERT_TRUE(runs(result)) << result.text;
    ASSERT_EQ(options.outputs.size(), 3u);
    EXPECT_EQ(options.outputs[0].type, "junit");
    EXPECT_EQ(options.outputs[0].file, "results.xml");
    EXPECT_EQ(options.outputs[1].type, "text");
    EXPECT_EQ(options.outputs[2].type, "text");

    Options defaults;
    ASSERT_TRUE(runs(parse({"-t", "a.so"}, defaults)));
    ASSERT_EQ(defaults.outputs.size(), 1u);
    EXPECT_EQ(defaults.outputs[0].file, "result.txt");

    Options none;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--no-output", "-o", "x.txt"}, none)));
    EXPECT_TRUE(none.outputs.empty());
}

TEST(Options, UsageErrorsExitWithTwoAndSayWhy) {
    struct Case {
        std::initializer_list<const char*> args;
        const char* says;
    };
    const Case cases[] = {
        {{}, "nothing to run"},
        {{"-t", "a.so", "--bogus"}, "--bogus"},
        {{"-t"}, "--test"},
        {{"-t", "a.so", "--repetition", "-1"}, "repetition"},
        {{"-t", "a.so", "--repetition", "abc"}, "repetition"},
        {{"-t", "a.so", "--web-port", "70000"}, "web-port"},
        {{"-t", "a.so", "--web-linger", "-1"}, "web-linger"},
        {{"-t", "a.so", "--output-type", "xml"}, "unknown output type 'xml'"},
        {{"-t", "a.so", "-o", "yaml:out.yaml"}, "(expected text, junit, tap, json or html)"},
        {{"-t", "a.so", "-o", "junit:"}, "no file name"},
        {{"-t", "a.so", "--isolation", "thread"}, "isolation"},
        {{"-t", "a.so", "--network", "bridge"}, "--network: bridge not in {private,host}"},
        {{"-t", "a.so", "--timeout", "-1"}, "timeout"},
        {{"-t", "a.so", "--timeout", "soon"}, "timeout"},
        {{"-t", "a.so", "--var", "novalue"}, "NAME=VALUE"},
        {{"-t", "a.so", "stray"}, "stray"},
        {{"-t", "a.so", "--repetition", "99999999999"}, "is too large: at most 1000000000 runs"},
        {{"-t", "a.so", "--timeout", "inf"}, "'inf' is not a number of seconds"},
        {{"-t", ""}, "--test: the value is empty"},
        {{"--suite", ""}, "--suite: the value is empty"},
        {{"-t", "a.so", "--jobs", ""}, "--jobs: the value is empty"},
        {{"-t", "a.so", "-e"}, "--environment"},
        {{"-t", "a.so", "-o", "junti:x.xml"}, "unknown output type 'junti'"},
        {{"-t", "a.so", "-o", "junti:x.xml"}, "text:junti:x.xml or ./junti:x.xml"},
    };
    for (const auto& c : cases) {
        Options options;
        std::vector<const char*> argv{"robottestingframework-testrunner"};
        argv.insert(argv.end(), c.args.begin(), c.args.end());
        ParseResult result = parseOptions(static_cast<int>(argv.size()), argv.data(), options);
        std::string line;
        for (const char* arg : c.args) {
            line += std::string(arg) + " ";
        }
        EXPECT_EQ(result.outcome, ParseResult::Outcome::Exit) << line;
        EXPECT_EQ(result.status, 2) << line;
        EXPECT_NE(result.text.find(c.says), std::string::npos) << line << "→ " << result.text;
    }
}

TEST(Options, AFileNameWithAColonIsWrittenWithItsTypeOrAFolder) {
    Options options;
    ParseResult result =
        parse({"-t", "a.so", "-o", "text:junti:x.xml", "-o", "./junti:y.xml"}, options);
    ASSERT_TRUE(runs(result)) << result.text;
    ASSERT_EQ(options.outputs.size(), 2u);
    EXPECT_EQ(options.outputs[0].type, "text");
    EXPECT_EQ(options.outputs[0].file, "junti:x.xml");
    EXPECT_EQ(options.outputs[1].type, "text");
    EXPECT_EQ(options.outputs[1].file, "./junti:y.xml");
}

TEST(Options, ProcessIsolationIsTheDefault) {
    Options options;
    ASSERT_TRUE(runs(parse({"-t", "a.so"}, options)));
    EXPECT_EQ(options.isolation, Isolation::Process);
    EXPECT_EQ(options.timeout, 0);
    EXPECT_FALSE(options.failFast);

    Options chosen;
    ASSERT_TRUE(runs(
        parse({"-t", "a.so", "--isolation", "none", "--timeout", "2.5", "--fail-fast"}, chosen)));
    EXPECT_EQ(chosen.isolation, Isolation::None);
    EXPECT_EQ(chosen.timeout, 2.5);
    EXPECT_TRUE(chosen.failFast);
}

TEST(Options, NetworkPrivateOrHost) {
    Options options;
    ASSERT_TRUE(runs(parse({"-t", "a.so"}, options)));
    EXPECT_FALSE(options.privateNetworks);
    Options isolated;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--network", "private"}, isolated)));
    EXPECT_TRUE(isolated.privateNetworks);
    Options host;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--network", "host"}, host)));
    EXPECT_FALSE(host.privateNetworks);
}

TEST(Options, HelpAndVersionExitWithZero) {
    Options options;
    ParseResult help = parse({"--help"}, options);
    EXPECT_EQ(help.outcome, ParseResult::Outcome::Exit);
    EXPECT_EQ(help.status, 0);
    for (const char* option :
         {"--test", "--tests", "--suite", "--suites", "--recursive", "--param", "--environment",
          "--repetition", "--output", "--output-type", "--no-output", "--no-summary",
          "--web-reporter", "--web-port", "--detail", "--verbose", "--version"}) {
        EXPECT_NE(help.text.find(option), std::string::npos) << option;
    }
    Options other;
    ParseResult version = parse({"--version"}, other);
    EXPECT_EQ(version.status, 0);
    EXPECT_NE(version.text.find("3."), std::string::npos) << version.text;
}

TEST(Options, HistoryReportTakesAnOptionalNumberOfRuns) {
    Options options;
    ASSERT_TRUE(runs(parse({"--history", "h.db", "--history-report"}, options)));
    EXPECT_TRUE(options.historyReport);
    EXPECT_EQ(options.historyRuns, 30u);
    Options fifty;
    ASSERT_TRUE(runs(parse({"--history", "h.db", "--history-report", "50"}, fifty)));
    EXPECT_EQ(fifty.historyRuns, 50u);
    for (const char* bad : {"0", "x", "-3"}) {
        Options wrong;
        const ParseResult result = parse({"--history", "h.db", "--history-report", bad}, wrong);
        EXPECT_EQ(result.status, 2) << bad;
    }
    Options alone;
    const ParseResult result = parse({"--history-report"}, alone);
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.text.find("needs --history FILE"), std::string::npos) << result.text;
}

TEST(Options, HistoryImportTakesTheReportsAfterTheOptions) {
    Options options;
    ASSERT_TRUE(runs(parse({"--history", "h.db", "--history-import", "a.xml", "b.json"}, options)));
    EXPECT_EQ(options.historyImports, (std::vector<std::string>{"a.xml", "b.json"}));
    EXPECT_TRUE(options.mergeReports.empty());
    Options none;
    EXPECT_EQ(parse({"--history", "h.db", "--history-import"}, none).status, 2);
}

TEST(Options, DurationsNPrintsTheSlowestAndAReportIsDurationsFrom) {
    Options none;
    ASSERT_TRUE(runs(parse({"-t", "a.so"}, none)));
    EXPECT_EQ(none.slowestTests, -1);
    EXPECT_EQ(none.durations, "");

    Options five;  // pytest's --durations 5
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--durations", "5"}, five)));
    EXPECT_EQ(five.slowestTests, 5);
    EXPECT_EQ(five.durations, "");
    Options all;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--durations=0"}, all)));
    EXPECT_EQ(all.slowestTests, 0);

    Options from;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--durations-from", "last.xml"}, from)));
    EXPECT_EQ(from.durations, "last.xml");
    EXPECT_EQ(from.slowestTests, -1);
    // The form of earlier 3.0 builds: a value that is not a number is the report.
    Options old;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--durations", "last.xml"}, old)));
    EXPECT_EQ(old.durations, "last.xml");
    EXPECT_EQ(old.slowestTests, -1);

    Options both;
    ASSERT_TRUE(runs(parse({"-t", "a.so", "--durations", "3", "--durations-from", "h.db"}, both)));
    EXPECT_EQ(both.slowestTests, 3);
    EXPECT_EQ(both.durations, "h.db");
    Options twoReports;
    const ParseResult result =
        parse({"-t", "a.so", "--durations", "a.xml", "--durations-from", "b.xml"}, twoReports);
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.text.find("--durations a.xml and --durations-from b.xml: one REPORT at most"),
              std::string::npos)
        << result.text;
}
