#include "languages/exec/exec_process.h"

#include <cerrno>
#include <cstring>

#include "platform/file_descriptor.h"

// What every platform shares; starting the program, waiting for its end and stopping it are in
// exec_process-<platform>.cpp.
namespace robottestingframework {
namespace languages {

ExecOutcome ExecProcess::run(const std::vector<std::string>& argv,
                             const std::vector<std::pair<std::string, std::string>>& environment,
                             const Sink& out, const Sink& err,
                             const std::function<void()>& stopping) {
    ExecOutcome outcome;
    platform::FileDescriptor outRead, outWrite, errRead, errWrite;
    if (!platform::makePipe(outRead, outWrite) || !platform::makePipe(errRead, errWrite)) {
        outcome.startError = std::string("pipe: ") + std::strerror(errno);
        return outcome;
    }
    const bool started =
        start(argv, environment, outWrite.get(), errWrite.get(), outcome.startError);
    outWrite.reset();
    errWrite.reset();
    if (!started) {
        return outcome;
    }
    outcome.started = true;
    platform::setNonBlocking(outRead.get());
    platform::setNonBlocking(errRead.get());
    waitForEnd(outRead.get(), errRead.get(), out, err, stopping, outcome);
    return outcome;
}

void ExecProcess::tellStopping(bool& told, const std::function<void()>& stopping) {
    bool stopRequested;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopRequested = terminate_;
    }
    if (stopRequested && !told) {
        told = true;
        if (stopping) {
            stopping();
        }
    }
}

void ExecProcess::reset() {
    std::lock_guard<std::mutex> lock(mutex_);
    terminate_ = false;
}

void ExecProcess::terminate() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!terminate_) {
        terminatedAt_ = std::chrono::steady_clock::now();
    }
    terminate_ = true;
    stopRunning();
}

}  // namespace languages
}  // namespace robottestingframework
