#include "runner/plan/shared_world.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <numeric>

#include <robottestingframework/Exception.h>

#include "core/guarded_call.h"
#include "platform/clock.h"

namespace robottestingframework {
namespace runner {

namespace {

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", value);
    return text;
}

std::size_t root(std::vector<std::size_t>& parent, std::size_t at) {
    while (parent[at] != at) {
        parent[at] = parent[parent[at]];
        at = parent[at];
    }
    return at;
}

}  // namespace

std::string sharedWorldIdentity(const FixtureSpec& fixture) {
    std::error_code ignored;
    const std::string file = fixture.path.empty() ? fixture.plugin.str() : fixture.path.str();
    const std::string path = std::filesystem::absolute(file, ignored).lexically_normal().string();
    return path + '\n' + fixture.param;
}

std::vector<std::size_t> sharedWorldGroups(
    std::size_t suiteCount, const std::vector<std::vector<std::size_t>>& usersOfWorld) {
    std::vector<std::size_t> parent(suiteCount);
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& users : usersOfWorld) {
        for (std::size_t k = 1; k < users.size(); ++k) {
            std::size_t a = root(parent, users[0]);
            std::size_t b = root(parent, users[k]);
            if (a != b) {
                parent[std::max(a, b)] = std::min(a, b);  // the smallest index is the root
            }
        }
    }
    std::vector<std::size_t> group(suiteCount);
    for (std::size_t s = 0; s < suiteCount; ++s) {
        group[s] = root(parent, s);
    }
    return group;
}

// Keeps what the world's manager reports, for each suite that uses it.
class SharedWorld::Capture : public TestListener {
public:
    void onEvent(const RunEvent& event) override {
        std::lock_guard<std::mutex> lock(mutex);
        events.push_back(event);
    }
    std::size_t size() {
        std::lock_guard<std::mutex> lock(mutex);
        return events.size();
    }
    std::mutex mutex;
    std::vector<RunEvent> events;
};

SharedWorld::SharedWorld(std::string name, Factory make)
    : name_(std::move(name)),
      make_(std::move(make)),
      capture_(new Capture()),
      owner_("world " + name_) {
    result_.addListener(capture_.get());
}

SharedWorld::~SharedWorld() {
    result_.removeListener(capture_.get());
}

void SharedWorld::reset() {
    std::lock_guard<std::mutex> lock(mutex_);
    held_ = users_;
    active_.clear();
    interrupted_ = false;
    if (state_ != State::Up && state_ != State::Collapsed) {
        state_ = State::Idle;
    }
}

void SharedWorld::setNetwork(std::shared_ptr<const platform::PrivateNetwork> network) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == State::Idle && !network_) {
        network_ = std::move(network);
    }
}

void SharedWorld::note(const std::string& line, const std::string& phase, const std::string& detail,
                       double at) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        notes_.push_back({line, phase, detail, at});
    }
    if (changed_) {
        changed_();
    }
}

std::vector<SharedWorld::Note> SharedWorld::notes() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Note> taken;
    taken.swap(notes_);
    return taken;
}

SharedWorld::State SharedWorld::state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
}

double SharedWorld::startedAt() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return startedAt_;
}

void SharedWorld::start() {
    // Called with state_ Starting, nothing locked: the others wait on cv_.
    const double began = platform::monotonicSeconds();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        startedAt_ = began;
    }
    const std::string shared = std::to_string(users_) + (users_ == 1 ? " suite" : " suites");
    note("world '" + name_ + "' (shared by " + shared + ") starting", "start", shared, began);
    std::string error;
    std::unique_ptr<FixtureManager> manager = make_(error);
    std::string why;
    bool up = false;
    if (!manager) {
        why = error;
    } else {
        manager->setName(name_);
        manager->setDispatcher(this);
        manager->setResult(&result_, &owner_);
        if (auto* holder = dynamic_cast<WorkerNetwork*>(manager.get())) {
            std::lock_guard<std::mutex> lock(mutex_);
            holder->setWorkerNetwork(network_);
        }
        bool cut = false;
        {
            // The instance of an earlier round (stopped) goes after the lock is let go: its
            // threads may still report to this world.
            std::lock_guard<std::mutex> lock(mutex_);
            manager_.swap(manager);
            // An interrupt while it was made found no manager to cut short: its set-up (a
            // world's whole ready timeout) is not begun.
            cut = interrupted_;
        }
        manager.reset();
        std::lock_guard<std::mutex> call(callMutex_);
        if (cut) {
            why = "interrupted";
        } else if (guardedCall([&] { up = manager_->setup(); }, why) && !up) {
            why = "setup returned false";
        }
    }
    const double ready = platform::monotonicSeconds();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (up && interrupted_) {
            up = false;
            why = "interrupted";
        }
        startEvents_ = capture_->size();
        if (up && state_ == State::Starting) {
            state_ = State::Up;
            readyAt_ = ready;
        } else if (!up) {
            state_ = State::Failed;
            reason_ = TestMessage("shared world '" + name_ + "' did not start: " + why);
        }
    }
    cv_.notify_all();
    if (up) {
        note("world '" + name_ + "' ready after " + seconds(ready - began), "ready", "", ready);
    } else {
        note("world '" + name_ + "' failed to start: " + why, "failed", why, ready);
    }
}

void SharedWorld::replay(std::size_t from, std::size_t to, TestResult& result, const Test* owner) {
    std::vector<RunEvent> events;
    {
        std::lock_guard<std::mutex> lock(capture_->mutex);
        to = std::min(to, capture_->events.size());
        for (std::size_t i = from; i < to; ++i) {
            events.push_back(capture_->events[i]);
        }
    }
    for (RunEvent& event : events) {
        if (isReplayed(event.data.kind)) {  // the column of the kinds' table
            event.test = owner;
            event.suite = nullptr;
            event.happened = 0;
            result.publish(event);
        }
    }
}

