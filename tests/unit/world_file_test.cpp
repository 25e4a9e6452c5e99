// The world file of the process fixture: what it reads, and how it says what is wrong.
#include "fixtures/process/world_file.h"

#include <signal.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "process_test_helpers.h"

using namespace robottestingframework::fixtures;

namespace {

struct Parsed {
    bool ok = false;
    World world;
    std::string error;
};

Parsed parse(const std::string& text, WorldOptions options = {}) {
    Parsed out;
    out.ok = parseWorld(text, "/tmp/rtf-world/world.xml", options, out.world, out.error);
    return out;
}

// The error must start with the file and line, and contain `words`.
void expectError(const std::string& text, unsigned line, const std::string& words) {
    Parsed parsed = parse(text);
    ASSERT_FALSE(parsed.ok) << text;
    const std::string where = "/tmp/rtf-world/world.xml:" + std::to_string(line) + ": ";
    EXPECT_EQ(parsed.error.rfind(where, 0), 0u) << parsed.error;
    EXPECT_NE(parsed.error.find(words), std::string::npos) << parsed.error;
}

}  // namespace

TEST(WorldFile, ReadsEveryPartOfAProcess) {
    Parsed parsed = parse(R"(<world name="lab" logdir="logs" ready-timeout="12s">
  <env name="COMMON">1</env>
  <process name="broker" command="mosquitto -c 'my conf.conf'">
    <ready><port>1883</port></ready>
  </process>
  <process name="robot" depends="broker">
    <command><arg>/usr/bin/python3</arg><arg>-u</arg><arg>robot with space.py</arg></command>
    <env name="ROBOT">sim</env>
    <ready timeout="5s">
      <delay>250ms</delay>
      <port host="::1" timeout="7">5000</port>
      <file>ready.flag</file>
      <output>calibrated \d+</output>
      <probe interval="20ms">test -e x</probe>
    </ready>
    <stop signal="SIGINT" grace="1.5s"/>
  </process>
  <process name="shell">
    <command shell="true">echo a | cat</command>
    <depends>robot</depends>
  </process>
</world>)");
    ASSERT_TRUE(parsed.ok) << parsed.error;
    const World& world = parsed.world;
    EXPECT_EQ(world.name, "lab");
    EXPECT_EQ(world.folder, "/tmp/rtf-world");
    EXPECT_EQ(world.logFolder, "/tmp/rtf-world/logs");
    ASSERT_EQ(world.processes.size(), 3u);

    const ProcessSpec& broker = world.processes[0];
    EXPECT_EQ(broker.argv, (std::vector<std::string>{"mosquitto", "-c", "my conf.conf"}));
    EXPECT_EQ(broker.folder, "/tmp/rtf-world");
    EXPECT_EQ(broker.line, 3u);
    ASSERT_EQ(broker.ready.size(), 1u);
    EXPECT_EQ(broker.ready[0].kind, ReadyCheck::Kind::Port);
    EXPECT_EQ(broker.ready[0].host, "127.0.0.1");
    EXPECT_EQ(broker.ready[0].timeout, 12);  // the world's default deadline
    EXPECT_EQ(broker.stopSignal, SIGTERM);
    EXPECT_EQ(broker.grace, 5);
    EXPECT_EQ(broker.logFile, "/tmp/rtf-world/logs/broker.log");
    ASSERT_EQ(broker.environment.size(), 1u);
    EXPECT_EQ(broker.environment[0].first, "COMMON");

    const ProcessSpec& robot = world.processes[1];
    EXPECT_EQ(robot.argv,
              (std::vector<std::string>{"/usr/bin/python3", "-u", "robot with space.py"}));
    EXPECT_EQ(robot.depends, std::vector<std::string>{"broker"});
    ASSERT_EQ(robot.environment.size(), 2u);
    EXPECT_EQ(robot.environment[1], (std::pair<std::string, std::string>{"ROBOT", "sim"}));
    ASSERT_EQ(robot.ready.size(), 5u);
    EXPECT_EQ(robot.ready[0].kind, ReadyCheck::Kind::Delay);
    EXPECT_DOUBLE_EQ(robot.ready[0].delay, 0.25);
    EXPECT_EQ(robot.ready[1].host, "::1");
    EXPECT_EQ(robot.ready[1].port, 5000);
    EXPECT_EQ(robot.ready[1].timeout, 7);
    EXPECT_EQ(robot.ready[2].path, "/tmp/rtf-world/ready.flag");
    EXPECT_EQ(robot.ready[2].timeout, 5);
    EXPECT_EQ(robot.ready[3].pattern, "calibrated \\d+");
    EXPECT_EQ(robot.ready[4].argv, (std::vector<std::string>{"test", "-e", "x"}));
    EXPECT_DOUBLE_EQ(robot.ready[4].interval, 0.02);
    EXPECT_EQ(robot.ready[4].line, 14u);
    EXPECT_EQ(robot.stopSignal, SIGINT);
    EXPECT_DOUBLE_EQ(robot.grace, 1.5);

    const ProcessSpec& shell = world.processes[2];
    EXPECT_EQ(shell.argv, (std::vector<std::string>{"/bin/sh", "-c", "echo a | cat"}));
    EXPECT_EQ(shell.depends, std::vector<std::string>{"robot"});
}

