#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>

#include "platform/fd_passing.h"
#include "platform/file_descriptor.h"
#include "platform/local_socket.h"
#include "platform/private_network.h"
#include "runner/cli/executor_choice.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/interrupt_watcher.h"
#include "runner/cli/kept_world.h"
#include "runner/cli/private_networks.h"
#include "runner/cli/program_name.h"
#include "runner/cli/world_keeper.h"
#include "runner/cli/world_protocol.h"
#include "runner/plan/run_plan.h"
#include "runner/schedule/scheduler.h"

namespace robottestingframework {
namespace runner {

namespace {

constexpr int kLookMs = 200;  // how often the keeper looks whether ctest is still there

// What the keeper knows of its world, shared by the suite's thread (the Hold test), the control
// thread and the keeper's main thread.
class KeeperState {
public:
    KeeperState(platform::FileDescriptor toStarter, std::string suite)
        : toStarter_(std::move(toStarter)), suite_(std::move(suite)) {}

    // The world is up (the suite's set-up passed): the --world-up runner may return.
    void up(std::shared_ptr<const platform::PrivateNetwork> network) {
        std::lock_guard<std::mutex> lock(mutex_);
        network_ = std::move(network);
        if (state_ == WorldStatus::State::Starting) {
            state_ = WorldStatus::State::Up;
        }
        tellStarter(WorldOutcome{true, ""});
    }
    // The set-up failed, or the keeper could not start it: what the runner prints.
    void failedToStart(const std::string& text) {
        std::lock_guard<std::mutex> lock(mutex_);
        tellStarter(WorldOutcome{false, text});
    }
    void collapsed(const std::string& reason) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (state_ == WorldStatus::State::Up) {
            state_ = WorldStatus::State::Collapsed;
            reason_ = reason;
        }
    }
    // What cuts a set-up in progress short (RunPlan::interruptFixtures).
    void setInterruptSetup(std::function<void()> interrupt) {
        std::lock_guard<std::mutex> lock(mutex_);
        interruptSetup_ = std::move(interrupt);
    }
    // Asks the world down (--world-down, ctest gone, a signal); `why` for the keeper's log. A
    // set-up in progress is cut short.
    void stop(const std::string& why) {
        std::function<void()> interrupt;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!stopping_ && state_ == WorldStatus::State::Starting) {
                interrupt = interruptSetup_;
            }
            if (!stopping_) {
                std::fprintf(stderr, "%s: tearing the world down: %s\n", programName, why.c_str());
                std::fflush(stderr);
            }
            stopping_ = true;
            if (state_ != WorldStatus::State::Collapsed) {
                state_ = WorldStatus::State::Stopping;
                reason_ = why;
            }
        }
        changed_.notify_all();
        if (interrupt) {
            interrupt();
        }
    }
    // Whoever asked --world-down: told the outcome once the world is down.
    void addDownClient(platform::FileDescriptor client) {
        std::lock_guard<std::mutex> lock(mutex_);
        downClients_.push_back(std::move(client));
    }
    std::vector<platform::FileDescriptor> takeDownClients() {
        std::lock_guard<std::mutex> lock(mutex_);
        return std::move(downClients_);
    }
    // The Hold test waits here until the world is asked down or `woken` says to look.
    void waitForStop(std::atomic<bool>& woken) {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait_for(lock, std::chrono::milliseconds(kLookMs),
                          [&] { return stopping_ || woken.load(); });
    }
    bool stopping() {
        std::lock_guard<std::mutex> lock(mutex_);
        return stopping_;
    }
    void wake() { changed_.notify_all(); }
    // The answer to "status", and the network's descriptors beside it.
    std::string status(std::vector<int>& fds) {
        std::lock_guard<std::mutex> lock(mutex_);
        WorldStatus status;
        status.state = state_;
        status.reason = reason_;
        status.suite = suite_;
        if (network_ && state_ == WorldStatus::State::Up) {
            fds = network_->descriptors();
        }
        status.networkDescriptors = static_cast<unsigned int>(fds.size());
        return worldStatusText(status);
    }
    bool wasUp() {
        std::lock_guard<std::mutex> lock(mutex_);
        return toldStarter_ && startPassed_;
    }

private:
    void tellStarter(const WorldOutcome& outcome) {
        if (toldStarter_) {
            return;
        }
        toldStarter_ = true;
        startPassed_ = outcome.passed;
        const std::string text = worldOutcomeText(outcome);
        platform::writeAll(toStarter_.get(), std::to_string(text.size()) + "\n" + text);
        toStarter_.reset();
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    platform::FileDescriptor toStarter_;
    const std::string suite_;
    bool toldStarter_ = false;
    bool startPassed_ = false;
    bool stopping_ = false;
    WorldStatus::State state_ = WorldStatus::State::Starting;
    std::string reason_;
    std::shared_ptr<const platform::PrivateNetwork> network_;
    std::vector<platform::FileDescriptor> downClients_;
    std::function<void()> interruptSetup_;
};

// The suite's one "test" in the keeper: runs once the fixtures are up, and holds the world
// until it is asked down. A collapse interrupts it (TestSuite::fixtureCollapsed): it notes the
// reason and keeps holding, so that the tests that ask are told why.
class Hold : public Test {
public:
    Hold(KeeperState& state, TestSuite& suite,
         std::shared_ptr<const platform::PrivateNetwork> network)
        : Test("world"), state_(state), suite_(suite), network_(std::move(network)) {}

