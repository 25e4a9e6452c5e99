#include "runner/execution/isolated_executor.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <sstream>

#include "core/events.h"
#include "core/not_run_reasons.h"
#include "isolation/event_relay.h"
#include "languages/plugin_locator.h"
#include "languages/test_loader.h"
#include "platform/clock.h"
#include "platform/private_network.h"
#include "platform/process.h"
#include "platform/signal_name.h"

#include "isolation/worker_process.h"

namespace robottestingframework {
namespace isolation {

namespace {

std::string seconds(double value) {
    std::ostringstream text;
    text << value << " s";
    return text.str();
}

std::string said(const EventRelay& relay) {
    return relay.lastSaid().empty() ? "it reported nothing before"
                                    : "last reported: " + relay.lastSaid();
}

void drain(int fd) {
    std::string bytes;
    while (platform::readSome(fd, bytes, 64) > 0) {
        bytes.clear();
    }
}

}  // namespace

IsolatedExecutor::IsolatedExecutor(IsolationOptions options) : options_(std::move(options)) {
    for (std::size_t i = 0; i < std::max<std::size_t>(options_.servers, 1); ++i) {
        slots_.push_back(std::make_shared<ServerSlot>());
    }
    server_ = slots_.front()->server;
    openWakePipe();
}

IsolatedExecutor::IsolatedExecutor(IsolationOptions options, std::shared_ptr<ServerSlot> slot)
    : options_(std::move(options)), server_(slot->server), laneSlot_(std::move(slot)) {
    ++laneSlot_->lanes;
    openWakePipe();
}

void IsolatedExecutor::openWakePipe() {
    platform::makePipe(wakeRead_, wakeWrite_);
    platform::setNonBlocking(wakeRead_.get());
    platform::setNonBlocking(wakeWrite_.get());
}

IsolatedExecutor::~IsolatedExecutor() {
    shutdown();
    if (laneSlot_) {
        --laneSlot_->lanes;
    }
}

bool IsolatedExecutor::start(std::string& error) {
    if (server_->running()) {
        return true;
    }
    std::string worker = options_.workerPath.empty() ? findWorker() : options_.workerPath;
    if (worker.empty()) {
        error = "cannot find robottestingframework-worker (next to the runner, or set RTF_WORKER)";
        return false;
    }
    // A lane whose server is not running starts it (an executor starts all of its own).
    if (slots_.empty()) {
        return server_->start(worker, error, options_.verbose);
    }
    for (const auto& slot : slots_) {
        if (!slot->server->running() && !slot->server->start(worker, error, options_.verbose)) {
            return false;
        }
    }
    return true;
}

void IsolatedExecutor::shutdown() {
    for (const auto& slot : slots_) {
        slot->server->stop();
    }
}

std::unique_ptr<runner::TestExecutor> IsolatedExecutor::makeLane() {
    IsolationOptions laneOptions = options_;
    laneOptions.servers = 1;
    if (slots_.empty()) {  // a lane's lane: the same server
        return std::unique_ptr<runner::TestExecutor>(new IsolatedExecutor(laneOptions, laneSlot_));
    }
    const auto& slot =
        *std::min_element(slots_.begin(), slots_.end(),
                          [](const std::shared_ptr<ServerSlot>& a,
                             const std::shared_ptr<ServerSlot>& b) { return a->lanes < b->lanes; });
    return std::unique_ptr<runner::TestExecutor>(new IsolatedExecutor(laneOptions, slot));
}

void IsolatedExecutor::interrupt() {
    interrupted_ = true;
    char byte = 1;
    // Async-signal-safe: may be called from a signal handler as well as another thread.
    ssize_t ignored = ::write(wakeWrite_.get(), &byte, 1);
    (void)ignored;
}

TestStatus IsolatedExecutor::run(const runner::TestSpec& spec, Test& self, TestResult& result) {
    self.clearCriticalError();
    EventRelay relay(self, result);
    // interrupt() sets the flag before it writes the byte: without the flag, nothing to drain.
    if (interrupted_) {
        drain(wakeRead_.get());
        interrupted_ = false;
    }

    WorkRequest request;
    request.name = spec.name;
    request.param = spec.param;
    request.environment = spec.environment;
    request.repetition = spec.repetition == 0 ? 1 : spec.repetition;
    request.variables = environment_;

    std::string error;
    if (!languages::locatePlugin(spec.plugin, spec.path, spec.type, spec.where.file, request.path,
                                 request.type, error)) {
        relay.add(events::failure(TestMessage("cannot load " + spec.plugin, error)));
        relay.end("");
        return relay.status();
    }
    WorkerProcess worker;
    if (start(error)) {
        // The pid comes with the events.
        worker.start(*server_, request, error, false,
                     network_ ? network_->descriptors() : std::vector<int>());
    }
    if (!error.empty()) {
        relay.add(events::error(TestMessage("cannot run " + spec.plugin + " in a worker", error)));
        relay.end("");
        return relay.status();
    }

    // The test starts with its worker (as in-process): one that hangs while loading and times
    // out reports the time it took, not the moment its timeout was reported.
    relay.start();
    enum class Stop { None, Timeout, Interrupt, Garbage } why = Stop::None;
    platform::Deadline deadline(spec.timeout);
    std::vector<WireRecord> records;
    for (;;) {
        records.clear();
        bool woken = false;
        worker.pump(deadline.remainingMs(), records, wakeRead_.get(), &woken);
        for (const WireRecord& record : records) {
            relay.relay(record);
        }
        // Finished is the worker's last word (only _exit follows): the test is over.
        if (worker.exited() || relay.finished()) {
            break;
        }
        if (woken || interrupted_) {
            why = Stop::Interrupt;
        } else if (deadline.expired()) {
            why = Stop::Timeout;
        } else if (worker.corrupt()) {
            why = Stop::Garbage;
        }
        if (why != Stop::None) {
            break;
        }
    }

    bool polite = true;
    if (why != Stop::None) {
        records.clear();
        polite = worker.stop(options_.killGrace, records);
        for (const WireRecord& record : records) {
            // A test that stops when asked (an exec test) says it was interrupted: that is our
            // SIGTERM, reported below as what it was.
            if (record.kind != WireKind::Event ||
                stateOf(record.event) != TestStatus::Interrupted) {
                relay.relay(record);
            }
        }
    }
    if (relay.finished() && !worker.exited()) {
        worker.drainOutput();
    }
    platform::ExitStatus ending = platform::ExitStatus::fromWaitStatus(worker.waitStatus());
    std::string forced = polite ? "" : " (it ignored SIGTERM and was killed)";
    if (why == Stop::Timeout) {
        relay.add(events::timeout(
            TestMessage("timed out after " + seconds(spec.timeout) + forced, said(relay))));
    } else if (why == Stop::Interrupt) {
        // The kind says "interrupted" before the message: the message says how.
        relay.add(
            events::interrupted(TestMessage(notrun::stoppedWhileRunning + forced, said(relay))));
    } else if (why == Stop::Garbage || worker.corrupt()) {
        relay.add(events::error(
            TestMessage("the worker sent unreadable events; it was stopped", ending.toString())));
    } else if (!relay.finished() && worker.pid() <= 0) {
        relay.add(events::error(TestMessage("cannot run " + spec.plugin + " in a worker",
                                            "the fork server could not start a worker")));
    } else if (!relay.finished()) {
        // The worker died before it finished (in the test, or destroying it after endTest).
        if (ending.signaled) {
            const std::string in = relay.repetition().empty() ? "" : " in " + relay.repetition();
            relay.add(events::crash(TestMessage(
                "crashed" + in + ": " + platform::crashName(ending.signal), said(relay))));
        } else {
            const std::string in = relay.repetition().empty() ? "" : " in " + relay.repetition();
            relay.add(events::error(TestMessage(
                "exited with status " + std::to_string(ending.code) + " before the test ended" + in,
                said(relay))));
        }
    }
    relay.end(worker.output().take());
    return relay.status();
}

}  // namespace isolation
}  // namespace robottestingframework
