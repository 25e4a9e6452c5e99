// Process isolation with real plug-ins: whatever a test or fixture does (crash, abort, exit,
// throw, hang, ignore SIGTERM, leave children), the runner gets the right state and message,
// and no process of the run is left behind.
#include <gtest/gtest.h>

#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/Exception.h>
#include <robottestingframework/FixtureEvents.h>
#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/Test.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>

#include "build_paths.h"
#include "platform/clock.h"
#include "runner/execution/isolated_executor.h"

using namespace robottestingframework;
using Kind = ResultEvent::Kind;
using isolation::IsolatedExecutor;
using isolation::IsolationOptions;

namespace {

std::string plugin(const std::string& name) {
    return std::string(build_paths::testPluginDir()) + "/" + name + ".so";
}

class StandIn : public Test {
public:
    explicit StandIn(const std::string& name) : Test(name) {}
    void run(TestResult& /*result*/) override {}
    bool succeeded() const override { return true; }
};

struct Event {
    Kind kind;
    std::string text;  // message and detail
};

class Recorder : public TestListener {
public:
    std::vector<Event> events;
    int starts = 0, ends = 0;
    std::string output;

    bool has(Kind kind, const std::string& part) const {
        for (const Event& e : events) {
            if (e.kind == kind && e.text.find(part) != std::string::npos) {
                return true;
            }
        }
        return false;
    }
    std::string dump() const {
        std::string text;
        for (const Event& e : events) {
            text += std::string(toString(e.kind)) + ": " + e.text + "\n";
        }
        return text + "output: " + output;
    }

    void add(Kind kind, const TestMessage& msg) { events.push_back({kind, msg.toString()}); }
    void startTest(const Test*) override { ++starts; }
    void endTest(const Test*) override { ++ends; }
    void addReport(const Test*, TestMessage msg) override { add(Kind::Report, msg); }
    void addError(const Test*, TestMessage msg) override { add(Kind::Error, msg); }
    void addFailure(const Test*, TestMessage msg) override { add(Kind::Failure, msg); }
    void addCheck(const Test*, TestMessage msg, bool) override { add(Kind::Check, msg); }
    void addSkipped(const Test*, TestMessage msg) override { add(Kind::Skipped, msg); }
    void addCrash(const Test*, TestMessage msg) override { add(Kind::Crash, msg); }
    void addTimeout(const Test*, TestMessage msg) override { add(Kind::Timeout, msg); }
    void addInterrupted(const Test*, TestMessage msg) override { add(Kind::Interrupted, msg); }
    void addOutput(const Test*, const std::string& text) override { output += text; }
};

class Collapses : public FixtureEvents {
public:
    std::atomic<int> count{0};
    std::string last;
    void fixtureCollapsed(TestMessage reason) override {
        last = reason.toString();
        ++count;
    }
};

// Every process whose environment carries the marker: the ones this test started.
// Field 6 of /proc/PID/stat (after the command in parentheses) is the session id.
bool leadsItsSession(const std::string& stat, pid_t pid) {
    std::istringstream fields(stat.substr(stat.rfind(')') + 1));
    std::string state;
    long parent = 0, group = 0, session = 0;
    fields >> state >> parent >> group >> session;
    return session == pid;
}

// The portable-POSIX build's parent-death guards (process_lifetime-portable.cpp) carry the
// marker too; they lead their own session, which no other process of a run does.
enum class Guards { Counted, LeftOut, Only };

std::vector<pid_t> markedProcesses(const std::string& marker, Guards guards = Guards::LeftOut) {
    std::vector<pid_t> found;
    std::string needle = "RTF_TEST_MARKER=" + marker;
    needle.push_back('\0');
    DIR* proc = ::opendir("/proc");
    while (dirent* entry = ::readdir(proc)) {
        pid_t pid = static_cast<pid_t>(std::atol(entry->d_name));
        if (pid <= 0 || pid == ::getpid()) {
            continue;
        }
        std::ifstream in("/proc/" + std::to_string(pid) + "/environ");
        std::stringstream text;
        text << in.rdbuf();
        std::string stat;
        std::ifstream statFile("/proc/" + std::to_string(pid) + "/stat");
        std::getline(statFile, stat);
        bool zombie = stat.find(") Z") != std::string::npos;
        bool guard = leadsItsSession(stat, pid);
        bool wanted = guards == Guards::Counted || (guards == Guards::Only) == guard;
        if (!zombie && wanted && text.str().find(needle) != std::string::npos) {
            found.push_back(pid);
        }
    }
    ::closedir(proc);
    return found;
}

bool noneLeft(const std::string& marker, double seconds) {
    platform::Deadline deadline(seconds);
    while (!markedProcesses(marker, Guards::Counted).empty()) {
        if (deadline.expired()) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
}

std::string freshMarker() {
    static int counter = 0;
    std::string marker = "iso-" + std::to_string(::getpid()) + "-" + std::to_string(++counter);
    ::setenv("RTF_TEST_MARKER", marker.c_str(), 1);
    return marker;
}

class Isolation : public ::testing::Test {
protected:
    void SetUp() override {
        marker = freshMarker();
        options.workerPath = build_paths::workerPath();
        options.killGrace = 0.3;
        options.fixtureTimeout = 2.0;
        executor.reset(new IsolatedExecutor(options));
        std::string error;
        ASSERT_TRUE(executor->start(error)) << error;
        result.addListener(&recorder);
    }
    void TearDown() override {
        executor.reset();
        EXPECT_TRUE(noneLeft(marker, 5.0)) << "processes of this test outlived it";
        ::unsetenv("RTF_TEST_MARKER");
    }

    TestStatus run(const std::string& name, double timeout = 0, const std::string& param = "",
                   unsigned int repetition = 1) {
        runner::TestSpec spec;
        spec.plugin = name;
        spec.path = plugin(name);
        spec.type = "dll";
        spec.param = param;
        spec.timeout = timeout;
        spec.repetition = repetition;
        TestStatus status = executor->run(spec, self, result);
        EXPECT_EQ(recorder.starts, 1) << recorder.dump();
        EXPECT_EQ(recorder.ends, 1) << recorder.dump();
        return status;
    }

    std::string marker;
    IsolationOptions options;
    std::unique_ptr<IsolatedExecutor> executor;
    StandIn self{"stand-in"};
    Recorder recorder;
    TestResult result;
};

}  // namespace

TEST_F(Isolation, PassingTestPassesUnderItsOwnName) {
    EXPECT_EQ(run("passing_test"), TestStatus::Passed) << recorder.dump();
    EXPECT_EQ(self.getName(), "PassingTest");
}

TEST_F(Isolation, SegfaultIsACrashNamingTheSignalAndKeepsWhatCameBefore) {
    EXPECT_EQ(run("crash_segv"), TestStatus::Crashed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Crash, "SIGSEGV")) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Report, "about to dereference a null pointer"));
    EXPECT_NE(recorder.output.find("last words before the crash"), std::string::npos)
        << recorder.dump();
}

