#include "runner/execution/isolated_fixture.h"

#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <exception>
#include <sstream>

#include <robottestingframework/Exception.h>
#include <robottestingframework/TestResult.h>

#include "isolation/event_relay.h"
#include "platform/clock.h"
#include "platform/private_network.h"
#include "platform/process.h"
#include "platform/process_tree.h"

namespace robottestingframework {
namespace isolation {

IsolatedFixture::IsolatedFixture(std::shared_ptr<ForkServer> server, WorkRequest request,
                                 IsolationOptions options)
    : FixtureManager(nullptr, request.param),
      server_(std::move(server)),
      request_(std::move(request)),
      options_(std::move(options)) {
    setName(request_.name);
}

IsolatedFixture::~IsolatedFixture() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quitting_ = true;
    }
    if (pid_ > 0) {
        bool alive;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            alive = !dead_;
        }
        if (alive) {
            platform::signalProcessGroup(pid_, SIGKILL);
        }
    }
    if (reader_.joinable()) {
        char byte = 1;
        ssize_t ignored = ::write(wakeWrite_.get(), &byte, 1);
        (void)ignored;
        reader_.join();
    }
}

void IsolatedFixture::watch() {
    std::vector<WireRecord> records;
    for (;;) {
        records.clear();
        bool woken = false;
        worker_->pump(-1, records, wakeRead_.get(), &woken);
        std::vector<TestMessage> collapses;
        bool diedQuietly = false;
        int status = 0;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            for (WireRecord& record : records) {
                if (record.kind == WireKind::Reply) {
                    reply_ = std::move(record);
                    replied_ = true;
                } else if (record.kind == WireKind::FixtureCollapsed) {
                    collapses.push_back(record.message);
                } else if (record.kind == WireKind::Event ||
                           record.kind == WireKind::FixtureCheckFailed) {
                    events_.push_back(std::move(record));  // in order, on the caller's thread
                }
            }
            std::string text = worker_->output().take();
            output_ += text;
            if (output_.size() > options_.outputTail * 2) {
                output_.erase(0, output_.size() - options_.outputTail);
            }
            if (worker_->exited()) {
                dead_ = true;
                status_ = worker_->waitStatus();
                status = status_;
                diedQuietly = !inCall_ && !quitting_;
            }
        }
        changed_.notify_all();
        // The dispatcher (the suite) is thread-safe by contract; call it unlocked.
        FixtureEvents* dispatcher = getDispatcher();
        for (const TestMessage& reason : collapses) {
            if (dispatcher != nullptr) {
                dispatcher->fixtureCollapsed(reason);
            }
        }
        if (diedQuietly && dispatcher != nullptr) {
            dispatcher->fixtureCollapsed(
                TestMessage("fixture " + getName() +
                            " died: " + platform::ExitStatus::fromWaitStatus(status).toString()));
        }
        if (worker_->exited() || woken) {
            return;
        }
    }
}

void IsolatedFixture::flush() {
    std::deque<WireRecord> events;
    std::string output;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        events.swap(events_);
        output.swap(output_);
    }
    TestResult* result = getResult();
    FixtureEvents* dispatcher = getDispatcher();
    for (const WireRecord& record : events) {
        if (record.kind == WireKind::FixtureCheckFailed) {
            // A record of its own in the suite; said with tearDown's failure when not taken.
            if (dispatcher == nullptr ||
                !dispatcher->fixtureCheckFailed(record.name, record.message,
                                                record.attachment.get())) {
                untakenChecks_ += (untakenChecks_.empty() ? "" : "\n") + record.name + ": " +
                                  record.message.toString();
            }
        } else if (result != nullptr) {
            relayEvent(record, getOwner(), *result);
        }
    }
    if (result == nullptr) {
        return;
    }
    if (!output.empty()) {
        result->addOutput(getOwner(), output);
    }
}

void IsolatedFixture::waitDead(double seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return dead_; });
}

void IsolatedFixture::kill() {
    if (pid_ <= 0) {
        return;
    }
    platform::signalProcessGroup(pid_, SIGTERM);
    platform::signalProcessGroup(pid_, SIGCONT);
    waitDead(options_.killGrace);
    bool alive;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        alive = !dead_;
    }
    if (alive) {
        platform::signalProcessGroup(pid_, SIGKILL);
        waitDead(10.0);
    }
}