TEST(WorldFile, NameDefaultsToTheFileAndLogsGoUnderTheCurrentFolder) {
    Parsed parsed = parse("<world><process name='a' command='true'/></world>");
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.name, "world");
    EXPECT_EQ(parsed.world.logFolder,
              (std::filesystem::current_path() / "rtf-logs" / "world").string());
}

TEST(WorldFile, LogFolderFromTheFixtureParamWins) {
    WorldOptions options;
    options.logFolder = "/tmp/elsewhere";
    Parsed parsed = parse("<world logdir='x'><process name='a' command='true'/></world>", options);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.logFolder, "/tmp/elsewhere");
}

TEST(WorldFile, SuitesSharingTheWorldFileEachHaveTheirLogFolder) {
    WorldOptions options;
    options.instance = "left";
    Parsed parsed = parse("<world><process name='a' command='true'/></world>", options);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.logFolder,
              (std::filesystem::current_path() / "rtf-logs" / "world" / "left").string());
    EXPECT_EQ(parsed.world.processes[0].logFile,
              (std::filesystem::current_path() / "rtf-logs" / "world" / "left" / "a.log").string());
    options.logFolder = "/tmp/elsewhere";
    parsed = parse("<world logdir='x'><process name='a' command='true'/></world>", options);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.logFolder, "/tmp/elsewhere/left");
}

TEST(WorldFile, ThePoolItemsOfTheSuiteReplaceResourceVariables) {
    WorldOptions options;
    options.variables["resource.port"] = "7,8";
    Parsed parsed = parse(
        "<world>\n<variable name='ports'>${resource.port}</variable>\n"
        "<process name='a' command='serve ${resource.port} ${ports}'/></world>",
        options);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.processes[0].argv, (std::vector<std::string>{"serve", "7,8", "7,8"}));
    // A pool the suite does not take, with or without items of others.
    parsed = parse("<world>\n<process name='a' command='serve ${resource.gpu}'/></world>", options);
    ASSERT_FALSE(parsed.ok);
    EXPECT_EQ(parsed.error,
              "/tmp/rtf-world/world.xml:2: ${resource.gpu} but the suite takes no item of pool "
              "gpu (add <resource pool=\"gpu\"/> to the suite)");
    expectError(
        "<world>\n<process name='a'>\n<command>run ${resource.gpu}</command></process>"
        "</world>",
        3, "${resource.gpu} but the suite takes no item of pool gpu");
}

TEST(WorldFile, ReportsMalformedXmlWithItsLine) {
    expectError("<world>\n  <process name='a' command='true'>\n</world>\n", 3, "malformed XML");
}

TEST(WorldFile, ReportsAWrongRootElement) {
    expectError("\n<suite/>", 2, "expected <world> as the root element, found <suite>");
}

