#include "exec_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

extern char** environ;

namespace robottestingframework {
namespace languages {

namespace {

// Reads what is there; false at end of file (or on error).
bool drain(int fd, std::string& into) {
    char buffer[8192];
    for (;;) {
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            into.append(buffer, static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            return true;
        }
        return false;
    }
}

// Seconds between SIGTERM and SIGKILL when the program (and what it started) is stopped.
const double kStopGrace = 1.0;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The program led its own process group; what it started in the background may still be in
// it after it ended. SIGTERM, a short grace, then SIGKILL, so a test never leaves them behind.
void stopGroup(pid_t group) {
    if (::kill(-group, SIGTERM) != 0) {
        return;  // nothing left
    }
    const auto start = std::chrono::steady_clock::now();
    while (::kill(-group, 0) == 0 && secondsSince(start) < kStopGrace) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(-group, SIGKILL);
}

}  // namespace

std::string signalName(int signal) {
    const char* abbrev = ::sigabbrev_np(signal);
    return abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(signal);
}

ExecOutcome ExecProcess::run(const std::vector<std::string>& argv,
                             const std::vector<std::pair<std::string, std::string>>& environment) {
    ExecOutcome outcome;
    std::map<std::string, std::string> env;
    for (char** e = environ; *e; ++e) {
        const char* eq = std::strchr(*e, '=');
        if (eq) {
            env[std::string(*e, static_cast<std::size_t>(eq - *e))] = eq + 1;
        }
    }
    for (const auto& [name, value] : environment) {
        env[name] = value;
    }
    std::vector<std::string> envStrings;
    for (const auto& [name, value] : env) {
        envStrings.push_back(name + "=" + value);
    }
    std::vector<char*> envp;
    for (auto& s : envStrings) {
        envp.push_back(s.data());
    }
    envp.push_back(nullptr);
    std::vector<std::string> args = argv;
    std::vector<char*> argp;
    for (auto& s : args) {
        argp.push_back(s.data());
    }
    argp.push_back(nullptr);

    int outPipe[2];
    int errPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0) {
        outcome.startError = std::strerror(errno);
        return outcome;
    }
    if (::pipe2(errPipe, O_CLOEXEC) != 0) {
        outcome.startError = std::strerror(errno);
        ::close(outPipe[0]);
        ::close(outPipe[1]);
        return outcome;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, outPipe[1], 1);
    posix_spawn_file_actions_adddup2(&actions, errPipe[1], 2);
    // The child starts with default signal handling, whatever this process installed.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t all;
    sigfillset(&all);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &all);
    posix_spawnattr_setsigmask(&attributes, &none);
    // Its own process group: stopping it stops whatever it started too.
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(
        &attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP);

    pid_t pid = -1;
    int spawnError;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        spawnError = ::posix_spawn(&pid, argp[0], &actions, &attributes, argp.data(), envp.data());
        if (spawnError == 0) {
            pid_ = pid;
            if (terminate_) {  // terminate() came while it was being started
                ::kill(-pid, SIGTERM);
                terminatedAt_ = std::chrono::steady_clock::now();
            }
        }
    }
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    if (spawnError != 0) {
        outcome.startError = std::strerror(spawnError);
        ::close(outPipe[0]);
        ::close(errPipe[0]);
        return outcome;
    }
    outcome.started = true;
    ::fcntl(outPipe[0], F_SETFL, O_NONBLOCK);
    ::fcntl(errPipe[0], F_SETFL, O_NONBLOCK);

    bool outOpen = true;
    bool errOpen = true;
    int status = 0;
    bool exited = false;
    bool killed = false;
    while (!exited) {
        if (!outOpen && !errOpen) {
            // Both pipes are closed: poll for the end (reaped under the lock below, so
            // terminate() never signals a recycled pid), still escalating a stop.
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        } else {
            pollfd fds[2] = {{outOpen ? outPipe[0] : -1, POLLIN, 0},
                             {errOpen ? errPipe[0] : -1, POLLIN, 0}};
            // Wakes up now and then to notice the program's end even when something it
            // started in the background still holds the pipes open.
            if (::poll(fds, 2, 100) > 0) {
                if (outOpen && fds[0].revents) {
                    outOpen = drain(outPipe[0], outcome.out);
                }
                if (errOpen && fds[1].revents) {
                    errOpen = drain(errPipe[0], outcome.err);
                }
            }
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (::waitpid(pid, &status, WNOHANG) == pid) {
            exited = true;
            pid_ = -1;
        } else if (terminate_ && !killed && secondsSince(terminatedAt_) >= kStopGrace) {
            ::kill(-pid, SIGKILL);  // it ignored SIGTERM
            killed = true;
        }
    }
    stopGroup(pid);
    if (outOpen) {
        drain(outPipe[0], outcome.out);
    }
    if (errOpen) {
        drain(errPipe[0], outcome.err);
    }
    ::close(outPipe[0]);
    ::close(errPipe[0]);
    if (WIFEXITED(status)) {
        outcome.exitStatus = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        outcome.signal = WTERMSIG(status);
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
    if (pid_ > 0) {
        ::kill(-pid_, SIGTERM);  // its whole group
    }
}

}  // namespace languages
}  // namespace robottestingframework
