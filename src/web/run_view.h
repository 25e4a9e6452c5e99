// The run as the web page shows it: suites, their tests (planned ones too), states, durations
// and messages, plus the numbered list of changes the page follows. Thread-safe: the run's
// thread writes, the server's threads read.
//
// Tests are found by the id their events carry (Test::getId()), never by name or order: two
// tests may share a name, and a test may rename itself while it runs.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestStatus.h>

namespace robottestingframework {
namespace web {

class RunView {
public:
    explicit RunView(bool verbose);

    // What the listener feeds in.
    void startRun();
    void endRun();
    struct Planned {
        std::uint64_t id;
        std::string name;
    };
    // The run's plan, given before it starts: every suite and its tests are on the page from
    // the start ("waiting" suites, "not run" tests), also those a parallel run (-j N) starts
    // later. A suite that starts takes the first waiting one of its name.
    struct PlannedSuite {
        std::string name;
        std::vector<Planned> tests;
    };
    void setPlan(const std::vector<PlannedSuite>& suites);
    // `id`: the suite's own (Test::getId()), which its fixture's messages carry; 0 for none.
    void startSuite(const std::string& name, const std::vector<Planned>& tests,
                    std::uint64_t id = 0);
    // Ends the latest open suite named `name` (suites side by side end in any order); the
    // innermost one when `name` is empty or not open.
    void endSuite(const std::string& name = {});
    void startTest(std::uint64_t id, const std::string& name);
    void endTest(std::uint64_t id);
    void renameTest(std::uint64_t id, const std::string& name);
    // A message about the running test `id`, else (a suite's id, a fixture) the open suite.
    // `status` is the state it gives (Passed for none).
    void addMessage(std::uint64_t id, const char* kind, const TestMessage& msg, TestStatus status);
    void addOutput(std::uint64_t id, const std::string& text);
    // The test `id` just ended failing and runs again (--retries): it is open again at its
    // next startTest, and flaky if that attempt passes.
    void retryTest(std::uint64_t id);
    // Repetition `index` of `count` of the running test `id` starts: its later messages carry
    // the repetition's id (repetitionId), and the test shows the one it is in.
    void startRepetition(std::uint64_t id, unsigned int index, unsigned int count);
    // The recent runs of the test "SUITE/TEST" (JSON, --history): shown with it once its suite
    // starts.
    void setTestHistory(const std::string& testId, const std::string& json);
    // The running test `id` measured something: shown beside its trend from --history.
    struct MeasurementView {
        std::string name;
        double value = 0;
        std::string unit;
        std::optional<double> low;
        std::optional<double> high;
        bool passed = true;
    };
    void addMeasurement(std::uint64_t id, MeasurementView measurement);
    // The test `id` attached a file (already copied): listed, with a link served from
    // /attachments/N, once the run has ended.
    struct AttachmentView {
        std::string test;  // the name the test is shown by
        std::string name;  // the file's own name
        std::string description;
        std::string absolutePath;  // the copy the link serves
        std::string contentType;
    };
    void addAttachment(std::uint64_t id, AttachmentView attachment);
    // The attachment numbered `index` (from 0), if there is one.
    bool attachment(std::size_t index, AttachmentView& found) const;

    // A world shared by suites (<fixture scope="run">) changed: `phase` "start" (`detail`: how
    // many suites share it), "ready", "failed", "collapsed" (`detail`: why) or "stop". Each
    // world is a lane of the page: its state and times.
    void worldPhase(const std::string& name, const std::string& phase, const std::string& detail);
    // Wakes the readers waiting in waitForChanges(), for good: the server is stopping.
    void close();

    // What the server reads.
    std::string snapshotJson() const;  // {"seq":N,"run":{...},"suites":[...]}
    std::string statusJson() const;    // RTF 2.x: {"name":"<suite>","testStatus":[0..3,...]}
    std::string logText() const;       // RTF 2.x: the log, HTML-escaped
    // Appends the changes after `since` to `out` as Server-Sent Events, waiting up to
    // `timeout` for one. Returns the number of the last change written (`since` when none);
    // `closed` tells the stream to end.
    std::uint64_t waitForChanges(std::uint64_t since, std::chrono::milliseconds timeout,
                                 std::string& out, bool& closed) const;

