#include "platform/process.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <thread>

#include "platform/clock.h"
#include "platform/file_descriptor.h"
#include "platform/process_lifetime.h"
#include "platform/signal_name.h"

extern char** environ;

namespace robottestingframework {
namespace platform {

namespace {

[[noreturn]] void failChild(int reportFd, const char* what) {
    int code = errno;
    ssize_t ignored = ::write(reportFd, &code, sizeof(code));
    ignored = ::write(reportFd, what, ::strlen(what));
    (void)ignored;
    ::_exit(127);
}

// "NAME=value" for our environment with `changes` applied.
std::vector<std::string> mergedEnvironment(
    const std::vector<std::pair<std::string, std::string>>& changes) {
    std::map<std::string, std::string> merged;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const char* eq = std::strchr(*entry, '=');
        if (eq != nullptr) {
            merged[std::string(*entry, static_cast<std::size_t>(eq - *entry))] = eq + 1;
        }
    }
    for (const auto& [name, value] : changes) {
        merged[name] = value;
    }
    std::vector<std::string> entries;
    for (const auto& [name, value] : merged) {
        entries.push_back(name + "=" + value);
    }
    return entries;
}

// exec said ENOENT although the program is there: the interpreter on its #! line is missing.
std::string missingInterpreter(const std::string& program) {
    if (program.find('/') == std::string::npos || ::access(program.c_str(), F_OK) != 0) {
        return {};
    }
    std::ifstream file(program, std::ios::binary);
    std::string first;
    std::getline(file, first);
    if (first.compare(0, 2, "#!") != 0) {
        return {};
    }
    std::size_t begin = first.find_first_not_of(" \t", 2);
    if (begin == std::string::npos) {
        return program + ": its #! line names no interpreter";
    }
    std::size_t end = first.find_first_of(" \t\r", begin);
    std::string interpreter = first.substr(begin, end == std::string::npos ? end : end - begin);
    if (::access(interpreter.c_str(), X_OK) == 0) {
        return {};
    }
    return program + ": its interpreter " + interpreter + " (line 1: " + first +
           ") cannot be run: " + ::strerror(errno);
}

}  // namespace

pid_t spawnProcess(const SpawnOptions& options, std::string& error, int* errorNumber) {
    if (options.argv.empty()) {
        error = "nothing to run";
        return -1;
    }
    // Everything the child needs is prepared here: after fork only async-signal-safe calls.
    std::vector<char*> argv;
    for (const std::string& word : options.argv) {
        argv.push_back(const_cast<char*>(word.c_str()));
    }
    argv.push_back(nullptr);
    const char* program = options.program.empty() ? argv[0] : options.program.c_str();
    const char* folder =
        options.workingDirectory.empty() ? nullptr : options.workingDirectory.c_str();
    std::vector<std::string> envEntries;
    std::vector<char*> envp;
    if (!options.environment.empty()) {
        envEntries = mergedEnvironment(options.environment);
        for (std::string& entry : envEntries) {
            envp.push_back(entry.data());
        }
        envp.push_back(nullptr);
    }
    int highest = 2;
    bool mapsStdin = false;
    for (const auto& mapping : options.fds) {
        highest = mapping.first > highest ? mapping.first : highest;
        mapsStdin = mapsStdin || mapping.first == 0;
    }
    FileDescriptor reportRead, reportWrite;
    if (!makePipe(reportRead, reportWrite)) {
        error = std::string("pipe: ") + ::strerror(errno);
        return -1;
    }
    if (options.parentDeathSignal != 0) {
        prepareChildrenParentDeath();
    }
    pid_t parent = ::getpid();
    pid_t pid = ::fork();
    if (pid < 0) {
        error = std::string("fork: ") + ::strerror(errno);
        return -1;
    }
    if (pid == 0) {
        int report = reportWrite.get();
        if (options.newProcessGroup) {
            ::setpgid(0, 0);
        }
        // Signals this process ignores or handles start at their defaults in the program.
        for (int number = 1; number < NSIG; ++number) {
            if (number != SIGKILL && number != SIGSTOP) {
                ::signal(number, SIG_DFL);
            }
        }
        sigset_t none;
        sigemptyset(&none);
        ::sigprocmask(SIG_SETMASK, &none, nullptr);
        if (options.parentDeathSignal != 0 &&
            !armParentDeathSignalInChild(options.parentDeathSignal, parent)) {
            ::_exit(127);  // the parent died before the signal was armed
        }
        // Move the report pipe and the sources above every target, then place them.
        int base = highest + 1 + static_cast<int>(options.fds.size()) + 1;
        report = ::fcntl(report, F_DUPFD_CLOEXEC, base);
        int next = report + 1;
        int sources[64];
        int count = 0;
        for (const auto& mapping : options.fds) {
            if (count < 64) {
                sources[count++] = ::fcntl(mapping.second, F_DUPFD, next);
                next = sources[count - 1] + 1;
            }
        }
        for (int i = 0; i < count; ++i) {
            if (::dup2(sources[i], options.fds[static_cast<std::size_t>(i)].first) < 0) {
                failChild(report, "dup2");
            }
        }
        if (options.nullStdin && !mapsStdin) {
            int null = ::open("/dev/null", O_RDONLY);
            if (null >= 0 && null != 0) {
                ::dup2(null, 0);
                ::close(null);
            }
        }
        // Keep 0-2, the mapped targets and the report pipe; close everything else.
        for (int fd = 3; fd <= highest; ++fd) {
            bool keep = false;
            for (const auto& mapping : options.fds) {
                keep = keep || mapping.first == fd;
            }
            if (!keep) {
                ::close(fd);
            }
        }
        for (int i = 0; i < count; ++i) {
            ::close(sources[i]);
        }
        for (int fd = highest + 1; fd < report; ++fd) {
            ::close(fd);
        }
        closeDescriptorsFrom(report + 1);
        if (folder != nullptr && ::chdir(folder) != 0) {
            failChild(report, "chdir");
        }
        if (envp.empty()) {
            ::execvp(program, argv.data());
        } else {
            execSearchingPath(program, argv.data(), envp.data());
        }
        failChild(report, "exec");
    }
    reportWrite.reset();
    // The child writes errno and a word only when it failed; EOF (exec closed it) is success.
    std::string message;
    while (readSome(reportRead.get(), message) > 0) {
    }
    if (!message.empty()) {
        int code = 0;
        if (message.size() >= sizeof(code)) {
            ::memcpy(&code, message.data(), sizeof(code));
        }
        const std::string step = message.substr(sizeof(code));
        const std::string file = options.program.empty() ? options.argv[0] : options.program;
        std::string interpreter = code == ENOENT && step == "exec" ? missingInterpreter(file) : "";
        if (step == "chdir") {
            error =
                "cannot enter the folder '" + options.workingDirectory + "': " + ::strerror(code);
        } else if (!interpreter.empty()) {
            error = interpreter;
        } else {
            error = step + " " + file + ": " + ::strerror(code);
        }
        if (errorNumber != nullptr) {
            *errorNumber = code;
        }
        int status;
        ::waitpid(pid, &status, 0);
        return -1;
    }
    return pid;
}

ExitStatus ExitStatus::fromWaitStatus(int status) {
    ExitStatus result;
    if (WIFSIGNALED(status)) {
        result.signaled = true;
        result.signal = WTERMSIG(status);
#ifdef WCOREDUMP
        result.coreDumped = WCOREDUMP(status);
#endif
    } else if (WIFEXITED(status)) {
        result.code = WEXITSTATUS(status);
    }
    return result;
}

std::string ExitStatus::toString() const {
    if (signaled) {
        return "killed by " + signalName(signal) + " (" + signalDescription(signal) + ")";
    }
    return "exited with status " + std::to_string(code);
}

bool waitChild(pid_t pid, double timeoutSeconds, int& status) {
    Deadline deadline(timeoutSeconds);
    int pause = 1;
    // With a pidfd the wait ends as the child does; without, polling with growing pauses
    // notices it up to a pause late (up to 20 ms: most of a short run's shutdown).
    const FileDescriptor ended(timeoutSeconds > 0 ? openExitNotifier(pid) : -1);
    for (;;) {
        pid_t done = ::waitpid(pid, &status, timeoutSeconds < 0 ? 0 : WNOHANG);
        if (done == pid) {
            return true;
        }
        if (done < 0 && errno != EINTR) {
            status = 0;
            return true;  // not our child (any more): nothing to wait for
        }
        if (done == 0) {
            if (timeoutSeconds == 0 || deadline.expired()) {
                return false;
            }
            if (ended.valid()) {
                pollfd readable{ended.get(), POLLIN, 0};
                ::poll(&readable, 1, deadline.remainingMs());  // EINTR: look again
            } else {
                std::this_thread::sleep_for(std::chrono::milliseconds(pause));
                pause = pause < 20 ? pause * 2 : 20;
            }
        }
    }
}

std::size_t threadCount() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.compare(0, 8, "Threads:") == 0) {
            return static_cast<std::size_t>(std::strtoul(line.c_str() + 8, nullptr, 10));
        }
    }
    return 0;
}

std::size_t threadCountSettled(std::size_t atMost, int waitMs) {
    double end = monotonicSeconds() + waitMs / 1000.0;
    std::size_t count = threadCount();
    while (count > atMost && monotonicSeconds() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        count = threadCount();
    }
    return count;
}

std::vector<int> openDescriptors() {
    std::vector<int> found;
    DIR* folder = ::opendir("/proc/self/fd");
    if (folder == nullptr) {
        return found;
    }
    int own = ::dirfd(folder);
    while (dirent* entry = ::readdir(folder)) {
        char* end = nullptr;
        long fd = std::strtol(entry->d_name, &end, 10);
        if (end != entry->d_name && *end == '\0' && fd != own) {
            found.push_back(static_cast<int>(fd));
        }
    }
    ::closedir(folder);
    std::sort(found.begin(), found.end());
    return found;
}

std::string executablePath() {
    char buffer[PATH_MAX];
    ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
    return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : std::string();
}

std::vector<std::string> shellCommand(const std::string& text) {
    return {"/bin/sh", "-c", text};
}

}  // namespace platform
}  // namespace robottestingframework
