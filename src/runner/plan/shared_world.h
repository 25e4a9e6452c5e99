// A world shared by the suites of a run (<fixture type="process" scope="run">): one instance,
// started by the first suite that needs it, kept while any suite that needs it has not ended,
// stopped by the last one (docs/reference/world-file.md, "Shared worlds").
//
// Each suite holds a stand-in fixture (SharedWorldFixture) in the world's place among its
// fixtures. Its setup starts the world when it is the first (on the suite's thread), or waits
// until the world is up; the world's reports, output and logs are handed to every suite that
// uses it; a failure to start fails each of them with the world's reason. Its tearDown lets the
// world go; the last suite's tearDown stops it, so a failed stop is that suite's fixture
// tearDown failure, in every report. A collapse of the world reaches every suite running with
// it; the suites after it fail with the reason.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/RunEvent.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "runner/model/suite_model.h"
#include "runner/model/test_executor.h"

namespace robottestingframework {
namespace runner {

// What makes a shared world one: its world file's absolute path and its param once every
// variable is filled in.
std::string sharedWorldIdentity(const FixtureSpec& fixture);

// The suites linked through the worlds they share, each a group that shares one private
// network: for each suite (0..suiteCount-1) the number of its group (the smallest suite index
// of the group). `usersOfWorld`: per world, the suites that need it.
std::vector<std::size_t> sharedWorldGroups(
    std::size_t suiteCount, const std::vector<std::vector<std::size_t>>& usersOfWorld);

class SharedWorld : public FixtureEvents {
public:
    // Makes the fixture manager of one instance (at each start); nullptr and `error` set when
    // it cannot.
    using Factory = std::function<std::unique_ptr<FixtureManager>(std::string& error)>;
    enum class State { Idle, Starting, Up, Failed, Collapsed, Stopped };

    SharedWorld(std::string name, Factory make);
    ~SharedWorld() override;
    SharedWorld(const SharedWorld&) = delete;
    SharedWorld& operator=(const SharedWorld&) = delete;

    const std::string& name() const { return name_; }
    // One more stand-in (one suite) needs it; at plan time.
    void addUser() { ++users_; }
    std::size_t users() const { return users_; }

    // Before a run (a round): every user holds it again; a world of an earlier round is gone.
    void reset();
    // Before it starts: the private network its processes live in (nullptr: the machine's).
    void setNetwork(std::shared_ptr<const platform::PrivateNetwork> network);
    // Called when its state changed (from any thread): the scheduler looks at notes().
    void onChange(std::function<void()> changed) { changed_ = std::move(changed); }

    // A suite's stand-in in its setup: starts the world on this thread if no one has, else
    // waits until it is up. Hands the world's events so far to `result` about `owner`. True
    // when it is up; false and `failure` set when it failed, collapsed or the wait was cut.
    bool acquire(FixtureEvents* suite, TestResult& result, const Test* owner, TestMessage& failure);
    // A user lets it go (its tearDown, or the scheduler for a suite whose tearDown did not
    // run: result nullptr). The last one stops it, on this thread; returns why the stop failed
    // (empty: it did not, or there was nothing to stop).
    std::string release(FixtureEvents* suite, TestResult* result, const Test* owner);
    // Between tests: false when it collapsed (the suite was told).
    bool check(FixtureEvents* suite);
    // Stops it if it is still up (the end of a run); returns why the stop failed.
    std::string stop();
    // Cuts short a start in progress and the waits for it. Thread-safe.
    void interrupt();

    State state() const;
    // When it was started; 0 before (steady seconds, for the order of stops at the end).
    double startedAt() const;
    // What happened to it since the last call: for the console, its line ("world 'lab' (shared
    // by 3 suites) starting"); for the reports, its phase ("start", "ready", "failed",
    // "collapsed", "stop"), a detail and when (steady seconds): a world event (isWorldPhase).
    struct Note {
        std::string line, phase, detail;
        double at = 0;
    };
    std::vector<Note> notes();

    void fixtureCollapsed(TestMessage reason) override;

private:
    class Capture;
    void start();
    std::string stopNow();
    void replay(std::size_t from, std::size_t to, TestResult& result, const Test* owner);
    void note(const std::string& line, const std::string& phase, const std::string& detail,
              double at);

    std::string name_;
    Factory make_;
    std::size_t users_ = 0;
    std::unique_ptr<Capture> capture_;
    TestResult result_;  // where the world's manager reports; kept for every user
    TestSuite owner_;    // what its events are about until handed to a suite
    std::unique_ptr<FixtureManager> manager_;
    std::shared_ptr<const platform::PrivateNetwork> network_;
    std::function<void()> changed_;

    mutable std::mutex mutex_;
    std::condition_variable cv_;
    std::mutex callMutex_;  // one call to the manager at a time (check from many suites)
    State state_ = State::Idle;
    TestMessage reason_;
    std::size_t held_ = 0;
    std::set<FixtureEvents*> active_;  // suites running with it
    std::size_t startEvents_ = 0;      // events of its start, handed to every user
    double startedAt_ = 0, readyAt_ = 0;
    bool interrupted_ = false;
    std::vector<Note> notes_;
};

// A suite's place for a shared world among its fixtures.
class SharedWorldFixture : public FixtureManager, public InterruptibleFixture {
public:
    explicit SharedWorldFixture(SharedWorld& world);
    bool setup(int argc, char** argv) override;
    bool check() override;
    void tearDown() override;
    void interruptCall() override { world_.interrupt(); }

    SharedWorld& world() { return world_; }
    // For the scheduler once the suite ended: lets the world go if its tearDown did not run
    // (its setup failed, an earlier fixture failed, the suite was not run). Returns why a stop
    // it made failed.
    std::string releaseIfHeld();
    // A new round: it holds the world again.
    void reset() { released_ = false; }

private:
    SharedWorld& world_;
    bool released_ = false;
};

}  // namespace runner
}  // namespace robottestingframework
