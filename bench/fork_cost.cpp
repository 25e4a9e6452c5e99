// rtf-bench-fork COUNT [JOBS]: the floor of process isolation on this machine. JOBS processes
// (default 1), each forking COUNT/JOBS children that only _exit(0), each child waited for with
// waitpid before the next fork; prints one line "<wall seconds> <forks>": the wall time of the
// whole, from the first fork to the last wait. Divided by the forks, it is the cost of one
// bare fork+_exit+waitpid at JOBS at a time, what bench/perf_bench.py states the isolated
// runner's cost per test against (`-j 2` beside JOBS 2).
//
// The forking processes are small (this program, about 1 MiB): a fork's cost grows with the
// parent's mapped memory, so this is the least a fork can cost here, not what it costs a runner.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace {

// COUNT bare forks, one after the other; false when one failed.
bool forkLoop(long count) {
    for (long i = 0; i < count; ++i) {
        const pid_t pid = ::fork();
        if (pid < 0) {
            return false;
        }
        if (pid == 0) {
            ::_exit(0);
        }
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0) {
            if (errno != EINTR) {
                return false;
            }
        }
    }
    return true;
}

double now() {
    timespec t{};
    ::clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

}  // namespace

int main(int argc, char** argv) {
    const long count = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 0;
    const long jobs = argc > 2 ? std::strtol(argv[2], nullptr, 10) : 1;
    if (argc < 2 || argc > 3 || count < 1 || jobs < 1 || jobs > count) {
        std::fprintf(stderr, "usage: %s COUNT [JOBS]  (1 <= JOBS <= COUNT)\n", argv[0]);
        return 2;
    }
    const double start = now();
    // JOBS forking processes, each with its share of the forks (the first takes what is left).
    for (long job = 0; job < jobs; ++job) {
        const long share = count / jobs + (job == 0 ? count % jobs : 0);
        const pid_t pid = ::fork();
        if (pid < 0) {
            std::perror("rtf-bench-fork: fork");
            return 1;
        }
        if (pid == 0) {
            ::_exit(forkLoop(share) ? 0 : 1);
        }
    }
    bool ok = true;
    for (long job = 0; job < jobs; ++job) {
        int status = 0;
        if (::wait(&status) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            ok = false;
        }
    }
    if (!ok) {
        std::fprintf(stderr, "rtf-bench-fork: a fork or a wait failed\n");
        return 1;
    }
    std::printf("%.6f %ld\n", now() - start, count);
    return 0;
}
