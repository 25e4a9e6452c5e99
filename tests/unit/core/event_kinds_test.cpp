// The event vocabulary: one table row per kind, and the one switch from an event to the named
// handler RTF 2.x's listeners override.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "core/events.h"

using namespace robottestingframework;

namespace {

using Kind = ResultEvent::Kind;

std::vector<Kind> everyKind() {
    std::vector<Kind> kinds;
    for (unsigned int k = 0; k <= static_cast<unsigned int>(ResultEvent::lastKind); ++k) {
        kinds.push_back(static_cast<Kind>(k));
    }
    return kinds;
}

class Named : public TestCase {
public:
    explicit Named(const std::string& name) : TestCase(name) {}
    void run() override {}
};

// Overrides every named handler, as a listener written against RTF 2.x (and the additions
// since) does: each call is one line "handler message".
class Named2x : public TestListener {
public:
    void addReport(const Test*, TestMessage m) override { said("addReport " + m.getMessage()); }
    void addError(const Test*, TestMessage m) override { said("addError " + m.getMessage()); }
    void addFailure(const Test*, TestMessage m) override { said("addFailure " + m.getMessage()); }
    void startTest(const Test*) override { said("startTest"); }
    void endTest(const Test*) override { said("endTest"); }
    void startTestSuite(const Test*) override { said("startTestSuite"); }
    void endTestSuite(const Test*) override { said("endTestSuite"); }
    void startTestRunner() override { said("startTestRunner"); }
    void endTestRunner() override { said("endTestRunner"); }
    void addCheck(const Test*, TestMessage m, bool passed) override {
        said(std::string("addCheck ") + (passed ? "ok " : "failed ") + m.getMessage());
    }
    void addSkipped(const Test*, TestMessage m) override { said("addSkipped " + m.getMessage()); }
    void addCrash(const Test*, TestMessage m) override { said("addCrash " + m.getMessage()); }
    void addTimeout(const Test*, TestMessage m) override { said("addTimeout " + m.getMessage()); }
    void addInterrupted(const Test*, TestMessage m) override {
        said("addInterrupted " + m.getMessage());
    }
    void addOutput(const Test*, const std::string& text) override { said("addOutput " + text); }
    void renameTest(const Test*, const std::string& name) override { said("renameTest " + name); }
    void retryTest(const Test*, TestMessage m) override { said("retryTest " + m.getMessage()); }
    void startRepetition(const Test*, unsigned int index, unsigned int count) override {
        said("startRepetition " + std::to_string(index) + "/" + std::to_string(count));
    }
    void addMeasurement(const Test*, const Measurement& m, bool passed) override {
        said("addMeasurement " + m.name + (passed ? " ok" : " outside"));
    }
    void addAttachment(const Test*, const Attachment& a) override {
        said("addAttachment " + a.path);
    }
    void addEvent(const Test*, const ResultEvent& event) override {
        said(std::string("addEvent ") + toString(event.kind));
    }
    void said(const std::string& line) { lines.push_back(line); }
    std::vector<std::string> lines;
};

// Knows only RTF 2.x's addReport.
class Rtf2 : public TestListener {
public:
    void addReport(const Test*, TestMessage m) override { reports.push_back(m.getMessage()); }
    std::vector<std::string> reports;
};

}  // namespace

TEST(EventKinds, EveryKindHasAWordOfItsOwn) {
    std::set<std::string> words;
    for (Kind kind : everyKind()) {
        const std::string word = toString(kind);
        EXPECT_NE(word, "unknown");
        EXPECT_TRUE(words.insert(word).second) << word;
    }
}

TEST(EventKinds, TheFramesAreTheStartsAndEnds) {
    std::vector<std::string> frames;
    for (Kind kind : everyKind()) {
        if (isFrame(kind)) {
            frames.push_back(toString(kind));
        }
    }
    EXPECT_EQ(frames, (std::vector<std::string>{"start-runner", "end-runner", "start-suite",
                                                "end-suite", "start-test", "end-test"}));
}

// The other questions about a kind are columns too: which kind starts or ends a test, starts a
// repetition, holds printed text, a new name or a world's phase.
TEST(EventKinds, WhatAKindDoesToItsTestIsAColumn) {
    auto wordsWhere = [](bool (*question)(Kind)) {
        std::vector<std::string> words;
        for (Kind kind : everyKind()) {
            if (question(kind)) {
                words.push_back(toString(kind));
            }
        }
        return words;
    };
    using Words = std::vector<std::string>;
    EXPECT_EQ(wordsWhere(startsTest), Words{"start-test"});
    EXPECT_EQ(wordsWhere(endsTest), Words{"end-test"});
    EXPECT_EQ(wordsWhere(startsRepetition), Words{"repetition"});
    EXPECT_EQ(wordsWhere(isOutput), Words{"output"});
    EXPECT_EQ(wordsWhere(renamesTest), Words{"rename"});
    EXPECT_EQ(wordsWhere(isWorldPhase), Words{"world"});
}

