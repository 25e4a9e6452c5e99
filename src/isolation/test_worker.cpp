#include <signal.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
#include <typeinfo>

#include <robottestingframework/TestResult.h>

#include "core/events.h"
#include "isolation/event_writer.h"
#include "isolation/worker.h"
#include "languages/test_loader.h"
#include "platform/signal_pipe.h"

namespace robottestingframework {
namespace isolation {

namespace {

EventWriter* activeWriter = nullptr;
std::string activeName;

std::string describeCurrentException() {
    try {
        throw;
    } catch (const std::exception& e) {
        return std::string("unhandled exception (") + typeid(e).name() + "): " + e.what();
    } catch (...) {
        return "unhandled exception of unknown type";
    }
}

// An exception that escapes everything (a test's own thread, a noexcept function): say what
// it was before the process aborts, so the report has more than "SIGABRT".
[[noreturn]] void onTerminate() {
    if (activeWriter != nullptr && std::current_exception()) {
        activeWriter->send(eventRecord(
            events::error(TestMessage("std::terminate called", describeCurrentException())),
            activeName));
    }
    std::abort();
}

std::string baseName(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int runTestWorker(const WorkRequest& request, int channel) {
    EventWriter writer(channel);
    activeWriter = &writer;
    activeName = request.name.empty() ? baseName(request.path) : request.name;
    std::set_terminate(onTerminate);

    std::string error;
    std::unique_ptr<languages::LoadedTest> loaded;
    try {
        loaded = languages::loadTest(request.type, request.path, error);
    } catch (...) {
        error = describeCurrentException();
    }
    if (!loaded || loaded->get() == nullptr) {
        writer.send(eventRecord(events::startTest(), activeName));
        writer.send(eventRecord(events::failure(TestMessage("cannot load " + request.path, error)),
                                activeName));
        writer.send(eventRecord(events::endTest(), activeName));
        writer.send(WireRecord{WireKind::Finished, {}, {}, {}, true, 0});
        return 0;
    }

    TestCase* test = loaded->get();
    if (!request.name.empty()) {
        test->setName(request.name);
    }
    test->setParam(request.param);
    test->setEnvironment(request.environment);
    test->setRepetition(request.repetition == 0 ? 1 : request.repetition);
    activeName = test->getName();
    WireRecord described;
    described.kind = WireKind::Described;
    described.name = test->getName();
    described.message = TestMessage(test->getDescription());
    writer.hold(described);  // goes out with startTest

    TestResult result;
    result.addListener(&writer);
    // The runner stops a test that outlives its time or is interrupted with SIGTERM. An exec
    // test is asked to stop instead of dying at once: it reports what its program said, then
    // stops it. Other tests end with the worker, as their output already reached the runner.
    std::unique_ptr<platform::SignalPipe> stopSignal;
    std::thread stopWatcher;
    if (request.type == "exec") {
        stopSignal = std::make_unique<platform::SignalPipe>(std::initializer_list<int>{SIGTERM});
        stopWatcher = std::thread([&stopSignal, test]() {
            if (stopSignal->wait() == SIGTERM) {
                test->interrupt();
            }
        });
    }
    try {
        test->run(result);
    } catch (...) {
        // TestCase::run catches what the test throws; this is for what escapes it anyway.
        writer.sendEvent(events::error(TestMessage(describeCurrentException())), test);
        writer.sendEvent(events::endTest(), test);
    }
    if (stopWatcher.joinable()) {
        stopSignal->wake();
        stopWatcher.join();
    }
    if (test->hasCriticalError()) {
        WireRecord record;
        record.kind = WireKind::CriticalError;
        record.name = test->getName();
        record.message = test->getCriticalError();
        writer.send(record);
    }
    std::string name = test->getName();
    // Destroying the test runs the plug-in's destructors: a crash there is still reported,
    // as it comes before Finished. After Finished the runner no longer waits for us.
    loaded.reset();
    std::fflush(stdout);
    std::fflush(stderr);
    writer.send(WireRecord{WireKind::Finished, {}, name, {}, true, 0});
    activeWriter = nullptr;
    return 0;
}

}  // namespace isolation
}  // namespace robottestingframework
