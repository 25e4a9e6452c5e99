// Windows: no fork server. The runner starts each worker itself (worker_process-windows.cpp);
// the ForkServer only knows which program that is.
#include "isolation/fork_server_client.h"

#include <windows.h>

#include <cstdlib>

#include "platform/process.h"

namespace robottestingframework {
namespace isolation {

namespace {

const char* const kWorkerName = "robottestingframework-worker.exe";

bool isFile(const std::string& path) {
    if (path.empty()) {
        return false;
    }
    const DWORD attributes = ::GetFileAttributesA(path.c_str());
    return attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_DIRECTORY) == 0;
}

}  // namespace

ForkServer::~ForkServer() {
    stop();
}

bool ForkServer::start(const std::string& workerPath, std::string& error, bool /*verbose*/) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!isFile(workerPath)) {
        error = "cannot start the worker: no program " + workerPath;
        return false;
    }
    workerPath_ = workerPath;
    pid_ = static_cast<pid_t>(::GetCurrentProcessId());  // the runner starts the workers
    return true;
}

bool ForkServer::spawn(const WorkRequest&, int, int, int, std::string& error, pid_t*,
                       const std::vector<int>&) {
    error = "no fork server on Windows: WorkerProcess starts the worker";
    return false;
}

void ForkServer::stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    pid_ = -1;  // every worker is in a job object its WorkerProcess closes
}

std::string findWorker() {
    if (const char* override = std::getenv("RTF_WORKER")) {
        if (isFile(override)) {
            return override;
        }
    }
    const std::string self = platform::executablePath();
    const std::string dir = self.substr(0, self.find_last_of("/\\"));
    for (const std::string& candidate :
         {dir + "\\" + kWorkerName, dir + "\\..\\libexec\\" + kWorkerName}) {
        if (isFile(candidate)) {
            return candidate;
        }
    }
    return {};
}

}  // namespace isolation
}  // namespace robottestingframework