TEST(WorldFile, ReportsUnknownElementsAndAttributesWithTheirLine) {
    expectError("<world>\n<process name='a' command='true'>\n<wait/>\n</process></world>", 3,
                "unknown element <wait> in <process>");
    expectError("<world>\n<process name='a' command='true' colour='red'/></world>", 2,
                "unknown attribute 'colour' of <process>");
    expectError(
        "<world>\n<process name='a' command='true'>\n<ready>\n<socket>1</socket>"
        "</ready></process></world>",
        4, "unknown readiness check <socket>");
}

TEST(WorldFile, ReportsAProcessWithoutNameOrCommand) {
    expectError("<world>\n<process command='true'/></world>", 2, "needs a 'name' attribute");
    expectError("<world>\n<process name='a'/></world>", 2, "has no command");
    expectError("<world>\n<process name='a' command='  '/></world>", 2, "empty command");
    expectError("<world>\n<process name='a' command='echo \"x'/></world>", 2,
                "unterminated double quote");
}

TEST(WorldFile, ReportsTwoProcessesWithTheSameName) {
    expectError(
        "<world>\n<process name='a' command='true'/>\n<process name='a' command='true'/>"
        "</world>",
        3, "a second process named 'a' (the first is at line 2)");
}

TEST(WorldFile, ReportsAnUnknownDependency) {
    expectError(
        "<world>\n<process name='broker' command='true'/>\n"
        "<process name='robot' depends='brocker' command='true'/></world>",
        3, "'robot' depends on 'brocker', which is not a process of this world");
}

TEST(WorldFile, ReportsADependencyCycle) {
    expectError(
        "<world>\n<process name='a' depends='c' command='true'/>\n"
        "<process name='b' depends='a' command='true'/>\n"
        "<process name='c' depends='b' command='true'/></world>",
        2, "dependency cycle: 'a' -> 'c' -> 'b' -> 'a'");
    expectError("<world>\n<process name='self' depends='self' command='true'/></world>", 2,
                "dependency cycle: 'self' -> 'self'");
}

TEST(WorldFile, ReportsBadValuesOfChecks) {
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<port>http</port>"
        "</ready></process></world>",
        3, "'http' is not a TCP port");
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<port>70000</port>"
        "</ready></process></world>",
        3, "'70000' is not a TCP port");
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<delay>soon</delay>"
        "</ready></process></world>",
        3, "'soon' is not a duration");
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<output>([a-</output>"
        "</ready></process></world>",
        3, "is not a regular expression RE2 takes");
    // RE2 has no back-references or look-around: refused when the file is read, not at
    // set-up (README: the syntax users may write).
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<output>(a)\\1</output>"
        "</ready></process></world>",
        3, "invalid escape sequence");
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n<output>(?=ready)</output>"
        "</ready></process></world>",
        3, "no back-references or look-around");
    expectError(
        "<world>\n<process name='a' command='true'><ready>\n"
        "<file timeout='forever'>x</file></ready></process></world>",
        3, "'forever' is not a duration");
    expectError(
        "<world>\n<process name='a' command='true'>\n<stop signal='SIGNOPE'/>"
        "</process></world>",
        3, "'SIGNOPE' is not a signal");
}

TEST(WorldFile, ExpandsVariablesFromTheParamTheFileAndTheEnvironment) {
    ::setenv("RTF_WORLD_TEST_HOME", "/home/robot", 1);
    WorldOptions options;
    options.variables["port"] = "4242";
    Parsed parsed = parse(R"(<world>
  <variable name="port">1111</variable>
  <variable name="greeting">hello</variable>
  <process name="a" command="echo ${greeting} ${env:RTF_WORLD_TEST_HOME} $${literal}">
    <env name="WHERE">${world_dir}</env>
    <ready><port>${port}</port></ready>
  </process>
</world>)",
                          options);
    ASSERT_TRUE(parsed.ok) << parsed.error;
    const ProcessSpec& a = parsed.world.processes[0];
    EXPECT_EQ(a.argv, (std::vector<std::string>{"echo", "hello", "/home/robot", "${literal}"}));
    EXPECT_EQ(a.environment[0].second, "/tmp/rtf-world");
    EXPECT_EQ(a.ready[0].port, 4242);  // the param wins over the file
}

