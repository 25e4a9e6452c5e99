// rtf-bench-measure PROGRAM [ARGS...]: runs PROGRAM (stdin, stdout and stderr on /dev/null)
// and prints one line "<wall seconds> <peak KiB> <exit status> <CPU seconds>" -- its wall time,
// its own peak resident memory (ru_maxrss from wait4) and the processor time it and the
// children it waited for used (user + system, from wait4): on a shared machine the CPU time is
// the steadier figure, the wall time the one a user waits.
//
// Why a program of its own: the kernel starts a process's ru_maxrss at the resident size of
// the process that forked it (a fork copies the parent's page counts; a vfork or posix_spawn
// shares its memory until exec). Spawned from Python (bench/perf_bench.py), every figure would
// be at least Python's own 10-16 MiB; spawned from this small program, the floor is its ~1 MiB.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <ctime>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s PROGRAM [ARGS...]\n", argv[0]);
        return 2;
    }
    timespec start{};
    ::clock_gettime(CLOCK_MONOTONIC, &start);
    const pid_t pid = ::fork();
    if (pid < 0) {
        std::perror("rtf-bench-measure: fork");
        return 1;
    }
    if (pid == 0) {
        const int null = ::open("/dev/null", O_RDWR);
        if (null >= 0) {
            ::dup2(null, 0);
            ::dup2(null, 1);
            ::dup2(null, 2);
        }
        ::execvp(argv[1], argv + 1);
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0) {
        if (errno != EINTR) {
            std::perror("rtf-bench-measure: wait4");
            return 1;
        }
    }
    timespec end{};
    ::clock_gettime(CLOCK_MONOTONIC, &end);
    const double seconds =
        static_cast<double>(end.tv_sec - start.tv_sec) + (end.tv_nsec - start.tv_nsec) * 1e-9;
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const auto cpu = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
    };
    std::printf("%.6f %ld %d %.6f\n", seconds, usage.ru_maxrss, code,
                cpu(usage.ru_utime) + cpu(usage.ru_stime));
    return 0;
}