    void run(TestResult& result) override {
        state_.up(network_);  // also when already asked down: the starter hears of it
        // In the suite's events, after its set-up's: what --world-down prints starts here
        // (WorldErrors, which hears of it once the world is up).
        result.startTest(this);
        bool collapsed = false;
        while (!state_.stopping()) {
            state_.waitForStop(woken_);
            if (woken_.exchange(false)) {
                const TestMessage failure = suite_.fixtureFailure();
                if (collapsed || failure.getMessage().empty()) {
                    // A signal (TestSuite::interrupt), or more of a world already collapsed.
                    state_.stop("interrupted");
                } else {
                    collapsed = true;
                    const std::string reason = failure.toString();
                    std::fprintf(stderr, "%s: the world collapsed: %s\n", programName,
                                 reason.c_str());
                    std::fflush(stderr);
                    state_.collapsed(reason);
                }
            }
        }
        result.endTest(this);
    }
    // Called under the suite's lock: only flags.
    void interrupt() override {
        woken_ = true;
        state_.wake();
    }
    bool succeeded() const override { return true; }

private:
    KeeperState& state_;
    TestSuite& suite_;
    std::shared_ptr<const platform::PrivateNetwork> network_;
    std::atomic<bool> woken_{false};
};

// What a run would print about the world: its errors and its fixtures' reports, from the
// suite's set-up on, or once it is up (the Hold test started) for its tear-down.
class WorldErrors : public TestListener {
public:
    explicit WorldErrors(KeeperState& state) : state_(state) {}