TEST(WorldFile, ReportsAnUndefinedVariableWithItsLine) {
    expectError("<world>\n<process name='a'>\n<command>run ${nope}</command></process></world>", 3,
                "undefined variable ${nope}");
    ::unsetenv("RTF_WORLD_TEST_UNSET");
    expectError("<world>\n<process name='a' command='run ${env:RTF_WORLD_TEST_UNSET}'/></world>", 2,
                "environment variable 'RTF_WORLD_TEST_UNSET' is not set");
}

// Variables that expand each other ten times per level reach 100 MB after 8 levels.
TEST(WorldFile, RefusesAnExpansionBombAtTheVariableThatCrossesTheCap) {
    std::string text = "<world>\n<variable name=\"v0\">0123456789</variable>\n";
    for (int level = 1; level <= 8; ++level) {
        text += "<variable name=\"v" + std::to_string(level) + "\">";
        for (int i = 0; i < 10; ++i) {
            text += "${v" + std::to_string(level - 1) + "}";
        }
        text += "</variable>\n";
    }
    text += "<process name=\"p\" command=\"true\"/>\n</world>\n";
    // v5 holds 10^6 bytes, v6 would hold 10^7: v6 (line 8) is the first over 1 MiB.
    expectError(text, 8, "<variable name=\"v6\"> grows past 1 MiB");
}

TEST(WorldFile, RefusesManyLargeValuesThatTogetherPassTheTotalCap) {
    std::string text =
        "<world>\n<variable name=\"big\">" + std::string(512 * 1024, 'x') + "</variable>\n";
    for (int i = 0; i < 40; ++i) {
        text += "<env name=\"E" + std::to_string(i) + "\">${big}</env>\n";
    }
    text += "<process name=\"p\" command=\"true\"/>\n</world>\n";
    // The variable and 31 copies of it (with the names) pass 16 MiB at the 31st <env>.
    expectError(text, 33, "grow past 16 MiB together");
}

TEST(WorldFile, KeepsValuesJustUnderTheCap) {
    Parsed parsed = parse("<world><variable name=\"v\">" + std::string(1024 * 1024 - 2, 'x') +
                          "</variable><process name=\"p\" command=\"true\">"
                          "<env name=\"E\">${v}ab</env></process></world>");
    ASSERT_TRUE(parsed.ok) << parsed.error.substr(0, 300);
    EXPECT_EQ(parsed.world.processes[0].environment[0].second.size(), 1024u * 1024u);
}

TEST(WorldFile, AcceptsA200CharacterNameAndGivesItAShortLogFile) {
    const std::string name(200, 'n');
    Parsed parsed =
        parse("<world><process name='" + name + "' command='true'/>" + "<process name='" + name +
              "x' depends='" + name + "' command='true'/></world>");
    ASSERT_TRUE(parsed.ok) << parsed.error;
    EXPECT_EQ(parsed.world.processes[0].name, name);
    const std::string file0 =
        std::filesystem::path(parsed.world.processes[0].logFile).filename().string();
    const std::string file1 =
        std::filesystem::path(parsed.world.processes[1].logFile).filename().string();
    EXPECT_LT(file0.size(), 100u);
    EXPECT_NE(file0, file1);
}

