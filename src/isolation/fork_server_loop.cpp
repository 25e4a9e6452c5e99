#include "isolation/fork_server_loop.h"

#include <errno.h>
#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <set>
#include <thread>

#include "isolation/wire_format.h"
#include "isolation/worker.h"
#include "languages/test_loader.h"
#include "platform/clock.h"
#include "platform/coverage.h"
#include "platform/fd_passing.h"
#include "platform/file_descriptor.h"
#include "platform/fork_template.h"
#include "platform/private_network.h"
#include "platform/process.h"
#include "platform/process_tree.h"
#include "platform/signal_pipe.h"

namespace robottestingframework {
namespace isolation {

namespace {

using platform::FileDescriptor;

// A request's descriptors after its channel, output (and status, to the server): those of a
// private network, its user namespace and its network namespace.
constexpr std::size_t kMaxNetworkFds = 2;

// The descriptors a pre-started runtime opened (Ruby's internal pipes): its workers keep them.
std::vector<int> g_runtimeDescriptors;

// Closes every descriptor from `first` on, except the runtime's and `except`.
void closeFrom(int first, int except = -1) {
    std::vector<int> keep = g_runtimeDescriptors;
    if (except >= 0) {
        keep.push_back(except);
    }
    std::sort(keep.begin(), keep.end());
    int next = first;
    for (int fd : keep) {
        for (; next < fd; ++next) {
            ::close(next);
        }
        next = std::max(next, fd + 1);
    }
    platform::closeDescriptorsFrom(next);
}

// In a freshly forked child: the state every worker starts from. Returns in the child.
void prepareChild(pid_t server) {
    platform::SignalPipe::resetInChild();
    ::signal(SIGPIPE, SIG_DFL);
    ::setpgid(0, 0);
    platform::setParentDeathSignal(SIGKILL);
    if (::getppid() != server) {
        ::_exit(125);
    }
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
}

// Become the worker of `request`; first, in `network` when given (its suite's private network:
// the namespaces to join, platform/private_network.h). Never returns.
[[noreturn]] void becomeWorker(const WorkRequest& request, int channel, int output,
                               const std::vector<int>& network) {
    std::string refused;
    if (!network.empty() && !platform::joinPrivateNetwork(network, refused)) {
        const std::string line =
            "robottestingframework-worker: cannot join the suite's private network: " + refused +
            "\n";
        platform::writeAll(output, line);
        ::_exit(125);
    }
    // 0: /dev/null (the server's since it started), 1 and 2: the output pipe, 3: the channel,
    // close-on-exec (a program the test runs must not write on our channel); nothing else is
    // inherited. The spare received both descriptors close-on-exec on the lowest free numbers:
    // the channel on 3 (closed for it), the output above; then only the output moves.
    if (channel != 3 || output <= 3) {
        int high = ::fcntl(channel, F_DUPFD_CLOEXEC, 10);
        output = ::fcntl(output, F_DUPFD_CLOEXEC, 10);
        ::dup2(high, 3);
        platform::setCloseOnExec(3);
    }
    ::dup2(output, 1);
    ::dup2(output, 2);
    if (g_runtimeDescriptors.empty()) {
        platform::closeDescriptorsFrom(4);
    } else {
        closeFrom(4);
    }
    // Line-buffered, so what a test printed just before it crashed still reaches the report.
    ::setvbuf(stdout, nullptr, _IOLBF, 0);
    // The suite's resource items (RTF_RESOURCE_<POOL>), for the test and what it starts.
    for (const auto& variable : request.variables) {
        const std::size_t equals = variable.find('=');
        if (equals != std::string::npos && equals > 0) {
            ::setenv(variable.substr(0, equals).c_str(), variable.c_str() + equals + 1, 1);
        }
    }

    int code = request.role == WorkRequest::Role::Fixture ? runFixtureWorker(request, 3)
                                                          : runTestWorker(request, 3);
    // Finished is sent: the runner goes on with the next test without waiting for this process
    // to end. Woken by Finished, its thread is often queued behind this process on this CPU;
    // it goes first, and ending this process (unmapping it) waits. On 2 cores, about 10 % off
    // the time of 1 000 trivial isolated tests.
    ::sched_yield();
    ::fflush(stdout);
    ::fflush(stderr);
    platform::flushCoverage();
    ::_exit(code);
}

// A spare: forked ahead of time, so the fork is not on the path of the next test. It waits
// on `link` for its request and the two descriptors, then becomes that worker. `language`: the
// script runtime it was forked from, which rehearses a test meanwhile; empty for the server.
[[noreturn]] void waitAsSpare(int link, pid_t server, const std::string& language) {
    prepareChild(server);
    if (g_runtimeDescriptors.empty()) {
        ::dup2(link, 4);
        platform::closeDescriptorsFrom(5);
        link = 4;
    } else {
        closeFrom(4, link);
    }
    ::close(3);
    if (!language.empty()) {
        languages::rehearseLanguage(language);
    }
    std::string packet;
    std::vector<FileDescriptor> fds;
    WorkRequest request;
    // The channel, the output, then the namespaces of a private network if any.
    if (!platform::receiveWithFds(link, packet, fds) || fds.size() < 2 ||
        fds.size() > 2 + kMaxNetworkFds || !decodeRequest(packet, request)) {
        ::_exit(0);  // the server is gone or shutting down
    }
    std::vector<int> network;
    for (std::size_t i = 2; i < fds.size(); ++i) {
        network.push_back(fds[i].get());
    }
    becomeWorker(request, fds[0].get(), fds[1].get(), network);
}

// Spares the fork server keeps handed to the runner: one for the test it is about to ask for,
// one more for when that test ends before the next fork does.
constexpr std::size_t kAnnouncedSpares = 2;

// Spares a language server keeps: one rehearsing (waitAsSpare) while the other waits for the
// next test, so that the fork and the rehearsal of the one after it run beside that test
// rather than between two tests.
constexpr std::size_t kLanguageSpares = 2;

struct Spare {
    pid_t pid = -1;
    FileDescriptor link;
};

// Forks the next spare; false (no spare) when fork fails. `language`: the script runtime this
// process pre-started (its fork hooks run), empty for the fork server itself.
bool makeSpare(Spare& spare, pid_t server, const std::string& language) {
    FileDescriptor ours, theirs;
    if (!platform::makeSocketPair(ours, theirs, true)) {
        return false;
    }
    pid_t pid = language.empty() ? ::fork() : languages::forkLanguage(language);
    if (pid == 0) {
        waitAsSpare(theirs.get(), server, language);
    }
    if (pid < 0) {
        return false;
    }
    // Both sides set the group, so it exists before anyone signals it.
    ::setpgid(pid, pid);
    spare.pid = pid;
    spare.link = std::move(ours);
    return true;
}

bool sendStatus(int fd, WireKind kind, std::int64_t number) {
    WireRecord record;
    record.kind = kind;
    record.number = number;
    return platform::writeAll(fd, encode(record));
}

// Kills every descendant until none is left, reaping as they go. Bounded.
void killEverything() {
    pid_t self = ::getpid();
    platform::Deadline deadline(5.0);
    while (!deadline.expired()) {
        std::size_t killed = platform::killDescendants(self);
        int status;
        while (::waitpid(-1, &status, WNOHANG) > 0) {
        }
        if (killed == 0 && platform::descendantsOf(self).empty()) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    int status;
    while (::waitpid(-1, &status, WNOHANG) > 0) {
    }
}

// A pre-started interpreter (see fork_server_loop.h): a child of the fork server that serves
// the requests of one script language as the server does, from forks of itself.
struct LanguageServer {
    pid_t pid = -1;
    FileDescriptor control;
    std::string refused;  // why it cannot be pre-started: its tests take the plain path
    // Requests sent to it and not yet taken (it answers once per request, in order).
    std::deque<std::pair<std::string, std::vector<FileDescriptor>>> pending;
};

bool isScriptLanguage(const std::string& type) {
    return type == "python" || type == "lua" || type == "ruby";
}

bool prestartWanted() {
    const char* setting = std::getenv("RTF_PRESTART");
    return setting == nullptr || std::strcmp(setting, "0") != 0;
}

int serve(int control, const std::string& language, bool verbose);

// In the child: pre-starts `language`, says on `link` whether it could ("" or why not), then
// serves. Never returns.
[[noreturn]] void runLanguageServer(int link, pid_t server, const std::string& language) {
    prepareChild(server);
    ::dup2(link, 4);
    ::dup2(4, 3);
    platform::closeDescriptorsFrom(4);
    std::string error;
    bool ready = false;
    try {
        ready = languages::prestartLanguage(language, error);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!ready) {
        platform::sendWithFds(3, "refused: " + error, {});
        platform::flushCoverage();
        ::_exit(0);
    }
    for (int fd : platform::openDescriptors()) {
        if (fd > 3) {
            g_runtimeDescriptors.push_back(fd);
        }
    }
    struct Context {
        std::string language;
        std::size_t threads;
        bool hosted;
    } context{language, platform::threadCountSettled(1, 200), false};
    int code = languages::hostLanguage(
        language,
        [](void* opaque) {
            auto* context = static_cast<Context*>(opaque);
            // A fork keeps only the calling thread: a thread started with the runtime (or by
            // what it imported) would be missing in every test, holding whatever lock it held.
            // A runtime with a thread of its own forks from that thread, and the thread that
            // waits for it is not needed in a test.
            if (context->threads != (context->hosted ? 2u : 1u)) {
                platform::sendWithFds(3,
                                      "refused: " + std::to_string(context->threads) +
                                          " threads run once it started, and a fork keeps one",
                                      {});
                return 0;
            }
            if (!platform::sendWithFds(3, "ready", {})) {
                return 0;
            }
            return serve(3, context->language, false);
        },
        &context, context.hosted);
    platform::flushCoverage();
    ::_exit(code);
}

// Starts the language server of `language` and waits (bounded) until it is ready.
void startLanguageServer(LanguageServer& entry, pid_t self, const std::string& language,
                         bool verbose) {
    FileDescriptor ours, theirs;
    if (!platform::makeSocketPair(ours, theirs, true)) {
        entry.refused = std::string("socketpair: ") + ::strerror(errno);
        return;
    }
    pid_t pid = ::fork();
    if (pid == 0) {
        runLanguageServer(theirs.get(), self, language);
    }
    if (pid < 0) {
        entry.refused = std::string("fork: ") + ::strerror(errno);
        return;
    }
    ::setpgid(pid, pid);
    theirs.reset();
    std::vector<bool> ready;
    std::string answer;
    std::vector<FileDescriptor> none;
    if (!platform::waitReadable({ours.get()}, 60000, ready) ||
        !platform::receiveWithFds(ours.get(), answer, none) || answer != "ready") {
        ::kill(pid, SIGKILL);  // reaped with the other children
        entry.refused =
            answer.empty() ? "it ended while starting" : answer.substr(answer.find(' ') + 1);
        if (verbose) {
            std::fprintf(stderr,
                         "robottestingframework-worker: no pre-started %s interpreter (%s): each "
                         "%s test starts its own\n",
                         language.c_str(), entry.refused.c_str(), language.c_str());
        }
        return;
    }
    entry.pid = pid;
    entry.control = std::move(ours);
    if (verbose) {
        std::fprintf(stderr,
                     "robottestingframework-worker: %s tests run in forks of a pre-started "
                     "interpreter (pid %d)\n",
                     language.c_str(), static_cast<int>(pid));
    }
}

int serve(int control, const std::string& language, bool verbose) {
    ::signal(SIGPIPE, SIG_IGN);  // a runner that went away must not kill us before we clean up
    platform::SignalPipe signals({SIGCHLD, SIGTERM, SIGINT, SIGHUP});
    platform::becomeSubreaper();
    // Also covered by the control socket's end of file; this catches a runner whose socket
    // leaked into another process.
    platform::setParentDeathSignal(SIGTERM);

    // The workers, spares and language servers forked from here die with us.
    platform::prepareChildrenParentDeath();

    pid_t self = ::getpid();
    std::map<pid_t, FileDescriptor> statusOf;  // live workers -> where their status goes
    bool running = true;
    std::string packet;
    std::vector<FileDescriptor> fds;
    std::vector<bool> ready;
    std::deque<Spare> spares;  // forked here, oldest first (ready soonest)
    std::map<std::string, LanguageServer> languageServers;
    bool prestart = language.empty() && prestartWanted();
    // The fork server (not a language server) hands spares to the runner ahead of time: a test's
    // request goes from the runner straight to one, so a fork in progress here never holds it
    // up. The runner then claims the spare it used, with the status pipe (SpareNote).
    const bool announce = language.empty();
    std::set<pid_t> announced;            // handed to the runner, not claimed yet
    std::map<pid_t, int> endedUnclaimed;  // how such a one ended (its claim may come after)

    // Hands a request to the spare (forking one now if there is none); tells the runner.
    auto handToSpare = [&](const std::string& request, std::vector<FileDescriptor>& passed) {
        pid_t pid = -1;
        for (int attempt = 0; attempt < 2 && pid < 0; ++attempt) {
            if (spares.empty()) {
                Spare made;
                if (!makeSpare(made, self, language)) {
                    break;
                }
                spares.push_back(std::move(made));
            }
            Spare& spare = spares.front();
            std::vector<int> handed{passed[0].get(), passed[1].get()};
            for (std::size_t i = 3; i < passed.size(); ++i) {
                handed.push_back(passed[i].get());  // a private network's
            }
            if (platform::sendWithFds(spare.link.get(), request, handed)) {
                pid = spare.pid;
            } else {
                ::kill(spare.pid, SIGKILL);  // a broken spare; reaped as an orphan
            }
            spares.pop_front();
        }
        if (pid < 0) {
            sendStatus(passed[2].get(), WireKind::Exited, -1);
        } else {
            sendStatus(passed[2].get(), WireKind::Started, pid);
            statusOf[pid] = std::move(passed[2]);
        }
        passed.clear();
    };
    // A language server that died (killed from outside; its workers went with it): what it had
    // not yet taken takes the plain path, and the next test of the language starts another.
    auto lost = [&](LanguageServer& entry) {
        entry.pid = -1;
        entry.control.reset();
        while (!entry.pending.empty()) {
            handToSpare(entry.pending.front().first, entry.pending.front().second);
            entry.pending.pop_front();
        }
    };

    while (running) {
        // The next worker is forked while the runner is busy with the current one. The spare
        // just handed a request, often woken on this CPU, goes first: the fork can wait.
        while (announce && running && announced.size() < kAnnouncedSpares) {
            ::sched_yield();
            Spare next;
            if (!makeSpare(next, self, language)) {
                break;  // tried again on the next event; a request meanwhile comes here
            }
            if (!platform::sendWithFds(control, encodeSpareNote(SpareNote::Announced, next.pid),
                                       {next.link.get()})) {
                ::kill(next.pid, SIGKILL);  // the runner is gone; reaped below
                break;
            }
            endedUnclaimed.erase(next.pid);  // an earlier process's, with the same pid
            announced.insert(next.pid);
        }
        while (!announce && spares.size() < kLanguageSpares) {
            ::sched_yield();
            Spare made;
            if (!makeSpare(made, self, language)) {
                break;
            }
            spares.push_back(std::move(made));
        }
        std::vector<int> watched{control, signals.fd()};
        std::vector<LanguageServer*> servers;
        for (auto& entry : languageServers) {
            if (entry.second.pid > 0) {
                watched.push_back(entry.second.control.get());
                servers.push_back(&entry.second);
            }
        }
        platform::waitReadable(watched, -1, ready);
        for (std::size_t i = 0; i < servers.size(); ++i) {
            if (!ready[i + 2]) {
                continue;
            }
            // Each answer says the oldest request was taken: its descriptors are the server's
            // now. End of file: it died.
            std::string answer;
            std::vector<FileDescriptor> none;
            if (platform::receiveWithFds(servers[i]->control.get(), answer, none)) {
                if (!servers[i]->pending.empty()) {
                    servers[i]->pending.pop_front();
                }
            } else {
                lost(*servers[i]);
            }
        }
        if (ready[1]) {
            while (int signal = signals.take()) {
                if (signal != SIGCHLD) {
                    running = false;
                }
            }
            int status;
            pid_t pid;
            while ((pid = ::waitpid(-1, &status, WNOHANG)) > 0) {
                auto it = statusOf.find(pid);
                if (it != statusOf.end()) {
                    // What the worker left behind in its group goes with it.
                    platform::signalProcessGroup(pid, SIGKILL);
                    sendStatus(it->second.get(), WireKind::Exited, status);
                    statusOf.erase(it);
                } else if (announced.erase(pid) > 0) {
                    // A worker that ended before its claim came (or a spare that died): said
                    // when it is claimed. A new spare replaces it.
                    platform::signalProcessGroup(pid, SIGKILL);
                    endedUnclaimed[pid] = status;
                }
                // A spare that died waiting (killed from outside).
                spares.erase(std::remove_if(spares.begin(), spares.end(),
                                            [pid](const Spare& s) { return s.pid == pid; }),
                             spares.end());
                for (auto& entry : languageServers) {
                    if (entry.second.pid == pid) {
                        lost(entry.second);
                    }
                }
                // Otherwise an orphan that was re-parented to us: reaped, nothing to say.
            }
        }
        if (ready[0] && running) {
            if (!platform::receiveWithFds(control, packet, fds)) {
                if (errno == EMSGSIZE) {
                    continue;
                }
                break;  // the runner is gone
            }
            SpareNote note;
            std::int64_t claimed;
            if (announce && fds.size() == 1 && decodeSpareNote(packet, note, claimed) &&
                note == SpareNote::Claimed) {
                const auto pid = static_cast<pid_t>(claimed);
                announced.erase(pid);
                sendStatus(fds[0].get(), WireKind::Started, pid);
                auto ended = endedUnclaimed.find(pid);
                if (ended != endedUnclaimed.end()) {
                    sendStatus(fds[0].get(), WireKind::Exited, ended->second);
                    endedUnclaimed.erase(ended);
                } else {
                    statusOf[pid] = std::move(fds[0]);
                }
                fds.clear();
                continue;
            }
            if (!language.empty()) {
                // Taken (see LanguageServer::pending): said before the worker can run, so a
                // test that kills this process is never run again by the fork server.
                platform::sendWithFds(control, "taken", {});
            }
            WorkRequest request;
            if (fds.size() < 3 || fds.size() > 3 + kMaxNetworkFds ||
                !decodeRequest(packet, request)) {
                continue;  // not a request we understand; its descriptors close here
            }
            if (prestart && isScriptLanguage(request.type)) {
                LanguageServer& entry = languageServers[request.type];
                if (entry.pid < 0 && entry.refused.empty()) {
                    startLanguageServer(entry, self, request.type, verbose);
                }
                // It answers the runner itself (Started, Exited) on the status descriptor. The
                // request stays ours until it says it took it: one sent as it dies is not lost.
                std::vector<int> forwarded;
                for (const auto& fd : fds) {
                    forwarded.push_back(fd.get());
                }
                if (entry.pid > 0 &&
                    platform::sendWithFds(entry.control.get(), packet, forwarded)) {
                    entry.pending.emplace_back(packet, std::move(fds));
                    fds.clear();
                    continue;
                }
                if (entry.pid > 0) {
                    lost(entry);
                }
            }
            handToSpare(packet, fds);
        }
    }
    spares.clear();
    killEverything();
    return 0;
}

}  // namespace

int serveForkRequests(int control, bool verbose) {
    // Every worker's stdin: /dev/null, opened once here rather than in each worker. Inherited
    // by the programs the tests run: not close-on-exec.
    int null = ::open("/dev/null", O_RDONLY);
    if (null > 0) {
        ::dup2(null, 0);
        ::close(null);
    }
    // Before the first fork: every worker then starts with the page tables of the code.
    platform::shareCodePagesWithForks();
    return serve(control, {}, verbose);
}

}  // namespace isolation
}  // namespace robottestingframework