TEST_F(Isolation, AbortIsACrashWithSigabrt) {
    EXPECT_EQ(run("crash_abort"), TestStatus::Crashed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Crash, "SIGABRT")) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Report, "about to abort"));
}

TEST_F(Isolation, ExitIsAnErrorWithTheStatus) {
    EXPECT_EQ(run("exit3"), TestStatus::Error) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Error, "exited with status 3")) << recorder.dump();
}

TEST_F(Isolation, ThrownIntIsAnErrorOfUnknownType) {
    EXPECT_EQ(run("throw_int"), TestStatus::Error) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Error, "unhandled exception of unknown type"))
        << recorder.dump();
}

TEST_F(Isolation, ThrownRuntimeErrorCarriesItsText) {
    EXPECT_EQ(run("throw_runtime"), TestStatus::Error) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Error, "the motor driver is on fire")) << recorder.dump();
}

TEST_F(Isolation, BlockedTestTimesOutWithTheLimitAndWhatItSaid) {
    double start = platform::monotonicSeconds();
    EXPECT_EQ(run("hang_block", 1.5), TestStatus::TimedOut) << recorder.dump();
    EXPECT_LT(platform::monotonicSeconds() - start, 4.0);
    EXPECT_TRUE(recorder.has(Kind::Timeout, "timed out after 1.5 s")) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Timeout, "waiting for a message that never comes"));
    EXPECT_TRUE(recorder.has(Kind::Report, "waiting for a message that never comes"));
}

TEST_F(Isolation, SpinningTestTimesOut) {
    EXPECT_EQ(run("hang_spin", 0.3), TestStatus::TimedOut) << recorder.dump();
}

TEST_F(Isolation, TestIgnoringSigtermIsKilledAfterTheGrace) {
    double start = platform::monotonicSeconds();
    EXPECT_EQ(run("ignore_sigterm", 0.3), TestStatus::TimedOut) << recorder.dump();
    double took = platform::monotonicSeconds() - start;
    EXPECT_GE(took, 0.6);  // the limit, then the grace
    EXPECT_LT(took, 3.0);
    EXPECT_TRUE(recorder.has(Kind::Timeout, "ignored SIGTERM")) << recorder.dump();
}