// Events are made by name (core/events.h): each maker makes its kind, with what it names.
TEST(EventKinds, EachMakerMakesItsKind) {
    const TestMessage msg("said", "detail");
    const std::vector<std::pair<ResultEvent, std::string>> made = {
        {events::startRunner(), "start-runner"},
        {events::endRunner(), "end-runner"},
        {events::startSuite(), "start-suite"},
        {events::endSuite(), "end-suite"},
        {events::startTest(), "start-test"},
        {events::endTest(), "end-test"},
        {events::report(msg), "report"},
        {events::check(msg, false), "check"},
        {events::failure(msg), "failure"},
        {events::error(msg), "error"},
        {events::skipped(msg), "skipped"},
        {events::crash(msg), "crash"},
        {events::timeout(msg), "timeout"},
        {events::interrupted(msg), "interrupted"},
        {events::output("printed"), "output"},
        {events::rename("new name"), "rename"},
        {events::retry(msg), "retry"},
        {events::repetition(2, 3), "repetition"},
        {events::measurement(nullptr, true, msg), "measurement"},
        {events::attachment(nullptr, msg), "attachment"},
        {events::world("db", "ready", "3 suites"), "world"},
    };
    for (const auto& one : made) {
        EXPECT_EQ(toString(one.first.kind), one.second);
        EXPECT_EQ(one.first.testId, 0u) << one.second;
    }
    EXPECT_FALSE(events::check(msg, false).passed);
    EXPECT_TRUE(events::check(msg, true).passed);
    EXPECT_EQ(events::failure(msg).message.getDetail(), "detail");
    EXPECT_EQ(events::output("printed").message.getMessage(), "printed");
    EXPECT_EQ(events::rename("new name").message.getMessage(), "new name");
    const ResultEvent repetition = events::repetition(2, 3);
    EXPECT_EQ(repetition.repetition, 2u);
    EXPECT_EQ(repetition.repetitions, 3u);
    auto measured = std::make_shared<const Measurement>();
    const ResultEvent measurement = events::measurement(measured, false, msg);
    EXPECT_EQ(measurement.measurement, measured);
    EXPECT_FALSE(measurement.passed);
    const ResultEvent world = events::world("db", "ready", "3 suites");
    EXPECT_EQ(world.testName, "db");
    EXPECT_EQ(world.message.getMessage(), "ready");
    EXPECT_EQ(world.message.getDetail(), "3 suites");
}

// What a shared world's start said is said again to each suite that joins it: its messages,
// output and data, never a frame nor a state of the test that started it (the table's column).
TEST(EventKinds, ASharedWorldReplaysItsMessagesOutputAndDataOnly) {
    std::set<Kind> replayed;
    for (int k = 0; k <= static_cast<int>(ResultEvent::lastKind); ++k) {
        if (isReplayed(static_cast<Kind>(k))) {
            replayed.insert(static_cast<Kind>(k));
        }
    }
    EXPECT_EQ(replayed, (std::set<Kind>{Kind::Report, Kind::Output, Kind::Attachment,
                                        Kind::Measurement, Kind::Probe}));
}

TEST(EventKinds, EveryKindCallsExactlyOneNamedHandler) {
    Named test("t");
    TestSuite suite("s");
    for (Kind kind : everyKind()) {
        RunEvent event;
        event.data.kind = kind;
        event.test = &test;
        event.suite = &suite;
        Named2x listener;
        listener.onEvent(event);
        EXPECT_EQ(listener.lines.size(), 1u) << toString(kind);
    }
}

TEST(EventKinds, TheNamedSendersReachTheNamedHandlersAsInRtf2) {
    Named test("t");
    TestSuite suite("s");
    TestResult result;
    Named2x listener;
    result.addListener(&listener);
    result.startTestRunner();
    result.startTestSuite(&suite);
    result.startTest(&test);
    result.startRepetition(&test, 2, 3);
    result.addReport(&test, TestMessage("r"));
    result.addCheck(&test, TestMessage("c"), false);
    result.addFailure(&test, TestMessage("f"));
    result.addError(&test, TestMessage("e"));
    result.addSkipped(&test, TestMessage("s"));
    result.addCrash(&test, TestMessage("c"));
    result.addTimeout(&test, TestMessage("t"));
    result.addInterrupted(&test, TestMessage("i"));
    result.addOutput(&test, "o");
    result.renameTest(&test, "n");
    result.endTest(&test);
    result.retryTest(&test, TestMessage("again"));
    result.endTestSuite(&suite);
    result.endTestRunner();
    EXPECT_EQ(listener.lines,
              (std::vector<std::string>{
                  "startTestRunner", "startTestSuite", "startTest", "startRepetition 2/3",
                  "addReport r", "addCheck failed c", "addFailure f", "addError e", "addSkipped s",
                  "addCrash c", "addTimeout t", "addInterrupted i", "addOutput o", "renameTest n",
                  "endTest", "retryTest again", "endTestSuite", "endTestRunner"}));
}

