#include "runner/schedule/scheduler.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

#include <robottestingframework/TestSuite.h>

#include "core/events.h"
#include "core/not_run_reasons.h"
#include "platform/environment.h"
#include "platform/private_network.h"
#include "variables/variables.h"

namespace robottestingframework {
namespace runner {

namespace {

// Follows which test of a suite runs now, for the line of what runs.
class Current : public TestListener {
public:
    void startTest(const Test* test) override { name = test != nullptr ? test->getName() : ""; }
    void endTest(const Test*) override { name.clear(); }
    std::string name;
};

std::string quote(const std::string& name) {
    return "\"" + name + "\"";
}

}  // namespace

struct Scheduler::Job {
    Job(std::size_t at, std::function<void()> wake) : index(at), events(std::move(wake)) {
        result.addListener(&events);
    }
    enum class State { Waiting, Running, Finished };

    std::size_t index;
    State state = State::Waiting;
    SuiteEvents events;  // what the suite reports, until the loop takes it
    TestResult result;   // where the suite reports, on its thread
    std::thread thread;
    std::atomic<bool> done{false};
    ResourceTable::Held held;
    std::vector<SuiteEvents::Event> pending;  // taken, not yet handed on (a later suite)
    std::string waitSaid;                     // what it was last said to wait for
    Current current;
    // network="private": its network while it runs (its workers hold it too while they live).
    std::shared_ptr<const platform::PrivateNetwork> network;
};

Scheduler::Scheduler(RunPlan& plan, ResourcePools pools, SchedulerSettings settings)
    : plan_(plan), pools_(std::move(pools)), table_(pools_), settings_(settings) {
    if (settings_.jobs == 0) {
        settings_.jobs = 1;
    }
    platform::makePipe(wakeRead_, wakeWrite_);
    platform::setNonBlocking(wakeRead_.get());
    platform::setNonBlocking(wakeWrite_.get());

    const std::size_t count = plan_.suiteCount();
    after_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const SuiteSpec& spec = plan_.spec(i);
        std::vector<ResourceTemplate> templates;
        std::vector<std::string> fixtureParams;
        for (std::size_t t = 0; t < spec.tests.size(); ++t) {
            const TestSpec& test = spec.tests[t];
            if (!variables::resourcesUsed(test.param).empty() ||
                !variables::resourcesUsed(test.environment).empty()) {
                templates.push_back({t, test.param, test.environment});
            }
        }
        for (const auto& fixture : spec.fixtures) {
            fixtureParams.push_back(fixture.param);
        }
        testTemplates_.push_back(std::move(templates));
        fixtureParams_.push_back(std::move(fixtureParams));
        // A test that depends on a test of another suite sees it as run one suite at a time
        // would: the later of the two suites starts once the earlier one ended.
        for (std::size_t j = 0; j < count; ++j) {
            if (j == i) {
                continue;
            }
            bool linked = false;
            for (const auto& test : spec.tests) {
                for (const auto& dependency : test.depends) {
                    for (const auto& other : plan_.spec(j).tests) {
                        linked = linked || dependencyNames(dependency, other);
                    }
                }
            }
            if (linked) {
                after_[std::max(i, j)].push_back(std::min(i, j));
            }
        }
    }
}

Scheduler::~Scheduler() {
    // Only when run() was left by an exception: a suite still running is stopped first.
    bool left = false;
    for (const auto& job : jobs_) {
        left = left || job->thread.joinable();
    }
    if (left) {
        interrupt();
    }
    for (auto& job : jobs_) {
        if (job->thread.joinable()) {
            job->thread.join();
        }
    }
}

void Scheduler::wake() {
    char byte = 1;
    ssize_t ignored = ::write(wakeWrite_.get(), &byte, 1);
    (void)ignored;
}

void Scheduler::interrupt() {
    interrupted_ = true;
    // Every suite: one that has not started is never started now, and a suite's own flag is
    // safe to set from any thread.
    for (std::size_t i = 0; i < plan_.suiteCount(); ++i) {
        plan_.suite(i).interrupt();
    }
    plan_.interruptFixtures();
    wake();
}

void Scheduler::notRun(Job& job, const TestMessage& reason, bool interrupted) {
    plan_.suite(job.index).reportNotRun(job.result, reason, interrupted);
    job.state = Job::State::Finished;
    releaseWorlds(job);
}

void Scheduler::releaseWorlds(Job& job) {
    for (SharedWorldFixture* place : plan_.sharedWorlds(job.index)) {
        const std::string problem = place->releaseIfHeld();
        if (!problem.empty() && settings_.view != nullptr) {
            settings_.view->note("error: " + problem);
        }
    }
}

void Scheduler::noteWorlds() {
    for (std::size_t w = 0; w < plan_.worldCount(); ++w) {
        for (const SharedWorld::Note& note : plan_.world(w).notes()) {
            if (settings_.view != nullptr) {
                settings_.view->note(note.line);
            }
            // Its lane in the reports' timelines (TestResultCollector::worlds()).
            if (result_ != nullptr) {
                RunEvent event;
                event.data = events::world(plan_.world(w).name(), note.phase, note.detail);
                event.happened = note.at;
                result_->publish(event);
            }
        }
    }
}

void Scheduler::stopWorlds() {
    std::vector<SharedWorld*> up;
    for (std::size_t w = 0; w < plan_.worldCount(); ++w) {
        up.push_back(&plan_.world(w));
    }
    std::stable_sort(up.begin(), up.end(), [](const SharedWorld* a, const SharedWorld* b) {
        return a->startedAt() > b->startedAt();
    });
    for (SharedWorld* world : up) {
        const std::string problem = world->stop();
        if (!problem.empty() && settings_.view != nullptr) {
            settings_.view->note("error: " + problem);
        }
    }
    noteWorlds();
}

bool Scheduler::mayStart(Job& job) {
    for (std::size_t before : after_[job.index]) {
        if (jobs_[before]->state != Job::State::Finished) {
            return false;
        }
    }
    const SuiteSpec& spec = plan_.spec(job.index);
    std::string busyLock, busyPool;
    if (table_.take(spec, spec.name, job.held, busyLock, busyPool)) {
        return true;
    }
    std::string line = "suite " + quote(spec.name) + " waits for ";
    if (!busyLock.empty()) {
        line += "lock " + busyLock;
        if (settings_.verbose) {
            line += " (held by suite " + quote(table_.holderOf(busyLock)) + ")";
        }
    } else {
        line += "an item of pool " + busyPool;
    }
    if (line != job.waitSaid && settings_.view != nullptr) {
        settings_.view->note(line);
    }
    job.waitSaid = line;
    return false;
}

void Scheduler::start(Job& job) {
    const std::size_t i = job.index;
    SuiteSpec& spec = plan_.spec(i);
    // The items it took reach it as ${resource.POOL} and RTF_RESOURCE_POOL.
    auto value = [&job](const std::string& pool) {
        std::string text;
        auto found = job.held.items.find(pool);
        if (found != job.held.items.end()) {
            for (const auto& id : found->second) {
                text += (text.empty() ? "" : ",") + id;
            }
        }
        return text;
    };
    for (const ResourceTemplate& given : testTemplates_[i]) {
        spec.tests[given.test].param = variables::fillResources(given.param, value);
        spec.tests[given.test].environment = variables::fillResources(given.environment, value);
    }
    std::vector<std::string> environment;
    for (const auto& pool : job.held.items) {
        environment.push_back(resourceVariable(pool.first) + "=" + value(pool.first));
    }
    const std::vector<SharedWorldFixture*> shared = plan_.sharedWorlds(i);
    const std::size_t group = groups_[i];
    if (shared.empty() ? spec.network == SuiteSpec::Network::Private : groupPrivate_[group]) {
        // Checked before the run (cli/private_networks.h); one that fails now (the kernel's
        // limit of namespaces) stops the suite rather than run it in the machine's network.
        // Suites that share worlds share one network, the worlds' (made for the first).
        std::string error;
        if (settings_.network) {
            // A network given from outside (a kept world's, --world DIR).
            job.network = settings_.network;
        } else if (shared.empty()) {
            job.network = platform::PrivateNetwork::create(error);
        } else {
            if (!groupNetworks_[group]) {
                groupNetworks_[group] = platform::PrivateNetwork::create(error);
            }
            job.network = groupNetworks_[group];
            for (SharedWorldFixture* place : shared) {
                place->world().setNetwork(job.network);
            }
        }
        if (!job.network) {
            table_.release(job.held);
            job.held = ResourceTable::Held();
            notRun(job, TestMessage("not run: " + error), true);
            return;
        }
    }
    const std::vector<FixtureManager*> fixtures = plan_.fixtures(i);
    for (std::size_t f = 0; f < fixtures.size() && f < fixtureParams_[i].size(); ++f) {
        spec.fixtures[f].param = variables::fillResources(fixtureParams_[i][f], value);
        fixtures[f]->setParam(spec.fixtures[f].param);
        if (auto* holder = dynamic_cast<WorkerEnvironment*>(fixtures[f])) {
            holder->setWorkerEnvironment(environment);
        }
        if (auto* holder = dynamic_cast<WorkerNetwork*>(fixtures[f])) {
            holder->setWorkerNetwork(job.network);
        }
    }
    plan_.lane(i).open(environment, job.network);
    TestSuite& suite = plan_.suite(i);
    suite.setGate(&plan_.gate());
    job.state = Job::State::Running;
    ++running_;
    aloneRunning_ = aloneRunning_ || spec.exclusive;
    if (settings_.inlineSuites) {
        // --isolation none: this thread, and what it starts, in the suite's network while it
        // runs (cli/private_networks.h checked that the thread can join it).
        platform::ThreadInNetwork inNetwork;
        std::string error;
        if (job.network && !inNetwork.enter(*job.network, error)) {
            suite.reportNotRun(job.result, TestMessage("not run: its private network: " + error),
                               true);
            finish(job);
            return;
        }
        // One suite at a time in this process: its items are this process's environment
        // while it runs.
        for (const auto& variable : environment) {
            const std::size_t equals = variable.find('=');
            platform::setEnvironment(variable.substr(0, equals), variable.substr(equals + 1));
        }
        // Its events go straight to the run's listeners, the gate after them as on the suite's
        // own result: one fan-out and one lock less for each event.
        result_->addListener(&plan_.gate());
        try {
            suite.run(*result_);
        } catch (...) {
            result_->removeListener(&plan_.gate());
            throw;
        }
        result_->removeListener(&plan_.gate());
        for (const auto& variable : environment) {
            platform::unsetEnvironment(variable.substr(0, variable.find('=')));
        }
        finish(job);
        return;
    }
    job.thread = std::thread([this, &job, &suite] {
        suite.run(job.result);
        job.done = true;
        wake();
    });
}

void Scheduler::finish(Job& job) {
    if (job.thread.joinable()) {
        job.thread.join();
    }
    plan_.lane(job.index).close();
    releaseWorlds(job);
    job.network.reset();
    table_.release(job.held);
    job.held = ResourceTable::Held();
    job.state = Job::State::Finished;
    --running_;
    if (plan_.spec(job.index).exclusive) {
        aloneRunning_ = false;
    }
}

void Scheduler::startReady() {
    for (auto& owned : jobs_) {
        Job& job = *owned;
        if (job.state != Job::State::Waiting) {
            continue;
        }
        if (interrupted_) {
            notRun(job, TestMessage(notrun::interrupted), true);
            continue;
        }
        // As the library's TestRunner asks before each suite (--fail-fast).
        TestMessage reason;
        if (plan_.gate().skip(&plan_.suite(job.index), reason)) {
            notRun(job, reason, false);
            continue;
        }
        const bool exclusive = plan_.spec(job.index).exclusive;
        if (aloneRunning_) {
            continue;  // nothing starts beside an exclusive suite
        }
        if (running_ >= settings_.jobs || (exclusive && running_ > 0)) {
            // An exclusive suite holds back the ones after it, or it might never run alone.
            if (exclusive) {
                break;
            }
            continue;
        }
        if (!mayStart(job)) {
            continue;
        }
        start(job);
        if (exclusive) {
            break;
        }
    }
}

void Scheduler::collect(bool& changed) {
    for (auto& owned : jobs_) {
        Job& job = *owned;
        if (job.state == Job::State::Running && job.done) {
            finish(job);
            changed = true;
        }
        std::vector<SuiteEvents::Event> taken = job.events.take();
        if (taken.empty()) {
            continue;
        }
        changed = true;
        for (const auto& event : taken) {
            job.current.onEvent(event);
        }
        if (settings_.view != nullptr) {
            settings_.view->events(plan_.suite(job.index), taken);
        }
        job.pending.insert(job.pending.end(), std::make_move_iterator(taken.begin()),
                           std::make_move_iterator(taken.end()));
    }
}

std::string Scheduler::runningLine() const {
    std::string line;
    for (const auto& job : jobs_) {
        if (job->state != Job::State::Running) {
            continue;
        }
        line += (line.empty() ? "" : " | ") + plan_.spec(job->index).name;
        line += job->current.name.empty() ? " (fixtures)" : ": " + job->current.name;
    }
    return line;
}

void Scheduler::run(TestResult& result) {
    jobs_.clear();
    running_ = 0;
    aloneRunning_ = false;
    for (std::size_t i = 0; i < plan_.suiteCount(); ++i) {
        jobs_.push_back(std::make_unique<Job>(i, [this] { wake(); }));
        jobs_.back()->result.addListener(&plan_.gate());  // --fail-fast learns at once
    }
    result_ = &result;
    if (settings_.inlineSuites) {
        settings_.jobs = 1;
    }
    groups_ = plan_.worldGroups();
    groupPrivate_.assign(plan_.suiteCount(), false);
    groupNetworks_.assign(plan_.suiteCount(), nullptr);
    for (std::size_t i = 0; i < plan_.suiteCount(); ++i) {
        if (plan_.spec(i).network == SuiteSpec::Network::Private) {
            groupPrivate_[groups_[i]] = true;
        }
        for (SharedWorldFixture* place : plan_.sharedWorlds(i)) {
            place->reset();
        }
    }
    // A world changes on a suite's thread: the loop is woken to say it. With the suites on
    // this thread (--isolation none) it is said at once, among the suite's own lines.
    const std::thread::id loop = std::this_thread::get_id();
    for (std::size_t w = 0; w < plan_.worldCount(); ++w) {
        plan_.world(w).reset();
        plan_.world(w).onChange([this, loop] {
            if (settings_.inlineSuites && std::this_thread::get_id() == loop) {
                noteWorlds();
            } else {
                wake();
            }
        });
    }
    result.startTestRunner();
    std::size_t head = 0;  // the first suite not yet handed on whole
    std::string shown;
    for (;;) {
        {
            std::string drained;
            while (platform::readSome(wakeRead_.get(), drained) > 0) {
                drained.clear();
            }
        }
        bool changed = false;
        collect(changed);
        noteWorlds();
        for (; head < jobs_.size(); ++head) {
            Job& job = *jobs_[head];
            for (const auto& event : job.pending) {
                result.publish(event);
            }
            job.pending.clear();
            if (job.state != Job::State::Finished) {
                break;
            }
        }
        startReady();
        collect(changed);  // a suite reported not run is handed on at once
        for (; head < jobs_.size() && jobs_[head]->state == Job::State::Finished; ++head) {
            for (const auto& event : jobs_[head]->pending) {
                result.publish(event);
            }
            jobs_[head]->pending.clear();
        }
        if (settings_.view != nullptr) {
            const std::string line = runningLine();
            if (line != shown) {
                settings_.view->running(line);
                shown = line;
            }
        }
        if (head == jobs_.size()) {
            break;
        }
        if (!changed) {
            // While suites run, a look every kLookMs takes the events of their running tests.
            std::vector<bool> ready;
            platform::waitReadable({wakeRead_.get()}, running_ > 0 ? SuiteEvents::kLookMs : 1000,
                                   ready);
        }
    }
    stopWorlds();
    for (std::size_t w = 0; w < plan_.worldCount(); ++w) {
        plan_.world(w).onChange(nullptr);
    }
    groupNetworks_.clear();
    result.endTestRunner();
    result_ = nullptr;
}

}  // namespace runner
}  // namespace robottestingframework