TEST_F(Isolation, ChildLeftBehindByAPassingTestIsGoneAtItsEnd) {
    EXPECT_EQ(run("fork_sleeper"), TestStatus::Passed) << recorder.dump();
    // The test reports the child's pid ("left child N behind"). Counting marked processes
    // flaked: the fork server starts a spare worker ahead of the next test at any moment.
    pid_t child = 0;
    for (const Event& e : recorder.events) {
        const std::size_t at = e.text.find("left child ");
        if (e.kind == Kind::Report && at != std::string::npos) {
            child = static_cast<pid_t>(std::atol(e.text.c_str() + at + 11));
        }
    }
    ASSERT_GT(child, 0) << recorder.dump();
    auto alive = [&] {
        const std::vector<pid_t> marked = markedProcesses(marker, Guards::Counted);
        return std::find(marked.begin(), marked.end(), child) != marked.end();
    };
    platform::Deadline deadline(2.0);
    while (alive() && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_FALSE(alive()) << "the left child " << child << " is gone";
}

TEST_F(Isolation, HungTestWithAChildLosesBothOnTimeout) {
    EXPECT_EQ(run("fork_sleeper", 0.3, "--hang"), TestStatus::TimedOut) << recorder.dump();
}

TEST_F(Isolation, CrashInSetupIsACrash) {
    EXPECT_EQ(run("crash_in_setup"), TestStatus::Crashed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Report, "setting up"));
    EXPECT_FALSE(recorder.has(Kind::Report, "never here"));
}

TEST_F(Isolation, CrashInTearDownIsACrashAfterTheChecks) {
    EXPECT_EQ(run("crash_in_teardown"), TestStatus::Crashed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Check, "ran fine"));
    EXPECT_TRUE(recorder.has(Kind::Crash, "SIGABRT"));
}

TEST_F(Isolation, InterruptFromAnotherThreadStopsTheTest) {
    std::thread interrupter([this] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        executor->interrupt();
    });
    EXPECT_EQ(run("hang_block"), TestStatus::Interrupted) << recorder.dump();
    interrupter.join();
    EXPECT_TRUE(recorder.has(Kind::Interrupted, "stopped while running")) << recorder.dump();
    // Every listener puts the kind's word before the message ("interrupted: stopped while
    // running: ..."): the message does not say it again.
    EXPECT_FALSE(recorder.has(Kind::Interrupted, "interrupted")) << recorder.dump();
}

TEST_F(Isolation, RepetitionsRunInTheWorker) {
    EXPECT_EQ(run("passing_test", 0, "", 3), TestStatus::Passed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Report, "repetition 3/3")) << recorder.dump();
}

TEST_F(Isolation, CriticalErrorReachesTheStandIn) {
    EXPECT_EQ(run("critical_error"), TestStatus::Error) << recorder.dump();
    EXPECT_TRUE(self.hasCriticalError());
    EXPECT_NE(self.getCriticalError().getMessage().find("the robot is not powered"),
              std::string::npos);
}

TEST_F(Isolation, UnloadablePluginIsAFailedTestWithTheLoadersReason) {
    EXPECT_EQ(run("not_a_plugin"), TestStatus::Failed) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Failure, "cannot load")) << recorder.dump();
}