bool SharedWorld::acquire(FixtureEvents* suite, TestResult& result, const Test* owner,
                          TestMessage& failure) {
    bool first = false;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (state_ == State::Idle && !interrupted_) {
            state_ = State::Starting;
            first = true;
        } else {
            cv_.wait(lock, [this] { return state_ != State::Starting || interrupted_; });
        }
    }
    if (first) {
        start();
    }
    std::size_t events = 0;
    State now;
    bool cut = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        now = state_;
        events = startEvents_;
        cut = interrupted_;
        if (now == State::Up) {
            active_.insert(suite);
        }
    }
    replay(0, events, result, owner);
    if (cut && now != State::Up) {
        failure = TestMessage("interrupted while shared world '" + name_ + "' was starting");
        return false;
    }
    switch (now) {
        case State::Up:
            return true;
        case State::Collapsed: {
            std::lock_guard<std::mutex> lock(mutex_);
            failure = TestMessage("collapsed before this suite: " + reason_.getMessage(),
                                  reason_.getDetail());
            return false;
        }
        case State::Stopped:
            failure = TestMessage("shared world '" + name_ + "' was stopped");
            return false;
        default: {
            std::lock_guard<std::mutex> lock(mutex_);
            failure = reason_;
            return false;
        }
    }
}

std::string SharedWorld::stopNow() {
    if (!manager_) {
        return {};
    }
    const double began = platform::monotonicSeconds();
    std::string why;
    {
        std::lock_guard<std::mutex> call(callMutex_);
        guardedCall([this] { manager_->tearDown(); }, why);
    }
    double upFor = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        state_ = State::Stopped;
        upFor = began - startedAt_;
    }
    cv_.notify_all();
    const double stopped = platform::monotonicSeconds();
    note("world '" + name_ + "' stopped after " + seconds(stopped - began) + " (up " +
             seconds(upFor) + ")" + (why.empty() ? "" : ": its stop failed: " + why),
         "stop", why.empty() ? why : "its stop failed: " + why, stopped);
    return why.empty() ? why : "shared world '" + name_ + "': " + why;
}

std::string SharedWorld::release(FixtureEvents* suite, TestResult* result, const Test* owner) {
    bool last = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        active_.erase(suite);
        if (held_ > 0) {
            --held_;
        }
        last = held_ == 0 && (state_ == State::Up || state_ == State::Collapsed);
    }
    if (!last) {
        return {};
    }
    const std::size_t from = capture_->size();
    const std::string problem = stopNow();
    if (result != nullptr) {
        replay(from, capture_->size(), *result, owner);
    }
    return problem;
}

std::string SharedWorld::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (state_ != State::Up && state_ != State::Collapsed) {
            return {};
        }
    }
    return stopNow();
}

bool SharedWorld::check(FixtureEvents* suite) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (state_ == State::Collapsed) {
            if (suite != nullptr) {
                suite->fixtureCollapsed(reason_);
            }
            return false;
        }
    }
    // One call at a time; a suite that finds another checking relies on its answer.
    std::unique_lock<std::mutex> call(callMutex_, std::try_to_lock);
    if (!call.owns_lock() || !manager_) {
        return true;
    }
    bool ok = true;
    std::string why;
    if (guardedCall([&] { ok = manager_->check(); }, why) && ok) {
        return true;
    }
    fixtureCollapsed(TestMessage(why.empty() ? "check failed" : why));
    return false;
}

void SharedWorld::interrupt() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        interrupted_ = true;
        if (manager_ && state_ == State::Starting) {
            if (auto* interruptible = dynamic_cast<InterruptibleFixture*>(manager_.get())) {
                interruptible->interruptCall();
            }
        }
    }
    cv_.notify_all();
}

void SharedWorld::fixtureCollapsed(TestMessage reason) {
    std::set<FixtureEvents*> told;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (state_ != State::Up) {
            return;
        }
        state_ = State::Collapsed;
        // The process fixture's reason names the world already ("world 'lab' collapsed: ...").
        const std::string text = reason.getMessage();
        const std::string named = "world '" + name_ + "'";
        reason_ = TestMessage(text.compare(0, named.size(), named) == 0
                                  ? "shared " + text
                                  : "shared " + named + " collapsed: " + text,
                              reason.getDetail());
        reason = reason_;
        told = active_;
    }
    note(reason.getMessage(), "collapsed", reason.getMessage(), platform::monotonicSeconds());
    for (FixtureEvents* suite : told) {
        suite->fixtureCollapsed(reason);
    }
}

SharedWorldFixture::SharedWorldFixture(SharedWorld& world) : world_(world) {
    setName(world.name() + " (shared world)");
}

bool SharedWorldFixture::setup(int, char**) {
    released_ = false;
    TestMessage failure;
    TestResult* result = getResult();
    TestResult none;
    if (!world_.acquire(getDispatcher(), result != nullptr ? *result : none, getOwner(), failure)) {
        throw TestErrorException(failure);
    }
    return true;
}

bool SharedWorldFixture::check() {
    return world_.check(getDispatcher());
}

void SharedWorldFixture::tearDown() {
    if (released_) {
        return;
    }
    released_ = true;
    const std::string problem = world_.release(getDispatcher(), getResult(), getOwner());
    if (!problem.empty()) {
        throw TestErrorException(TestMessage(problem));
    }
}

std::string SharedWorldFixture::releaseIfHeld() {
    if (released_) {
        return {};
    }
    released_ = true;
    return world_.release(getDispatcher(), nullptr, nullptr);
}

}  // namespace runner
}  // namespace robottestingframework
