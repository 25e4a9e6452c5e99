// The line at the bottom of a terminal that says where the run is, at any -j:
//   [3/12] arm :: JointLimits (4.2 s), 1 failed, ETA 0:35
// k of N the tests started of those planned, the latest one that runs and for how long (more at
// once: "+2 running"), the failures so far, and the time left when --durations gives the
// suites' times. It rewrites itself in place (a ticker redraws it while a long test runs); any
// other line the console prints pauses it first, so no line is ever mixed with it. Only on a
// terminal: in a pipe or a file the console stays one line per test.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/TestListener.h>

namespace robottestingframework {
namespace runner {

struct ProgressSettings {
    std::size_t tests = 0;  // N: the tests planned
    unsigned int jobs = 1;  // suites at once (for the ETA)
    bool colours = false;
    unsigned int redrawMilliseconds = 250;  // how often a running test's time moves; 0: never
    // Each planned suite's name and its expected seconds (--durations), < 0 when unknown.
    std::vector<std::pair<std::string, double>> suites;
};

class ProgressLine {
public:
    ProgressLine(std::FILE* stream, ProgressSettings settings);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // What the run does (any thread).
    void suiteStarted(const std::string& suite);
    void suiteEnded(const std::string& suite);
    void testStarted(const Test* test, const std::string& suite, const std::string& name);
    void testRenamed(const Test* test, const std::string& name);
    void testFailed(const Test* test);
    void testEnded(const Test* test);
    void testRetried(const Test* test);  // after its endTest: it runs again, not done yet
    // The run is over: the line goes and is not drawn again until a new round starts.
    void finish();
    void restart();  // a new round (--repeat-until-fail): counts from 0

    // Around any other write to the stream: the line is erased, then drawn again. Nested
    // pauses are fine (the lock is recursive; only the outermost erases and redraws).
    void pause();
    void resume();

    // Listeners for a run whose events come in order on one stream (-j 1): `before` is added
    // before the console, pauses the line and follows the tests; `after` is added after it and
    // draws the line again.
    TestListener& before() { return before_; }
    TestListener& after() { return after_; }

    // The line as it would be drawn now (for the tests of this class).
    std::string text();

private:
    class Before : public TestListener {
    public:
        explicit Before(ProgressLine& line) : line_(line) {}
        void onEvent(const RunEvent& event) override;
        void startTestSuite(const TestSuite* suite) override;
        void endTestSuite(const TestSuite* suite) override;
        void startTest(const Test* test) override;
        void endTest(const Test* test) override;
        void renameTest(const Test* test, const std::string& name) override;
        void retryTest(const Test* test, TestMessage msg) override;
        void addFailure(const Test* test, TestMessage msg) override;
        void addError(const Test* test, TestMessage msg) override;
        void addCrash(const Test* test, TestMessage msg) override;
        void addTimeout(const Test* test, TestMessage msg) override;
        void addInterrupted(const Test* test, TestMessage msg) override;
        void addCheck(const Test* test, TestMessage msg, bool passed) override;
        void addEvent(const Test* test, const ResultEvent& event) override;
        void startTestRunner() override;
        void endTestRunner() override;

    private:
        ProgressLine& line_;
        std::string suite_;  // the suite that runs now (one at a time on this stream)
    };
    class After : public TestListener {
    public:
        explicit After(ProgressLine& line) : line_(line) {}
        void onEvent(const RunEvent& event) override;

    private:
        ProgressLine& line_;
    };
    struct Running {
        std::string suite;
        std::string name;
        std::chrono::steady_clock::time_point started;
        bool failed = false;
    };

    void draw();  // with the lock held
    void tick();
    std::string eta(std::chrono::steady_clock::time_point now) const;

    std::FILE* stream_;
    ProgressSettings settings_;
    std::recursive_mutex mutex_;
    unsigned int paused_ = 0;
    bool shown_ = false;  // a line is on the screen now
    bool active_ = true;  // drawn between the run's start and finish()
    std::size_t started_ = 0;
    std::size_t failed_ = 0;
    std::set<const Test*> seen_;     // started once (a retry starts the same test again)
    std::set<const Test*> counted_;  // ended failed, counted in failed_
    std::map<const Test*, Running> running_;
    std::vector<const Test*> order_;  // running_, in the order they started
    // Suites by name (one suite file can run twice at once): those that run, since when, and
    // how many ended.
    std::multimap<std::string, std::chrono::steady_clock::time_point> suitesRunning_;
    std::map<std::string, unsigned int> suitesEnded_;
    Before before_{*this};
    After after_{*this};
    std::mutex tickMutex_;
    std::condition_variable tickWake_;
    bool stopping_ = false;
    std::thread ticker_;
};

}  // namespace runner
}  // namespace robottestingframework