TEST_F(Isolation, ManyTestsInARowShareOneForkServer) {
    for (int i = 0; i < 50; ++i) {
        Recorder local;
        TestResult localResult;
        localResult.addListener(&local);
        runner::TestSpec spec;
        spec.plugin = spec.path = plugin("passing_test");
        spec.type = "dll";
        ASSERT_EQ(executor->run(spec, self, localResult), TestStatus::Passed) << local.dump();
    }
    // The last worker may still be exiting after it said it finished.
    // The count asserted is the one the loop saw: the server may fork a new spare between two
    // reads, for a moment one more than the three.
    platform::Deadline deadline(2.0);
    std::size_t marked = markedProcesses(marker).size();
    while (marked > 3 && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        marked = markedProcesses(marker).size();
    }
    EXPECT_LE(marked, 3u) << "the fork server and its two spares alone";
    // A worker's guard leaves within its poll interval of the worker: only the server's and the
    // spares' remain (none where the platform has prctl).
    while (markedProcesses(marker, Guards::Only).size() > 3 && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_LE(markedProcesses(marker, Guards::Only).size(), 3u) << "guards of ended workers left";
    recorder.starts = recorder.ends = 1;  // this test did not use the shared recorder
}

TEST_F(Isolation, FixtureCrashingInSetupFailsSetupWithTheReason) {
    runner::FixtureSpec spec;
    spec.plugin = spec.path = plugin("fixture_crash_setup");
    spec.type = "dll";
    std::string error;
    std::unique_ptr<FixtureManager> fixture = executor->makeFixture(spec, error);
    ASSERT_NE(fixture, nullptr) << error;
    Collapses collapses;
    fixture->setDispatcher(&collapses);
    fixture->setResult(&result, &self);
    ArgumentVector args("");
    // The reason goes to the suite with the exception (which hands it on to skipped tests).
    std::string reason;
    try {
        fixture->setup(args.argc(), args.argv());
    } catch (const TestErrorException& e) {
        reason = e.what();
    }
    EXPECT_TRUE(recorder.has(Kind::Report, "starting the simulator")) << recorder.dump();
    EXPECT_NE(reason.find("SIGSEGV"), std::string::npos) << reason;
    recorder.starts = recorder.ends = 1;
}

TEST_F(Isolation, FixtureCollapseFromItsThreadReachesTheDispatcher) {
    runner::FixtureSpec spec;
    spec.plugin = spec.path = plugin("fixture_collapse");
    spec.type = "dll";
    std::string error;
    std::unique_ptr<FixtureManager> fixture = executor->makeFixture(spec, error);
    ASSERT_NE(fixture, nullptr) << error;
    Collapses collapses;
    fixture->setDispatcher(&collapses);
    fixture->setResult(&result, &self);
    ArgumentVector args("");
    ASSERT_TRUE(fixture->setup(args.argc(), args.argv())) << recorder.dump();
    EXPECT_TRUE(recorder.has(Kind::Report, "world is up"));
    platform::Deadline deadline(5.0);
    while (collapses.count == 0 && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_EQ(collapses.count, 1);
    EXPECT_NE(collapses.last.find("the simulator fell over"), std::string::npos);
    fixture->tearDown();
    EXPECT_EQ(collapses.count, 1) << "a clean tear-down is no collapse: " << collapses.last;
    recorder.starts = recorder.ends = 1;
}

TEST_F(Isolation, FixtureDyingBetweenCallsCollapsesWithItsStatus) {
    runner::FixtureSpec spec;
    spec.plugin = spec.path = plugin("fixture_collapse");
    spec.type = "dll";
    spec.param = "--die-after-setup";
    std::string error;
    std::unique_ptr<FixtureManager> fixture = executor->makeFixture(spec, error);
    ASSERT_NE(fixture, nullptr) << error;
    Collapses collapses;
    fixture->setDispatcher(&collapses);
    fixture->setResult(&result, &self);
    fixture->setParam("--die-after-setup");
    ArgumentVector args("--die-after-setup");
    ASSERT_TRUE(fixture->setup(args.argc(), args.argv())) << recorder.dump();
    platform::Deadline deadline(5.0);
    while (collapses.count == 0 && !deadline.expired()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_EQ(collapses.count, 1);
    EXPECT_NE(collapses.last.find("exited with status 7"), std::string::npos) << collapses.last;
    EXPECT_THROW(fixture->check(), TestErrorException) << "a dead fixture's check says why";
    recorder.starts = recorder.ends = 1;
}

// The runner killed with SIGKILL while a test (and the child it forked) hang: the fork server
// must still take every process of the run with it.
TEST(IsolationRunnerDeath, NoProcessSurvivesTheRunnerBeingKilled) {
    std::string marker = freshMarker();
    pid_t runner = ::fork();
    if (runner == 0) {
        IsolationOptions options;
        options.workerPath = build_paths::workerPath();
        IsolatedExecutor executor(options);
        StandIn self("x");
        TestResult result;
        runner::TestSpec spec;
        spec.plugin = spec.path = plugin("fork_sleeper");
        spec.type = "dll";
        spec.param = "--hang";
        executor.run(spec, self, result);
        ::_exit(0);
    }
    ASSERT_GT(runner, 0);
    // Server, its two spares, worker and the worker's child. In the portable build a
    // parent-death guard counts for a moment while it is started (before it leads its session
    // of its own): the five must be there in three readings in a row.
    platform::Deadline deadline(10.0);
    for (int steady = 0; steady < 3 && !deadline.expired();) {
        steady = markedProcesses(marker).size() == 5 ? steady + 1 : 0;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_EQ(markedProcesses(marker).size(), 5u);
    ::kill(runner, SIGKILL);
    int status;
    ::waitpid(runner, &status, 0);
    EXPECT_TRUE(noneLeft(marker, 5.0))
        << markedProcesses(marker, Guards::Counted).size() << " left";
    ::unsetenv("RTF_TEST_MARKER");
}