TEST(EventKinds, AMeasurementAndAnAttachmentReachTheirHandlersWithWhatTheyCarry) {
    TestResult result;
    Named2x listener;
    result.addListener(&listener);
    Named test("t");
    result.addMeasurement(&test, Measurement{"rate", 9, "Hz", 10.0, {}}, false);
    result.addAttachment(&test,
                         Attachment{"rtf-attachments/1-a.log", "/x/1-a.log", "", "a.log", 3});
    EXPECT_EQ(listener.lines, (std::vector<std::string>{"addMeasurement rate outside",
                                                        "addAttachment rtf-attachments/1-a.log"}));
}

TEST(EventKinds, ARepetitionIsAReportForAListenerThatDoesNotKnowIt) {
    Named test("t");
    TestResult result;
    Rtf2 listener;
    result.addListener(&listener);
    result.startRepetition(&test, 1, 2);
    EXPECT_EQ(listener.reports, (std::vector<std::string>{"repetition 1/2"}));
}

TEST(EventKinds, StateOfComesFromTheTable) {
    EXPECT_EQ(stateOf(Kind::Failure), TestStatus::Failed);
    EXPECT_EQ(stateOf(Kind::Crash), TestStatus::Crashed);
    EXPECT_EQ(stateOf(Kind::Report), TestStatus::Passed);
    EXPECT_EQ(stateOf(Kind::Retry), TestStatus::Passed);
    EXPECT_EQ(stateOf(Kind::Probe), TestStatus::Failed);
}

// What a kind is to the listeners: the other columns of the one table (issue 37, item 1).
TEST(EventKinds, WhatAKindIsToTheListenersComesFromTheTable) {
    EXPECT_TRUE(isMessage(Kind::Report));
    EXPECT_TRUE(isMessage(Kind::Check));
    EXPECT_FALSE(isMessage(Kind::Failure));
    EXPECT_TRUE(isCheck(Kind::Check));
    EXPECT_FALSE(isCheck(Kind::Report));

    ResultEvent check;
    check.kind = Kind::Check;
    EXPECT_TRUE(isHiddenCheck(check));
    EXPECT_FALSE(isShown(check, false));
    EXPECT_TRUE(isShown(check, true));
    check.passed = false;
    EXPECT_FALSE(isHiddenCheck(check));
    EXPECT_TRUE(isShown(check, false));
    EXPECT_STREQ(labelOf(Kind::Check, false), "check FAILED");
    EXPECT_STREQ(labelOf(Kind::Check, true), "check ok");
    EXPECT_STREQ(nameOf(Kind::Check, false), "check failed");
    EXPECT_STREQ(labelOf(Kind::Measurement, false), "measurement OUTSIDE LIMITS");
    EXPECT_STREQ(labelOf(Kind::Failure, true), "failure");

    for (Kind kind : {Kind::Failure, Kind::Error, Kind::Crash, Kind::Timeout, Kind::Retry}) {
        EXPECT_TRUE(tripsFailFast(kind)) << toString(kind);
    }
    for (Kind kind : {Kind::Report, Kind::Check, Kind::Skipped, Kind::Interrupted, Kind::Probe}) {
        EXPECT_FALSE(tripsFailFast(kind)) << toString(kind);
    }

    ResultEvent probe;
    probe.kind = Kind::Probe;  // no handler of its own: said as it comes
    EXPECT_TRUE(isSaid(probe));
    ResultEvent measured;
    measured.kind = Kind::Measurement;
    EXPECT_TRUE(isSaid(measured));  // lost its data: said as any other
    measured.measurement = std::make_shared<const Measurement>();
    EXPECT_FALSE(isSaid(measured));
    EXPECT_TRUE(isMeasurement(measured));
    ResultEvent world;
    world.kind = Kind::World;
    EXPECT_FALSE(isSaid(world));
    EXPECT_TRUE(isWorldPhase(Kind::World));
}

TEST(EventKinds, ARepetitionIsShownAsItsReport) {
    ResultEvent repetition;
    repetition.kind = Kind::Repetition;
    repetition.repetition = 2;
    repetition.repetitions = 3;
    ResultEvent scratch;
    const ResultEvent& shown = shownEvent(repetition, scratch);
    EXPECT_EQ(shown.kind, Kind::Report);
    EXPECT_EQ(shown.message.getMessage(), "repetition 2/3");
    ResultEvent report;
    EXPECT_EQ(&shownEvent(report, scratch), &report);
}
