// rtf-bench-measure PROGRAM [ARGS...]: runs PROGRAM (stdin, stdout and stderr on /dev/null)
// and prints one line "<wall seconds> <peak KiB> <exit status>" -- its wall time and its own
// peak resident memory (ru_maxrss from wait4).
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
    std::printf("%.6f %ld %d\n", seconds, usage.ru_maxrss, code);
    return 0;
}