bool IsolatedFixture::call(const std::string& name, const std::string& payload) {
    failure_.clear();
    if (!worker_) {
        worker_.reset(new WorkerProcess());
        std::string error;
        request_.param = getParam();  // the scheduler may have filled in ${resource.NAME}
        if (!worker_->start(*server_, request_, error, true,
                            network_ ? network_->descriptors() : std::vector<int>())) {
            failure_ = "cannot start fixture " + getName() + ": " + error;
            worker_.reset();
        } else {
            pid_ = worker_->pid();
            platform::makePipe(wakeRead_, wakeWrite_);
            // The calls go out on a second descriptor of our end of the channel, so the reader
            // thread owns the WorkerProcess alone.
            writer_.reset(::dup(worker_->channel()));
            reader_ = std::thread(&IsolatedFixture::watch, this);
        }
    }
    if (failure_.empty()) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (dead_) {
            failure_ = "fixture " + getName() + " is not running any more (" +
                       platform::ExitStatus::fromWaitStatus(status_).toString() + ")";
        } else {
            inCall_ = true;
            callName_ = name;
            interrupted_ = false;
            replied_ = false;
        }
    }
    bool ok = false;
    if (failure_.empty()) {
        WireRecord record;
        record.kind = WireKind::Call;
        record.name = name;
        record.message = TestMessage(payload);
        platform::sendAll(writer_.get(), encode(record));

        platform::Deadline deadline(options_.fixtureTimeout);
        bool done = false;
        while (!done) {
            flush();
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait_for(lock, std::chrono::milliseconds(deadline.remainingMs(100)),
                              [this] { return replied_ || dead_ || !events_.empty(); });
            done = replied_ || dead_ || deadline.expired() || interrupted_;
        }
        bool timedOut = false;
        bool interrupted = false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (replied_) {
                ok = reply_.flag;
                if (!ok) {
                    failure_ = reply_.message.toString();  // empty: it returned false
                }
            } else if (dead_) {
                failure_ = "fixture " + getName() + " died in " + name + ": " +
                           platform::ExitStatus::fromWaitStatus(status_).toString();
            } else if (interrupted_) {
                interrupted = true;
                failure_ = "fixture " + getName() + " " + name + " interrupted";
            } else {
                timedOut = true;
            }
        }
        if (interrupted) {
            kill();
        }
        if (timedOut) {
            std::ostringstream text;
            text << "fixture " << getName() << " " << name << " timed out after "
                 << options_.fixtureTimeout << " s";
            failure_ = text.str();
            kill();
        }
        std::lock_guard<std::mutex> lock(mutex_);
        inCall_ = false;
    }
    flush();
    // Why it failed goes to the suite with the exception, which names the fixture and the call
    // and hands the reason on to the tests it skips.
    if (!ok && !failure_.empty()) {
        throw TestErrorException(TestMessage(failure_));
    }
    return ok;
}

bool IsolatedFixture::setup(int argc, char** argv) {
    // Each word ends with '\0': no word is no byte, an empty word is one.
    std::string payload;
    for (int i = 0; i < argc; ++i) {
        payload += argv[i];
        payload.push_back('\0');
    }
    return call("setup", payload);
}

void IsolatedFixture::interruptCall() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!inCall_ || callName_ == "tearDown") {
            return;
        }
        interrupted_ = true;
    }
    changed_.notify_all();
}

bool IsolatedFixture::check() {
    return call("check", "");
}

void IsolatedFixture::tearDown() {
    if (!worker_) {
        return;
    }
    std::exception_ptr failed;
    try {
        call("tearDown", "");
    } catch (...) {
        failed = std::current_exception();
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quitting_ = true;
    }
    // End of file on the channel: the worker returns and exits.
    ::shutdown(writer_.get(), SHUT_WR);
    waitDead(options_.killGrace + 1.0);
    bool alive;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        alive = !dead_;
    }
    if (alive) {
        kill();
    }
    flush();
    if (failed) {
        std::rethrow_exception(failed);
    }
    if (!untakenChecks_.empty()) {
        std::string checks;
        checks.swap(untakenChecks_);
        throw TestErrorException(TestMessage(checks));
    }
}

}  // namespace isolation
}  // namespace robottestingframework