    struct Message {
        std::string kind;  // "failure", "error", "report", ...
        std::string text;
        std::string where;        // "file:line" when known
        std::string diagnostics;  // TestMessage::diagnosticsText: shown as a block under it
        std::string repetition;   // the id of the repetition it came in; empty for none
    };
    // A test as the page shows it (the snapshot and each change of it).
    struct TestView {
        std::uint64_t id = 0;
        std::string name;
        std::string state = "not run";  // "not run", "running", or toString(TestStatus)
        TestStatus worst = TestStatus::Passed;
        std::chrono::steady_clock::time_point started;
        double startedAt = 0;  // seconds on the view's clock ("now" of what the page reads)
        double duration = 0;
        std::vector<Message> messages;
        std::size_t hiddenReports = 0;  // messages beyond the caps, counted only
        std::string output;
        std::size_t retries = 0;  // earlier failed attempts
        std::string repetition;   // the id of the repetition it is in; empty when it runs once
        std::string history;      // its recent runs (JSON), when --history gave them
        std::vector<MeasurementView> measurements;  // in the order measured, capped
    };

private:
    struct SuiteView {
        std::string name;
        std::uint64_t id = 0;
        std::string state = "running";  // "waiting" (planned), "running", "passed", "failed"
        bool failed = false;
        std::chrono::steady_clock::time_point started;
        double startedAt = 0;  // on the view's clock, as TestView's
        double duration = 0;
        std::vector<Message> messages;
        std::size_t hiddenReports = 0;
        std::vector<TestView> tests;
    };
    static constexpr std::size_t none = static_cast<std::size_t>(-1);

    // All below with mutex_ held.
    SuiteView& openSuite();
    // A planned test of `suite`, with its recent runs when --history gave them.
    TestView plannedTest(const std::string& suite, const Planned& test) const;
    struct Place {
        std::size_t suite;
        std::size_t test;
    };
    // Where the running test `id` is; none when no test runs with it.
    std::optional<Place> findOpen(std::uint64_t id) const;
    TestView& testAt(Place place) { return suites_[place.suite].tests[place.test]; }
    void publishRun();
    void publishSuite(std::size_t suite);
    void publishTest(std::size_t suite, std::size_t test);
    // `key` names what the change is about ("run", "s3", "t3.7"): it carries the whole state
    // of that, so the change it replaces is not kept (the changes kept stay one per thing).
    void publish(const std::string& key, std::string json);
    void log(const std::string& line);
    std::string runJson() const;

    // Seconds since the view was made. The snapshot and every change say it ("now"), and
    // running tests and suites when they started on it: the page ticks their elapsed time.
    double clock() const;

    const bool verbose_;
    const std::chrono::steady_clock::time_point origin_ = std::chrono::steady_clock::now();
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    bool closed_ = false;
    std::string runState_ = "waiting";  // "waiting", "running", "finished"
    std::chrono::steady_clock::time_point runStarted_;
    double runDuration_ = 0;
    std::size_t counts_[3] = {};  // passed, failed, skipped
    std::vector<SuiteView> suites_;
    struct WorldView {
        std::string name;
        std::string users;
        std::string state = "starting";  // "starting", "ready", "failed", "collapsed", "stopped"
        double startedAt = 0;            // on the view's clock; the others -1 until they happen
        double readyAt = -1;
        double stoppedAt = -1;
        std::string reason;
    };
    std::vector<WorldView> worlds_;
    void publishWorld(std::size_t index);
    std::vector<AttachmentView> attachments_;  // at most maxAttachments
    std::vector<std::size_t> openSuites_;      // innermost last
    std::size_t openSuite_ = none;             // where tests go: the innermost open suite
    struct OpenTest {
        std::uint64_t id;
        Place place;
    };
    std::vector<OpenTest> openTests_;  // the running ones, innermost last
    struct Ended {
        std::uint64_t id = 0;  // 0 for none
        std::size_t suite = none;
        std::size_t test = none;
    };
    Ended ended_;  // the test that ended last, which a retry reopens
    std::map<std::uint64_t, std::string> changes_;  // by number (from 1), as JSON
    std::map<std::string, std::uint64_t> latest_;   // key -> the number of its latest change
    std::uint64_t lastChange_ = 0;
    std::string log_;
    std::map<std::string, std::string> history_;  // test id -> its recent runs (JSON)
};

}  // namespace web
}  // namespace robottestingframework
