// --watch on POSIX systems (watch_command.h): children started with platform::spawnProcess,
// files watched with platform::FileWatch (inotify on Linux, polling elsewhere).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "platform/file_watch.h"
#include "platform/process.h"
#include "runner/cli/exit_status.h"
#include "runner/cli/program_name.h"
#include "runner/cli/run_inputs.h"
#include "runner/cli/watch_command.h"

namespace robottestingframework {
namespace runner {

namespace {

volatile std::sig_atomic_t stopSignal = 0;

extern "C" void onStop(int signal) {
    stopSignal = signal;
}

// Runs the child runner with `words`; its status (128 + a signal that ended it).
int runChild(const std::vector<std::string>& words) {
    platform::SpawnOptions spawn;
    spawn.argv = words;
    spawn.program = platform::executablePath();
    // In our process group: Ctrl-C reaches it as it reaches us, and it stops as a run does.
    spawn.newProcessGroup = false;
    spawn.nullStdin = false;
    spawn.fds = {{0, 0}, {1, 1}, {2, 2}};
    spawn.parentDeathSignal = SIGTERM;
    std::string error;
    const pid_t pid = platform::spawnProcess(spawn, error);
    if (pid < 0) {
        std::fprintf(stderr, "%s: --watch: cannot start the run: %s\n", programName, error.c_str());
        return configurationError;
    }
    // Ctrl-C reaches the run itself (our process group): it stops as a run does, and we wait
    // for it. A signal sent to us alone lets the run end first.
    int status = 0;
    while (::waitpid(pid, &status, 0) != pid) {
        if (errno != EINTR) {
            return configurationError;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

int watchCommand(int argc, char** argv, Options& options) {
    struct sigaction action {};
    action.sa_handler = onStop;  // no SA_RESTART: waitpid and poll return to see it
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);

    platform::FileWatch watch;
    std::string error;
    if (!watch.watch({}, error)) {
        std::fprintf(stderr, "%s: %s\n", programName, error.c_str());
        return configurationError;
    }
    // The last run's JUnit report, for the failed tests first: in a folder of our own, removed
    // when the watch ends.
    std::string folder;
    if (!options.noOutput) {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern =
            std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/rtf-watch-XXXXXX";
        if (::mkdtemp(pattern.data()) != nullptr) {
            folder = pattern;
        }
    }
    const std::string report = folder.empty() ? "" : folder + "/last.xml";
    const std::vector<std::string> words = watchedRunArguments(argc, argv, report);
    int status = 0;
    bool failed = false;
    for (unsigned int round = 1; stopSignal == 0; ++round) {
        if (round > 1) {
            std::printf("\n%s --watch: run %u\n", programName, round);
            std::fflush(stdout);
        }
        if (failed && !report.empty()) {
            // The tests that failed, alone: the answer to the change comes first.
            std::vector<std::string> first = watchedRunArguments(argc, argv, "");
            first.insert(first.end(),
                         {"--rerun-failed", report, "--output", "junit:" + report + ".first"});
            std::printf("%s --watch: the tests that failed last time first\n", programName);
            std::fflush(stdout);
            status = runChild(first);
            std::error_code ignored;
            std::filesystem::remove(report + ".first", ignored);
        }
        if (stopSignal == 0 && (!failed || status == 0)) {
            status = runChild(words);
            failed = status == somethingFailed;
        }
        if (stopSignal != 0) {
            break;
        }
        // What to watch, read again: an edit may have added a test or a suite.
        // (Only for the files: the runs take the command line, not `options`.)
        RunInputs inputs;
        std::vector<std::string> files;
        if (readRunInputs(options, inputs)) {
            files = watchedFiles(inputs.suites);
        }
        // The suites of the command line too (one that does not parse is read again when it
        // changes), once: the plan names them by their absolute path.
        for (const auto& suite : options.suites) {
            std::error_code ignored;
            const std::string absolute =
                std::filesystem::absolute(suite, ignored).lexically_normal().string();
            if (std::find(files.begin(), files.end(), absolute) == files.end() &&
                std::find(files.begin(), files.end(), suite) == files.end()) {
                files.push_back(suite);
            }
        }
        watch.watch(files, error);
        std::printf("%s --watch: waiting for a change of %zu files (Ctrl-C stops)\n", programName,
                    files.size());
        std::fflush(stdout);
        std::string changed;
        while (stopSignal == 0 && !watch.waitForChange(200, changed)) {
        }
        if (stopSignal == 0) {
            std::printf("%s --watch: %s changed\n", programName, changed.c_str());
            std::fflush(stdout);
            // Editors write in steps: let the burst end.
            std::string more;
            while (watch.waitForChange(300, more)) {
            }
        }
    }
    if (!folder.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
    }
    return status;
}

}  // namespace runner
}  // namespace robottestingframework
