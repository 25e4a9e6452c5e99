#include "isolation/fork_server_client.h"

#include <errno.h>
#include <signal.h>
#include <string.h>
#include <unistd.h>

#include <cstdlib>

#include "languages/script_module_loading.h"
#include "platform/fd_passing.h"
#include "platform/process.h"
#include "platform/process_tree.h"

#ifndef RTF_WORKER_INSTALL_PATH
#define RTF_WORKER_INSTALL_PATH ""
#endif

namespace robottestingframework {
namespace isolation {

namespace {

const char* const kWorkerName = "robottestingframework-worker";

// How long spawn() waits for the server to hand over a spare before it asks the server itself:
// a fork takes a fraction of a millisecond; this is for a machine that is swapping.
constexpr int kSpareWaitMs = 10000;

bool isExecutable(const std::string& path) {
    return !path.empty() && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

ForkServer::~ForkServer() {
    stop();
}

bool ForkServer::start(const std::string& workerPath, std::string& error, bool verbose) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pid_ > 0) {
        return true;
    }
    platform::FileDescriptor ours, theirs;
    if (!platform::makeSocketPair(ours, theirs, true)) {
        error = std::string("socketpair: ") + ::strerror(errno);
        return false;
    }
    platform::SpawnOptions options;
    options.argv = {workerPath, "--fork-server", "3"};
    if (verbose) {
        options.argv.push_back("--verbose");
    }
    options.fds = {{3, theirs.get()}};
    if (std::getenv("LD_BIND_NOW") == nullptr) {
        // Every symbol bound once, at the server's start: otherwise each worker, a fork,
        // resolves again the functions it calls first (about 30 page faults a test).
        options.environment = {{"LD_BIND_NOW", "1"}, {kBindNowMark, "1"}};
    }
    options.newProcessGroup = true;  // Ctrl-C on the terminal is the runner's to handle
    options.parentDeathSignal = SIGTERM;
    pid_ = platform::spawnProcess(options, error);
    if (pid_ < 0) {
        error = "cannot start the worker: " + error;
        return false;
    }
    control_ = std::move(ours);
    return true;
}

bool ForkServer::takeSpare(Spare& spare) {
    if (spares_.empty()) {
        std::vector<bool> ready;
        std::string note;
        std::vector<platform::FileDescriptor> fds;
        SpareNote kind;
        std::int64_t pid;
        if (!platform::waitReadable({control_.get()}, kSpareWaitMs, ready) ||
            !platform::receiveWithFds(control_.get(), note, fds) || fds.size() != 1 ||
            !decodeSpareNote(note, kind, pid) || kind != SpareNote::Announced) {
            return false;
        }
        spares_.push_back(Spare{static_cast<pid_t>(pid), std::move(fds[0])});
    }
    spare = std::move(spares_.front());
    spares_.erase(spares_.begin());
    return true;
}

bool ForkServer::spawn(const WorkRequest& request, int channel, int output, int status,
                       std::string& error, pid_t* pid, const std::vector<int>& network) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pid_ <= 0) {
        error = "the fork server is not running";
        return false;
    }
    const std::string packet = encodeRequest(request);
    Spare spare;
    while (!languages::isScriptLanguage(request.type) && takeSpare(spare)) {
        std::vector<int> fds{channel, output};
        fds.insert(fds.end(), network.begin(), network.end());
        if (!platform::sendWithFds(spare.link.get(), packet, fds)) {
            continue;  // it died waiting: the server reaps it and hands over another
        }
        if (!platform::sendWithFds(control_.get(), encodeSpareNote(SpareNote::Claimed, spare.pid),
                                   {status})) {
            error = std::string("cannot reach the fork server: ") + ::strerror(errno);
            return false;
        }
        if (pid != nullptr) {
            *pid = spare.pid;
        }
        return true;
    }
    // A script, or no spare came: the server starts the worker.
    std::vector<int> fds{channel, output, status};
    fds.insert(fds.end(), network.begin(), network.end());
    if (!platform::sendWithFds(control_.get(), packet, fds)) {
        error = std::string("cannot reach the fork server: ") + ::strerror(errno);
        return false;
    }
    return true;
}

void ForkServer::stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pid_ <= 0) {
        return;
    }
    spares_.clear();
    control_.reset();  // end of file: the server kills everything and exits
    int status;
    if (!platform::waitChild(pid_, 5.0, status)) {
        platform::killDescendants(pid_);
        ::kill(pid_, SIGKILL);
        platform::waitChild(pid_, -1, status);
    }
    pid_ = -1;
}

std::string findWorker() {
    if (const char* override = std::getenv("RTF_WORKER")) {
        if (isExecutable(override)) {
            return override;
        }
    }
    std::string self = platform::executablePath();
    std::string dir = self.substr(0, self.find_last_of('/'));
    for (const std::string& candidate :
         {dir + "/" + kWorkerName, dir + "/../libexec/" + kWorkerName,
          std::string(RTF_WORKER_INSTALL_PATH)}) {
        if (isExecutable(candidate)) {
            return candidate;
        }
    }
    return {};
}

}  // namespace isolation
}  // namespace robottestingframework
