// Windows: the program runs in a job object of its own (platform/job_process.h), so stopping
// it, or its end, ends whatever it started too. A .bat or .cmd file runs through `cmd /c`.
// There is no SIGTERM to ask with: a stop ends the job at once. A program that ends by an
// exception (0xC0000005) is reported as one killed by a signal is on POSIX.
#include <windows.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <thread>

#include "languages/exec/exec_process.h"
#include "platform/file_descriptor.h"
#include "platform/job_process.h"
#include "platform/process.h"

namespace robottestingframework {
namespace languages {

namespace {

bool isBatchFile(const std::string& path) {
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos) {
        return false;
    }
    const std::string extension = path.substr(dot);
    return ::_stricmp(extension.c_str(), ".bat") == 0 || ::_stricmp(extension.c_str(), ".cmd") == 0;
}

// Reads what is in the pipe now; false at end of file.
bool readAvailable(int fd, const ExecProcess::Sink& sink) {
    for (int chunks = 0; chunks < 64; ++chunks) {
        std::string bytes;
        const long n = platform::readSome(fd, bytes, 65536);
        if (n > 0) {
            sink(bytes.data(), bytes.size());
            continue;
        }
        return n < 0;  // -1: nothing now; 0: end of file
    }
    return true;
}

}  // namespace

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
    platform::JobProcessOptions options;
    options.argv = argv;
    if (!argv.empty() && isBatchFile(argv[0])) {
        const char* shell = std::getenv("ComSpec");
        options.argv.insert(options.argv.begin(), {shell != nullptr ? shell : "cmd.exe", "/c"});
    }
    options.stdoutFd = outWrite.get();
    options.stderrFd = errWrite.get();
    options.environment = environment;
    auto job = std::make_shared<platform::JobProcess>();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!job->start(options, outcome.startError)) {
            return outcome;
        }
        job_ = job;
        if (terminate_) {  // terminate() came while it was being started
            job->kill();
        }
    }
    outWrite.reset();
    errWrite.reset();
    outcome.started = true;
    platform::setNonBlocking(outRead.get());
    platform::setNonBlocking(errRead.get());

    bool outOpen = true;
    bool errOpen = true;
    bool toldStopping = false;
    for (;;) {
        // Checked before reading: what it wrote before it ended is read below, all of it.
        const bool ended = job->ended();
        std::vector<bool> ready;
        if (platform::waitReadable({outOpen ? outRead.get() : -1, errOpen ? errRead.get() : -1},
                                   ended ? 0 : 20, ready)) {
            if (ready[0]) {
                outOpen = readAvailable(outRead.get(), out);
            }
            if (ready[1]) {
                errOpen = readAvailable(errRead.get(), err);
            }
        } else if (!outOpen && !errOpen && !ended) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        bool stopRequested;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopRequested = terminate_;
        }
        if (stopRequested && !toldStopping) {
            toldStopping = true;
            if (stopping) {
                stopping();
            }
        }
        if (ended) {
            break;
        }
    }
    if (outOpen) {
        readAvailable(outRead.get(), out);
    }
    if (errOpen) {
        readAvailable(errRead.get(), err);
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job_.reset();
    }
    const platform::ExitStatus status =
        platform::ExitStatus::fromWaitStatus(static_cast<int>(job->exitCode()));
    job.reset();  // closing the job ends what the program left behind
    if (status.signaled) {
        outcome.signal = status.signal;
    } else {
        outcome.exitStatus = status.code;
    }
    return outcome;
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
    if (job_) {
        job_->kill();
    }
}

}  // namespace languages
}  // namespace robottestingframework
