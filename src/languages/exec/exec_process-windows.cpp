// Windows: the program runs in a job object of its own (platform/job_process.h), so stopping
// it, or its end, ends whatever it started too. A .bat or .cmd file runs through `cmd /c`.
// There is no SIGTERM to ask with: a stop ends the job at once. A program that ends by an
// exception (0xC0000005) is reported as one killed by a signal is on POSIX.
#include <windows.h>

#include <algorithm>
#include <cstdlib>
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

bool ExecProcess::start(const std::vector<std::string>& argv,
                        const std::vector<std::pair<std::string, std::string>>& environment,
                        int outFd, int errFd, std::string& error) {
    platform::JobProcessOptions options;
    options.argv = argv;
    if (!argv.empty() && isBatchFile(argv[0])) {
        const char* shell = std::getenv("ComSpec");
        options.argv.insert(options.argv.begin(), {shell != nullptr ? shell : "cmd.exe", "/c"});
    }
    options.stdoutFd = outFd;
    options.stderrFd = errFd;
    options.environment = environment;
    auto job = std::make_shared<platform::JobProcess>();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!job->start(options, error)) {
        return false;
    }
    job_ = job;
    if (terminate_) {  // terminate() came while it was being started
        job->kill();
    }
    return true;
}

void ExecProcess::waitForEnd(int outFd, int errFd, const Sink& out, const Sink& err,
                             const std::function<void()>& stopping, ExecOutcome& outcome) {
    std::shared_ptr<platform::JobProcess> job;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        job = job_;
    }
    bool outOpen = true;
    bool errOpen = true;
    bool toldStopping = false;
    for (;;) {
        // Checked before reading: what it wrote before it ended is read below, all of it.
        const bool ended = job->ended();
        std::vector<bool> ready;
        if (platform::waitReadable({outOpen ? outFd : -1, errOpen ? errFd : -1}, ended ? 0 : 20,
                                   ready)) {
            if (ready[0]) {
                outOpen = readAvailable(outFd, out);
            }
            if (ready[1]) {
                errOpen = readAvailable(errFd, err);
            }
        } else if (!outOpen && !errOpen && !ended) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        tellStopping(toldStopping, stopping);
        if (ended) {
            break;
        }
    }
    if (outOpen) {
        readAvailable(outFd, out);
    }
    if (errOpen) {
        readAvailable(errFd, err);
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
}

void ExecProcess::stopRunning() {
    if (job_) {
        job_->kill();
    }
}

}  // namespace languages
}  // namespace robottestingframework
