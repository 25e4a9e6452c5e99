#include "runner/execution/in_process_executor.h"

#include <robottestingframework/ResultEvent.h>
#include <robottestingframework/TestResult.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <sstream>
#include <thread>

#include "core/events.h"
#include "languages/plugin_locator.h"
#include "runner/model/stand_in_test.h"

namespace robottestingframework {
namespace runner {

namespace {

// The fixture manager the suite holds: forwards to the one the plug-in made, and keeps the
// plug-in loaded as long as it lives.
class LoadedFixtureManager : public FixtureManager, public InterruptibleFixture {
public:
    explicit LoadedFixtureManager(std::unique_ptr<languages::LoadedFixture> loaded)
        : loaded_(std::move(loaded)) {}

    bool setup(int argc, char** argv) override {
        FixtureManager* inner = sync();
        inner->setParam(getParam());
        return inner->setup(argc, argv);
    }
    bool check() override { return sync()->check(); }
    void tearDown() override { sync()->tearDown(); }
    // Ctrl-C while its set-up runs on the runner's thread (--isolation none): a process
    // fixture stops awaiting its world.
    void interruptCall() override { loaded_->interrupt(); }

private:
    // The suite sets its dispatcher and result on this object; the plug-in reports through its
    // own, so pass them on before each call.
    FixtureManager* sync() {
        FixtureManager* inner = loaded_->get();
        inner->setDispatcher(getDispatcher());
        inner->setResult(getResult(), getOwner());
        if (inner->getName().empty()) {
            inner->setName(getName());
        }
        return inner;
    }

    std::unique_ptr<languages::LoadedFixture> loaded_;
};

// Calls `expire` on a thread of its own once `seconds` have passed, unless destroyed before.
class Watchdog {
public:
    template <typename Expire>
    Watchdog(double seconds, Expire expire) {
        if (seconds <= 0) {
            return;
        }
        thread_ = std::thread([this, seconds, expire] {
            std::unique_lock<std::mutex> lock(mutex_);
            if (!changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                                   [this] { return done_; })) {
                lock.unlock();
                expire();
            }
        });
    }
    ~Watchdog() {
        if (thread_.joinable()) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                done_ = true;
            }
            changed_.notify_all();
            thread_.join();
        }
    }
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

private:
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable changed_;
    bool done_ = false;
};

}  // namespace

// Passes the test case's events on to the run's result as events of the stand-in, whatever
// their kind, and keeps the worst state they carried. The stand-in takes the test case's name at
// each event: a script may name itself in setup, after startTest.
class InProcessExecutor::Relay : public TestListener {
public:
    void begin(TestResult& target, Test& self, double timeout) {
        target_ = &target;
        self_ = &self;
        shown_ = self.getName();
        status_ = TestStatus::Passed;
        timeout_ = timeout;
        timedOut_ = false;
    }
    TestStatus status() const { return status_; }
    // The watchdog stopped the test: its interruption is reported as the timeout it is.
    void timedOut() { timedOut_ = true; }

    void onEvent(const RunEvent& event) override {
        const Test* self = sync(event.test);
        if (renamesTest(event.data.kind)) {
            return;  // sync() told the listeners already, as the stand-in's new name
        }
        RunEvent relayed = event;
        relayed.test = self;
        if (timedOut_ && stateOf(event.data.kind) == TestStatus::Interrupted) {
            // The watchdog asked the test to stop: its interruption is the timeout it is.
            ResultEvent timeout = events::timeout(TestMessage(
                "timed out after " + seconds(timeout_), event.data.message.getMessage()));
            timeout.testName = event.data.testName;
            timeout.testId = event.data.testId;
            timeout.time = event.data.time;
            timeout.repetition = event.data.repetition;
            relayed.data = std::move(timeout);
        }
        const TestStatus state = stateOf(relayed.data.kind);
        if (state != TestStatus::Passed) {  // the lowest: most events leave the state as it is
            worsen(state);
        }
        target_->publish(relayed);
    }

private:
    void worsen(TestStatus status) {
        std::lock_guard<std::mutex> lock(mutex_);
        status_ = std::max(status_, status);
    }
    const Test* sync(const Test* test) {
        if (test != nullptr && test != self_) {
            std::string name = test->getName();
            if (!name.empty() && name != shown_) {
                // The stand-in takes the name; the listeners hear of it as an event.
                self_->setName(name);
                shown_ = self_->getName();
                target_->renameTest(self_, name);
            }
        }
        return self_;
    }
    static std::string seconds(double value) {
        std::ostringstream text;
        text << value << " s";
        return text.str();
    }

