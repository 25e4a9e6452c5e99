// rtf-bench-isolation: what process isolation costs per test, beside what a process costs on
// this machine. Prints one row per case: total and per-test time.
//   rtf-bench-isolation [--count N]     (default 1000)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include <robottestingframework/Test.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "runner/execution/in_process_executor.h"
#include "runner/execution/isolated_executor.h"

using namespace robottestingframework;

namespace {

class StandIn : public Test {
public:
    StandIn() : Test("trivial") {}
    void run(TestResult& /*result*/) override {}
    bool succeeded() const override { return true; }
};

double timeIt(int count, const std::function<bool()>& once) {
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        if (!once()) {
            std::fprintf(stderr, "rtf-bench-isolation: iteration %d failed\n", i);
            std::exit(1);
        }
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void row(const char* what, int count, double seconds, const char* note = "") {
    std::printf("%-44s %6d  %8.3f s  %8.3f ms/test  %s\n", what, count, seconds,
                seconds * 1000.0 / count, note);
    std::fflush(stdout);
}

bool forkExecTrue() {
    pid_t pid = ::fork();
    if (pid == 0) {
        char* argv[] = {const_cast<char*>("/bin/true"), nullptr};
        ::execv(argv[0], argv);
        ::_exit(127);
    }
    int status;
    return pid > 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
}

bool bareFork() {
    pid_t pid = ::fork();
    if (pid == 0) {
        ::_exit(0);
    }
    int status;
    return pid > 0 && ::waitpid(pid, &status, 0) == pid;
}

}  // namespace

int main(int argc, char** argv) {
    int count = 1000;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--count") == 0 && i + 1 < argc) {
            count = std::atoi(argv[++i]);
        } else if (std::strcmp(argv[i], "--quick") == 0) {
            count = 100;
        }
    }
    if (count <= 0) {
        std::fprintf(stderr, "usage: %s [--count N | --quick]\n", argv[0]);
        return 2;
    }

    runner::TestSpec spec;
    spec.plugin = spec.path = RTF_BENCH_TRIVIAL_PLUGIN;
    spec.type = "dll";
    StandIn self;
    TestResultCollector collector;
    collector.setKeepEvents(false);
    TestResult result;
    result.addListener(&collector);

    isolation::IsolationOptions options;
    options.workerPath = RTF_BENCH_WORKER;
    isolation::IsolatedExecutor isolated(options);
    std::string error;
    if (!isolated.start(error)) {
        std::fprintf(stderr, "rtf-bench-isolation: %s\n", error.c_str());
        return 1;
    }
    // One test first, so the page cache and the dynamic loader are warm for every case.
    isolated.run(spec, self, result);

    std::printf("%-44s %6s  %10s  %15s\n", "case", "tests", "total", "per test");
    double seconds =
        timeIt(count, [&] { return isolated.run(spec, self, result) == TestStatus::Passed; });
    row("trivial C++ test, isolated (fork server)", count, seconds, "(target: <= 0.5 ms/test)");
    isolated.shutdown();

    runner::InProcessExecutor inProcess;
    seconds =
        timeIt(count, [&] { return inProcess.run(spec, self, result) == TestStatus::Passed; });
    row("trivial C++ test, in process", count, seconds);

    seconds = timeIt(count, forkExecTrue);
    row("fork+exec of /bin/true", count, seconds);
    seconds = timeIt(count, bareFork);
    row("bare fork+_exit", count, seconds);

    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    std::printf("peak memory of this process: %.1f MB\n", usage.ru_maxrss / 1024.0);
    return 0;
}
