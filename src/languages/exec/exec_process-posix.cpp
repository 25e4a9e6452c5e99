#include "languages/exec/exec_process.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>

#include "platform/file_descriptor.h"
#include "platform/process.h"
#include "platform/process_tree.h"

namespace robottestingframework {
namespace languages {

namespace {

// Reads one chunk into `sink`; false at end of file (or on error).
bool readChunk(int fd, const ExecProcess::Sink& sink) {
    char buffer[65536];
    for (;;) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            sink(buffer, static_cast<std::size_t>(n));
            return true;
        }
        if (n < 0 && errno == EINTR) {
            continue;
        }
        return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
    }
}

// Reads what is already there (bounded: a program that keeps writing does not hold us).
bool drain(int fd, const ExecProcess::Sink& sink) {
    for (int chunks = 0; chunks < 64; ++chunks) {
        pollfd ready{fd, POLLIN, 0};
        if (::poll(&ready, 1, 0) <= 0) {
            return true;
        }
        if (!readChunk(fd, sink)) {
            return false;
        }
    }
    return true;
}

// Seconds between SIGTERM and SIGKILL when the program (and what it started) is stopped.
const double kStopGrace = 1.0;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The program led its own process group; what it started in the background may still be in
// it after it ended. SIGTERM, a short grace, then SIGKILL, so a test never leaves them behind.
// Members of the group that are our children (with --isolation none the runner adopts the
// orphans a test leaves) are reaped as they die: a zombie still answers kill(), and would hold
// every such test for the whole grace.
bool groupAlive(pid_t group) {
    while (::waitpid(-group, nullptr, WNOHANG) > 0) {
    }
    return ::kill(-group, 0) == 0;
}

void stopGroup(pid_t group) {
    if (!platform::signalProcessGroup(group, SIGTERM)) {
        return;  // nothing left
    }
    const auto start = std::chrono::steady_clock::now();
    while (groupAlive(group) && secondsSince(start) < kStopGrace) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (platform::signalProcessGroup(group, SIGKILL)) {
        const auto killed = std::chrono::steady_clock::now();
        while (groupAlive(group) && secondsSince(killed) < 0.2) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
}

}  // namespace

bool ExecProcess::start(const std::vector<std::string>& argv,
                        const std::vector<std::pair<std::string, std::string>>& environment,
                        int outFd, int errFd, std::string& error) {
    platform::SpawnOptions options;
    options.argv = argv;
    options.fds = {{1, outFd}, {2, errFd}};
    options.newProcessGroup = true;       // stopping it stops whatever it started too
    options.parentDeathSignal = SIGKILL;  // a runner killed with SIGKILL leaves no test behind
    options.environment = environment;
    // --isolation none: the runner's watchdog's variable (test_loader.h, setExecGuard).
    const std::string guard = execGuardEntry();
    const std::size_t equals = guard.find('=');
    if (equals != std::string::npos) {
        options.environment.emplace_back(guard.substr(0, equals), guard.substr(equals + 1));
    }

    std::lock_guard<std::mutex> lock(mutex_);
    const pid_t pid = platform::spawnProcess(options, error);
    if (pid <= 0) {
        return false;
    }
    pid_ = pid;
    if (terminate_) {  // terminate() came while it was being started
        platform::signalProcessGroup(pid, SIGTERM);
        terminatedAt_ = std::chrono::steady_clock::now();
    }
    return true;
}

void ExecProcess::waitForEnd(int outFd, int errFd, const Sink& out, const Sink& err,
                             const std::function<void()>& stopping, ExecOutcome& outcome) {
    pid_t pid;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pid = pid_;
    }
    bool outOpen = true;
    bool errOpen = true;
    int status = 0;
    bool exited = false;
    bool killed = false;
    bool toldStopping = false;
    while (!exited) {
        if (!outOpen && !errOpen) {
            // Both pipes are closed: poll for the end (reaped under the lock below, so
            // terminate() never signals a recycled pid), still escalating a stop.
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        } else {
            pollfd fds[2] = {{outOpen ? outFd : -1, POLLIN, 0}, {errOpen ? errFd : -1, POLLIN, 0}};
            // Wakes up now and then to notice the program's end even when something it
            // started in the background still holds the pipes open.
            if (::poll(fds, 2, 100) > 0) {
                if (outOpen && fds[0].revents) {
                    outOpen = readChunk(outFd, out);
                }
                if (errOpen && fds[1].revents) {
                    errOpen = readChunk(errFd, err);
                }
            }
        }
        tellStopping(toldStopping, stopping);
        std::lock_guard<std::mutex> lock(mutex_);
        if (::waitpid(pid, &status, WNOHANG) == pid) {
            exited = true;
            pid_ = -1;
        } else if (terminate_ && !killed && secondsSince(terminatedAt_) >= kStopGrace) {
            platform::signalProcessGroup(pid, SIGKILL);  // it ignored SIGTERM
            killed = true;
        }
    }
    stopGroup(pid);
    if (outOpen) {
        drain(outFd, out);
    }
    if (errOpen) {
        drain(errFd, err);
    }
    if (WIFEXITED(status)) {
        outcome.exitStatus = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        outcome.signal = WTERMSIG(status);
    }
}

void ExecProcess::stopRunning() {
    if (pid_ > 0) {
        platform::signalProcessGroup(pid_, SIGTERM);  // its whole group
    }
}

}  // namespace languages
}  // namespace robottestingframework