TEST(WorldFile, ReadsTheFileFromDiskAndResolvesFoldersAgainstIt) {
    const auto folder = rtf_process_test::freshFolder();
    std::filesystem::create_directories(folder / "bin");
    const auto file =
        rtf_process_test::writeFile(folder / "w.xml",
                                    "<world><process name='a' folder='bin' command='./run'>"
                                    "<ready><file>out/ready</file></ready></process></world>");
    World world;
    std::string error;
    ASSERT_TRUE(readWorldFile(file.string(), {}, world, error)) << error;
    EXPECT_EQ(world.processes[0].folder, (folder / "bin").string());
    EXPECT_EQ(world.processes[0].ready[0].path, (folder / "bin" / "out" / "ready").string());

    rtf_process_test::writeFile(folder / "w.xml",
                                "<world><process name='a' folder='nowhere' command='x'/></world>");
    EXPECT_FALSE(readWorldFile(file.string(), {}, world, error));
    EXPECT_NE(error.find("w.xml:1: the folder"), std::string::npos) << error;
    EXPECT_NE(error.find("does not exist"), std::string::npos) << error;

    EXPECT_FALSE(readWorldFile((folder / "missing.xml").string(), {}, world, error));
    EXPECT_NE(error.find("cannot read the world file"), std::string::npos) << error;

    // A device or a file past 16 MiB is refused, not read until memory runs out (issue 40).
    EXPECT_FALSE(readWorldFile("/dev/zero", {}, world, error));
    EXPECT_NE(error.find("/dev/zero: is a character device, not a world file"), std::string::npos)
        << error;
    std::filesystem::resize_file(folder / "w.xml", 16 * 1024 * 1024 + 1);  // sparse
    EXPECT_FALSE(readWorldFile(file.string(), {}, world, error));
    EXPECT_NE(error.find("the world file is larger than 16 MiB"), std::string::npos) << error;
}

