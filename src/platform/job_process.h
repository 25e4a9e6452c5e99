// Windows: a program started in a job object of its own, so that everything it starts ends
// with it (kill on job close). The worker of each isolated test and each exec test's program
// run this way. There is no fork: what the child gets is named when it starts.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace robottestingframework {
namespace platform {

struct JobProcessOptions {
    std::vector<std::string> argv;  // argv[0] is the program; quoted into one command line
    std::string workingDirectory;   // the child's; ours when empty
    // Our descriptors that become the child's standard handles; -1: the null device.
    int stdinFd = -1;
    int stdoutFd = -1;
    int stderrFd = -1;
    // Our descriptors whose handles the child inherits besides those (it is told their values
    // on its command line: handleValue()).
    std::vector<int> inheritedFds;
    // Set in (or added to) the child's environment, which is ours otherwise.
    std::vector<std::pair<std::string, std::string>> environment;
};

class JobProcess {
public:
    JobProcess() = default;
    // Closes the job: the child and everything it started end now (if they have not).
    ~JobProcess();
    JobProcess(const JobProcess&) = delete;
    JobProcess& operator=(const JobProcess&) = delete;

    // Starts the child suspended, puts it in a new job that kills on close, then lets it run.
    // False with `error` (naming the program and the system's reason) when it cannot start.
    bool start(const JobProcessOptions& options, std::string& error);
    unsigned long pid() const { return pid_; }
    // Waits up to `timeoutMs` (-1: forever) for the child itself to end.
    bool ended(int timeoutMs = 0);
    // Its exit code once ended(): for a crash, the exception code (0xC0000005).
    unsigned long exitCode() const { return exitCode_; }
    // Ends every process of the job (the child and its descendants) with `code`.
    void kill(unsigned int code = 1);

private:
    void* process_ = nullptr;
    void* job_ = nullptr;
    unsigned long pid_ = 0;
    unsigned long exitCode_ = 0;
    bool ended_ = false;
};

// The text of the Windows handle behind our descriptor `fd`, for a child's command line.
std::string handleValue(int fd);
// The descriptor for a handle value a parent gave on our command line; -1 when it is not one.
int descriptorOfHandle(const std::string& value);
// One argument quoted as CommandLineToArgvW and the C run-time read it back.
std::string quoteArgument(const std::string& argument);

}  // namespace platform
}  // namespace robottestingframework