    void addError(const Test*, TestMessage message) override { add("error", message); }
    void addFailure(const Test*, TestMessage message) override { add("failure", message); }
    void addReport(const Test*, TestMessage message) override {
        std::lock_guard<std::mutex> lock(mutex_);
        all_ += "  " + message.toString() + "\n";
        std::fprintf(stderr, "%s\n", message.toString().c_str());
    }
    // The world is up (Hold started): what the set-up said is not the tear-down's. (A set-up
    // that failed reports Hold skipped, with a startTest too.)
    void startTest(const Test*) override {
        if (!state_.wasUp()) {
            return;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        all_.clear();
        failed_ = false;
    }
    void addOutput(const Test*, const std::string& text) override {
        std::fprintf(stderr, "%s", text.c_str());
    }
    // Everything said since the last take(); `failed`: an error or failure among it.
    std::string take(bool& failed) {
        std::lock_guard<std::mutex> lock(mutex_);
        failed = failed_;
        failed_ = false;
        return std::move(all_);
    }

private:
    void add(const char* kind, const TestMessage& message) {
        std::lock_guard<std::mutex> lock(mutex_);
        failed_ = true;
        std::string text = message.toString();
        if (!message.getDetail().empty() && text.find(message.getDetail()) == std::string::npos) {
            text += "\n" + message.getDetail();
        }
        all_ += std::string(kind) + ": " + text + "\n";
        std::fprintf(stderr, "%s: %s\n", kind, text.c_str());
        std::fflush(stderr);
    }

    KeeperState& state_;
    std::mutex mutex_;
    std::string all_;
    bool failed_ = false;
};

bool ownerAlive(pid_t owner) {
    return owner <= 1 || ::kill(owner, 0) == 0 || errno == EPERM;
}

// The control socket: answers "status" and "down"; asks the world down when `owner` is gone.
void serve(int listener, KeeperState& state, pid_t owner, std::atomic<bool>& done) {
    while (!done) {
        std::vector<bool> ready;
        if (!ownerAlive(owner)) {
            state.stop("the process that started it (pid " + std::to_string(owner) +
                       ", ctest) is gone");
        }
        if (!platform::waitReadable({listener}, kLookMs, ready)) {
            continue;
        }
        platform::FileDescriptor client = platform::acceptLocal(listener);
        if (!client.valid()) {
            continue;
        }
        std::string packet;
        std::vector<platform::FileDescriptor> ignored;
        // A client sends its request at once; one that does not is not waited for long.
        std::vector<bool> readable;
        if (!platform::waitReadable({client.get()}, 1000, readable) ||
            !platform::receiveWithFds(client.get(), packet, ignored)) {
            continue;
        }
        const WorldRequest request = parseWorldRequest(packet);
        if (request == WorldRequest::Down) {
            state.addDownClient(std::move(client));
            state.stop("--world-down");
        } else if (request == WorldRequest::Status) {
            std::vector<int> fds;
            const std::string answer = state.status(fds);
            platform::sendWithFds(client.get(), answer, fds);
        }
    }
}

// The keeper's life, in the detached child: sets the world up, holds it, tears it down.
int keep(Options& options, SuiteSpec suite, const Overrides& overrides, ResourcePools pools,
         const std::string& folder, pid_t owner, platform::FileDescriptor toStarter) {
    KeeperState state(std::move(toStarter), suite.name);
    std::string error;
    platform::FileDescriptor listener = platform::listenLocal(folder, "keeper.sock", error);
    if (!listener.valid()) {
        state.failedToStart("cannot listen for the tests: " + error);
        return configurationError;
    }
    const std::string socketPath = worldSocketPath(folder);
    std::shared_ptr<const platform::PrivateNetwork> network;
    // --shared-worlds DIR: the suite's shared worlds are another keeper's, and so is the
    // network they live in.
    KeptWorld shared;
    if (!options.sharedWorlds.empty()) {
        if (!joinKeptWorld(options.sharedWorlds, suite.name, shared, error)) {
            state.failedToStart("--shared-worlds " + options.sharedWorlds + ": " + error);
            ::unlink(socketPath.c_str());
            return configurationError;
        }
        network = shared.network;
    }
    if (suite.network == SuiteSpec::Network::Private && !network) {
        network = platform::PrivateNetwork::create(error);
        if (!network) {
            state.failedToStart("suite " + suite.name + ": " + error);
            ::unlink(socketPath.c_str());
            return configurationError;
        }
    }
    const std::unique_ptr<TestExecutor> executor = chooseExecutor(options, 1, error);
    if (!executor) {
        state.failedToStart("cannot start process isolation: " + error);
        ::unlink(socketPath.c_str());
        return configurationError;
    }
    RunPlan plan(*executor);
    applyOverrides(suite, overrides);
    suite.tests.clear();
    plan.addSuite(std::move(suite), shared.fixture.get());
    state.setInterruptSetup([&plan] { plan.interruptFixtures(); });
    Hold hold(state, plan.suite(0), network);
    plan.suite(0).addTest(&hold);

    SchedulerSettings settings;
    settings.inlineSuites = options.isolation == Isolation::None;
    settings.network = network;
    Scheduler scheduler(plan, std::move(pools), settings);
    WorldErrors errors(state);
    TestResult result;
    result.addListener(&errors);

    std::atomic<bool> done{false};
    std::thread control([&] { serve(listener.get(), state, owner, done); });
    {
        InterruptWatcher watcher([&scheduler] { scheduler.interrupt(); }, stderr, [] {});
        scheduler.run(result);
        watcher.stop();
    }
    bool failed = false;
    const std::string said = errors.take(failed);
    if (!state.wasUp()) {
        state.failedToStart(said.empty() ? "the world's set-up failed" : said);
    }
    // Gone from the folder before anyone is told the world is down.
    ::unlink(socketPath.c_str());
    done = true;
    control.join();
    listener.reset();
    const std::string outcome = worldOutcomeText(WorldOutcome{!failed, said});
    for (const auto& client : state.takeDownClients()) {
        platform::sendWithFds(client.get(), outcome, {});
    }
    std::fprintf(stderr, "%s: the world is down%s\n", programName,
                 failed ? " (its tear-down failed)" : "");
    return failed ? somethingFailed : allPassed;
}

// Reads the keeper's "<size>\n<outcome>" from the pipe; false when it ended without one.
bool readStarterMessage(int fd, WorldOutcome& outcome) {
    std::string text;
    for (;;) {
        const std::size_t newline = text.find('\n');
        if (newline != std::string::npos) {
            const unsigned long size = std::strtoul(text.c_str(), nullptr, 10);
            if (text.size() - newline - 1 >= size) {
                return parseWorldOutcome(text.substr(newline + 1, size), outcome);
            }
        }
        if (platform::readSome(fd, text) <= 0) {
            return false;
        }
    }
}

// What --world-down reads to tell a world that never started from a keeper that ended.
void noteWorldFailed(const std::string& folder, const std::string& reason) {
    if (std::FILE* file = std::fopen(worldFailedPath(folder).c_str(), "w")) {
        std::fprintf(file, "%s\n", reason.c_str());
        std::fclose(file);
    }
}

void printLines(std::FILE* stream, const std::string& text) {
    if (!text.empty()) {
        std::fprintf(stream, "%s%s", text.c_str(), text.back() == '\n' ? "" : "\n");
    }
}

}  // namespace

int worldUpCommand(Options& options, PlannedRun& planned, RunInputs& inputs) {
    const std::string& folder = options.worldUp;
    if (planned.suites.size() != 1) {
        std::fprintf(stderr, "%s: --world-up %s: expected one suite (--suite FILE), got %zu\n",
                     programName, folder.c_str(), planned.suites.size());
        return configurationError;
    }
    std::error_code failure;
    std::filesystem::create_directories(folder, failure);
    if (failure) {
        std::fprintf(stderr, "%s: --world-up %s: cannot make the folder: %s\n", programName,
                     folder.c_str(), failure.message().c_str());
        return configurationError;
    }
    std::filesystem::remove(worldFailedPath(folder), failure);
    {
        std::string ignored;
        if (platform::connectLocal(folder, "keeper.sock", ignored).valid()) {
            std::fprintf(stderr,
                         "%s: --world-up %s: a world keeper already runs there; stop it with "
                         "--world-down %s\n",
                         programName, folder.c_str(), folder.c_str());
            return configurationError;
        }
    }
    std::string error, cost;
    if (!preparePrivateNetworks(options, planned.suites, error, cost)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return configurationError;
    }
    const std::string suiteName = planned.suites.front().name;
    const pid_t owner = ::getppid();  // ctest: the keeper lives no longer than it
    platform::FileDescriptor readEnd, writeEnd;
    if (!platform::makePipe(readEnd, writeEnd)) {
        std::fprintf(stderr, "%s: --world-up: pipe: %s\n", programName, std::strerror(errno));
        return configurationError;
    }
    const std::string log = worldLogPath(folder);
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t keeper = ::fork();
    if (keeper < 0) {
        std::fprintf(stderr, "%s: --world-up: fork: %s\n", programName, std::strerror(errno));
        return configurationError;
    }
    if (keeper == 0) {
        // A session of its own: ctest's signals to the test's process group, and the end of
        // its pipes, are not the keeper's. Its output goes to the log in the folder.
        ::setsid();
        // A starter gone (ctest's timeout killed it) must not kill the keeper when told.
        ::signal(SIGPIPE, SIG_IGN);
        readEnd.reset();
        const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
        const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (null < 0 || out < 0 || ::dup2(null, 0) < 0 || ::dup2(out, 1) < 0 ||
            ::dup2(out, 2) < 0) {
            ::_exit(configurationError);
        }
        ::close(null);
        ::close(out);
        std::fprintf(stderr, "%s: world keeper of suite %s (pid %d), for pid %d\n", programName,
                     suiteName.c_str(), static_cast<int>(::getpid()), static_cast<int>(owner));
        std::fflush(stderr);
        int status = configurationError;
        try {
            status = keep(options, std::move(planned.suites.front()), inputs.overrides,
                          std::move(inputs.pools), folder, owner, std::move(writeEnd));
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: the world keeper failed: %s\n", programName, e.what());
        }
        std::fflush(stdout);
        std::fflush(stderr);
        ::_exit(status);
    }
    writeEnd.reset();
    WorldOutcome outcome;
    if (!readStarterMessage(readEnd.get(), outcome)) {
        std::fprintf(stderr,
                     "%s: --world-up %s: the world keeper ended before its world was up; see "
                     "%s\n",
                     programName, folder.c_str(), log.c_str());
        noteWorldFailed(folder, "the world keeper ended before its world was up; see " + log);
        return somethingFailed;
    }
    if (!outcome.passed) {
        noteWorldFailed(folder, outcome.text);
        printLines(stderr, outcome.text);
        std::fprintf(stdout, "%s: the world of suite %s failed to start (log: %s)\n", programName,
                     suiteName.c_str(), log.c_str());
        return somethingFailed;
    }
    std::fprintf(stdout, "%s: the world of suite %s is up (keeper pid %d, %s)\n", programName,
                 suiteName.c_str(), static_cast<int>(keeper), folder.c_str());
    return allPassed;
}

int worldDownCommand(const Options& options) {
    const std::string& folder = options.worldDown;
    std::string error;
    platform::FileDescriptor socket = platform::connectLocal(folder, "keeper.sock", error);
    if (!socket.valid() && ::access(worldFailedPath(folder).c_str(), F_OK) == 0) {
        std::fprintf(stdout,
                     "%s: --world-down %s: the world never started (its --world-up failed and "
                     "counts that failure; see %s): nothing to stop\n",
                     programName, folder.c_str(), worldLogPath(folder).c_str());
        return worldNeverStarted;
    }
    if (!socket.valid()) {
        const std::string log = worldLogPath(folder);
        const std::string hint = ::access(log.c_str(), F_OK) == 0
                                     ? "; its world failed to start or its keeper ended: see " + log
                                     : "";
        std::fprintf(stderr, "%s: --world-down %s: no world keeper answers there (%s)%s\n",
                     programName, folder.c_str(), error.c_str(), hint.c_str());
        return configurationError;
    }
    std::string packet;
    std::vector<platform::FileDescriptor> ignored;
    WorldOutcome outcome;
    if (!platform::sendWithFds(socket.get(), worldRequestText(WorldRequest::Down), {}) ||
        !platform::receiveWithFds(socket.get(), packet, ignored) ||
        !parseWorldOutcome(packet, outcome)) {
        std::fprintf(stderr,
                     "%s: --world-down %s: the world keeper ended without saying how its "
                     "tear-down went; see %s\n",
                     programName, folder.c_str(), worldLogPath(folder).c_str());
        return somethingFailed;
    }
    printLines(outcome.passed ? stdout : stderr, outcome.text);
    std::fprintf(stdout, "%s: the world kept at %s is down%s\n", programName, folder.c_str(),
                 outcome.passed ? "" : "; its tear-down failed");
    return outcome.passed ? allPassed : somethingFailed;
}

}  // namespace runner
}  // namespace robottestingframework