    TestResult* target_ = nullptr;
    Test* self_ = nullptr;
    std::string shown_;  // self_->getName(), not copied again for each event
    std::mutex mutex_;
    TestStatus status_ = TestStatus::Passed;
    double timeout_ = 0;
    std::atomic<bool> timedOut_{false};
};

InProcessExecutor::InProcessExecutor() : relay_(std::make_unique<Relay>()) {
    relayed_.addListener(relay_.get());
}

InProcessExecutor::~InProcessExecutor() = default;

TestStatus InProcessExecutor::notLoaded(const TestSpec& spec, Test& self, TestResult& result,
                                        const std::string& reason) {
    self.setName(PluginTest::displayName(spec));
    result.startTest(&self);
    result.addFailure(&self, TestMessage("cannot load " + spec.plugin, reason));
    result.endTest(&self);
    return TestStatus::Failed;
}

bool InProcessExecutor::locate(const TestSpec& spec, std::string& error) {
    Located& last = located_;
    if (last.valid && spec.plugin.sharesWith(last.plugin) && spec.path.sharesWith(last.path) &&
        (spec.type.empty() ? last.type.empty() : spec.type.sharesWith(last.type)) &&
        spec.where.file.sharesWith(last.file)) {
        return true;
    }
    last.valid = false;
    if (!languages::locatePlugin(spec.plugin, spec.path, spec.type, spec.where.file, last.foundPath,
                                 last.foundType, error)) {
        return false;
    }
    last.plugin = spec.plugin;
    last.path = spec.path;
    last.type = spec.type;
    last.file = spec.where.file;
    last.valid = true;
    return true;
}

TestStatus InProcessExecutor::run(const TestSpec& spec, Test& self, TestResult& result) {
    std::string error;
    if (!locate(spec, error)) {
        return notLoaded(spec, self, result, error);
    }
    const std::string& path = located_.foundPath;  // run() is not re-entered while it runs
    const std::string& type = located_.foundType;
    std::unique_ptr<languages::LoadedTest> loaded;
    try {
        loaded = languages::loadTest(type, path, error);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!loaded || loaded->get() == nullptr) {
        return notLoaded(spec, self, result, error);
    }

    TestCase* test = loaded->get();
    test->setParam(spec.param);
    test->setEnvironment(spec.environment);
    test->setRepetition(spec.repetition == 0 ? 1 : spec.repetition);
    if (!spec.name.empty()) {
        test->setName(spec.name);
    }
    self.setName(test->getName().empty() ? PluginTest::displayName(spec) : test->getName());
    self.setDescription(test->getDescription());

    // The test case sends its events about itself; the relay makes them the stand-in's.
    relay_->begin(result, self, spec.timeout);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = test;
    }
    {
        // A timeout can only ask the test to stop (TestCase::interrupt): a C++ test that
        // never looks can't be stopped in this process; --isolation process can.
        Watchdog watchdog(spec.timeout, [this] {
            std::lock_guard<std::mutex> lock(mutex_);
            if (running_ != nullptr) {
                relay_->timedOut();
                running_->interrupt();
            }
        });
        test->run(relayed_);
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = nullptr;
    }
    if (test->hasCriticalError()) {
        self.setCriticalError(test->getCriticalError());
    }
    TestStatus status = relay_->status();
    if (status == TestStatus::Passed && !test->succeeded()) {
        status = TestStatus::Failed;
    }

    // Replacing the previous object of this file only now keeps its library loaded meanwhile.
    loaded_[path] = std::move(loaded);
    return status;
}

void InProcessExecutor::interrupt() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_ != nullptr) {
        running_->interrupt();
    }
}

std::unique_ptr<FixtureManager> InProcessExecutor::makeFixture(const FixtureSpec& spec,
                                                               std::string& error) {
    std::string path;
    std::string type;
    if (!languages::locatePlugin(spec.plugin, spec.path, spec.type, spec.where.file, path, type,
                                 error)) {
        return nullptr;
    }
    std::unique_ptr<languages::LoadedFixture> loaded;
    try {
        loaded = languages::loadFixture(type, path, error);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!loaded || loaded->get() == nullptr) {
        return nullptr;
    }
    auto manager = std::make_unique<LoadedFixtureManager>(std::move(loaded));
    manager->setName(spec.plugin);
    manager->setParam(spec.param);
    return manager;
}

}  // namespace runner
}  // namespace robottestingframework