TEST(CommandLine, SplitsLikeAShell) {
    std::vector<std::string> words;
    std::string error;
    ASSERT_TRUE(splitCommandLine(R"(a  'b c' "d \"e\"" f\ g "" h'i'j)", words, error));
    EXPECT_EQ(words, (std::vector<std::string>{"a", "b c", "d \"e\"", "f g", "", "hij"}));
    EXPECT_FALSE(splitCommandLine("a 'b", words, error));
    EXPECT_EQ(error, "unterminated single quote");
}

TEST(Duration, ReadsUnits) {
    double seconds = 0;
    ASSERT_TRUE(parseDuration("300ms", seconds));
    EXPECT_DOUBLE_EQ(seconds, 0.3);
    ASSERT_TRUE(parseDuration("2s", seconds));
    EXPECT_DOUBLE_EQ(seconds, 2);
    ASSERT_TRUE(parseDuration(" 1.5 ", seconds));
    EXPECT_DOUBLE_EQ(seconds, 1.5);
    ASSERT_TRUE(parseDuration("1min", seconds));
    EXPECT_DOUBLE_EQ(seconds, 60);
    EXPECT_FALSE(parseDuration("-1s", seconds));
    EXPECT_FALSE(parseDuration("2 hours", seconds));
    EXPECT_FALSE(parseDuration("", seconds));
}

TEST(Signals, ReadsNamesAndNumbers) {
    int signal = 0;
    ASSERT_TRUE(parseSignal("SIGINT", signal));
    EXPECT_EQ(signal, SIGINT);
    ASSERT_TRUE(parseSignal("term", signal));
    EXPECT_EQ(signal, SIGTERM);
    ASSERT_TRUE(parseSignal("9", signal));
    EXPECT_EQ(signal, SIGKILL);
    EXPECT_FALSE(parseSignal("SIGWHAT", signal));
    ASSERT_TRUE(parseSignal("winch", signal));  // every name platform::signalName knows
    EXPECT_EQ(signal, SIGWINCH);
}

// --- <stop exit="...">: what a clean stop is (docs/process-fixture.md, "Checked shutdowns") ---

namespace {

CleanStop cleanStopOf(const std::string& stop) {
    Parsed parsed =
        parse("<world>\n<process name='a' command='true'>\n" + stop + "\n</process>\n</world>");
    EXPECT_TRUE(parsed.ok) << parsed.error;
    return parsed.ok ? parsed.world.processes[0].cleanStop : CleanStop();
}

}  // namespace

TEST(CleanStop, DefaultsToStatusZeroOrTheStopSignal) {
    const CleanStop plain = cleanStopOf("");
    EXPECT_FALSE(plain.any);
    EXPECT_FALSE(plain.given);
    EXPECT_EQ(plain.statuses, std::vector<int>{0});
    EXPECT_EQ(plain.signals, std::vector<int>{SIGTERM});
    EXPECT_EQ(plain.describe(), "status 0 or SIGTERM");

    const CleanStop interrupt = cleanStopOf("<stop signal='SIGINT' grace='3s'/>");
    EXPECT_EQ(interrupt.statuses, std::vector<int>{0});
    EXPECT_EQ(interrupt.signals, std::vector<int>{SIGINT});
    EXPECT_TRUE(interrupt.acceptsStatus(0));
    EXPECT_TRUE(interrupt.acceptsSignal(SIGINT));
    EXPECT_FALSE(interrupt.acceptsStatus(1));
    EXPECT_FALSE(interrupt.acceptsSignal(SIGTERM));
    EXPECT_FALSE(interrupt.acceptsSignal(SIGABRT));
}

TEST(CleanStop, ReadsStatusesAndSignalNames) {
    const CleanStop stop = cleanStopOf("<stop signal='SIGINT' exit='0, 130, SIGINT, term, HUP'/>");
    EXPECT_TRUE(stop.given);
    EXPECT_EQ(stop.statuses, (std::vector<int>{0, 130}));
    EXPECT_EQ(stop.signals, (std::vector<int>{SIGINT, SIGTERM, SIGHUP}));
    EXPECT_EQ(stop.describe(), "statuses 0, 130, SIGINT, SIGTERM or SIGHUP");
    // The list replaces the default: status 1 alone, and the stop signal is no longer clean.
    const CleanStop one = cleanStopOf("<stop signal='SIGINT' exit='1'/>");
    EXPECT_EQ(one.statuses, std::vector<int>{1});
    EXPECT_TRUE(one.signals.empty());
    EXPECT_FALSE(one.acceptsStatus(0));
    EXPECT_FALSE(one.acceptsSignal(SIGINT));
    EXPECT_EQ(one.describe(), "status 1");
    // Bare integers are statuses, never signals: 15 is the status 15.
    const CleanStop fifteen = cleanStopOf("<stop exit='15'/>");
    EXPECT_EQ(fifteen.statuses, std::vector<int>{15});
    EXPECT_FALSE(fifteen.acceptsSignal(SIGTERM));
}

TEST(CleanStop, AnyAcceptsEveryEnding) {
    const CleanStop stop = cleanStopOf("<stop exit=' ANY '/>");
    EXPECT_TRUE(stop.any);
    EXPECT_TRUE(stop.acceptsStatus(3));
    EXPECT_TRUE(stop.acceptsSignal(SIGSEGV));
    EXPECT_EQ(stop.describe(), "any ending");
}

TEST(CleanStop, ReportsAnUnreadableExpectationWithFileAndLine) {
    const std::string head = "<world>\n<process name='a' command='true'>\n";
    expectError(head + "<stop exit='zero'/></process></world>", 3,
                "<stop exit=\"zero\">: expected a comma-separated list of exit statuses (0-255) "
                "and signal names (SIGINT, TERM), or 'any'; 'zero' is neither");
    expectError(head + "<stop exit='256'/></process></world>", 3, "'256' is over 255");
    expectError(head + "<stop exit='0,,1'/></process></world>", 3, "an empty item");
    expectError(head + "<stop exit=''/></process></world>", 3, "the list is empty");
    expectError(head + "<stop exit='-1'/></process></world>", 3, "'-1' is neither");
    expectError(head + "<stop exit='SIGNOPE'/></process></world>", 3, "'SIGNOPE' is neither");
    expectError(head + "<stop exit='any, 0'/></process></world>", 3, "'any' alone");
    expectError(head + "\n<stop signal='INT'\n exit='0 1'/></process></world>", 4,
                "'0 1' is neither");
}
