// rtf-bench: runs the real robottestingframework-testrunner on generated suites and prints, per
// case, the wall time, the time per test, the peak memory of the runner process (ru_maxrss from
// wait4) and the memory per test, in process (--isolation none) and isolated (--isolation
// process); then what a process costs on this machine (fork+exec of a trivial program, a bare
// fork+_exit), the floor isolation is measured against. A benchmark, not a test: it never fails
// on a slow number.
//
//   rtf-bench [--quick] [--filter TEXT] [--runner PATH] [--plugin PATH] [--workdir DIR]
//
// Each row is the fastest of 3 runs, after a warm-up run. Per-test numbers are net of the
// case's 1-test run (start-up and loading are not counted).
// Adding a case: write `Measurement myCase(Bench&, std::size_t tests)` below and add a row
// to cases() -- nothing else changes.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/text_safety.h"

extern char** environ;

namespace {

struct Measurement {
    bool ok = false;
    std::string error;  // why the run did not complete, when !ok
    double seconds = 0;
    long peakKiB = 0;
};

// What every case needs: where things are, and a way to run the runner and measure it.
class Bench {
public:
    std::string runner = RTF_BENCH_RUNNER;
    std::string trivialPlugin = RTF_BENCH_TRIVIAL_PLUGIN;
    std::string workdir = RTF_BENCH_WORKDIR;
    std::vector<std::string> runnerOptions;  // given to every run
    bool hasIsolation = false;               // the runner has --isolation
    double timeoutSeconds = 600;

    // Writes <workdir>/<name>.xml holding one suite with `tests` (already XML elements).
    std::string writeSuite(const std::string& name, const std::vector<std::string>& tests);
    // Runs the runner with `args` (stdout to /dev/null, stderr to <workdir>/<label>.log).
    Measurement run(const std::string& label, const std::vector<std::string>& args);
    // True when the runner's --help mentions `option`.
    bool runnerHas(const std::string& option);
};

// Suite files hold names and paths as markup: the reporters' escaper (src/reporters).
std::string xmlEscape(const std::string& text) {
    return robottestingframework::reporters::escapeMarkup(
        text, robottestingframework::reporters::Markup::Quoted);
}

std::string Bench::writeSuite(const std::string& name, const std::vector<std::string>& tests) {
    const std::string path = workdir + "/" + name + ".xml";
    std::ofstream out(path);
    out << "<suite name=\"" << xmlEscape(name) << "\">\n";
    for (const auto& test : tests)
        out << "  " << test << "\n";
    out << "</suite>\n";
    return path;
}

Measurement Bench::run(const std::string& label, const std::vector<std::string>& args) {
    Measurement m;
    std::vector<std::string> words{runner};
    words.insert(words.end(), runnerOptions.begin(), runnerOptions.end());
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& word : words)
        argv.push_back(word.data());
    argv.push_back(nullptr);
    const std::string log = workdir + "/" + label + ".log";

    // posix_spawn (vfork-like) so the child's peak memory is the runner's, not a copy of ours.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addchdir_np(&actions, workdir.c_str());

    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int error = posix_spawn(&pid, runner.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) {
        m.error = "cannot start " + runner + ": " + std::strerror(error);
        return m;
    }

    // A watchdog ends a runner that hangs, so the bench itself is bounded.
    std::mutex mutex;
    std::condition_variable done;
    bool finished = false;
    bool killed = false;
    std::thread watchdog([&] {
        std::unique_lock<std::mutex> lock(mutex);
        if (!done.wait_for(lock, std::chrono::duration<double>(timeoutSeconds),
                           [&] { return finished; })) {
            killed = true;
            kill(pid, SIGKILL);
        }
    });

    int status = 0;
    struct rusage usage {};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    const auto end = std::chrono::steady_clock::now();
    {
        std::lock_guard<std::mutex> lock(mutex);
        finished = true;
    }
    done.notify_one();
    watchdog.join();

    m.seconds = std::chrono::duration<double>(end - start).count();
    m.peakKiB = usage.ru_maxrss;  // KiB on Linux
    if (killed)
        m.error = "timed out, see " + log;
    else if (WIFSIGNALED(status))
        m.error = std::string("runner died of ") + strsignal(WTERMSIG(status)) + ", see " + log;
    else if (WEXITSTATUS(status) != 0)
        m.error = "runner exited " + std::to_string(WEXITSTATUS(status)) + ", see " + log;
    else
        m.ok = true;
    return m;
}

bool Bench::runnerHas(const std::string& option) {
    const std::string command = "'" + runner + "' --help 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
        return false;
    std::string text;
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
        text.append(buffer, n);
    pclose(pipe);
    return text.find(option) != std::string::npos;
}

// ---- cases: one function each ------------------------------------------------------------

// `tests` trivial C++ plug-in tests in one suite, run with `--isolation mode`.
Measurement cppTests(Bench& bench, std::size_t tests, const char* mode) {
    const std::string name = std::string("cpp-") + mode + "-" + std::to_string(tests);
    const std::vector<std::string> entries(
        tests, "<test type=\"dll\">" + xmlEscape(bench.trivialPlugin) + "</test>");
    std::vector<std::string> args{"--suite", bench.writeSuite(name, entries), "--no-output"};
    if (bench.hasIsolation) {
        args.insert(args.end(), {"--isolation", mode});
    }
    return bench.run(name, args);
}

// In the runner's process.
Measurement cppInProcess(Bench& bench, std::size_t tests) {
    return cppTests(bench, tests, "none");
}

// Each test in a worker process forked by the fork server.
Measurement cppIsolated(Bench& bench, std::size_t tests) {
    if (!bench.hasIsolation) {
        Measurement m;
        m.error = "this runner has no --isolation";
        return m;
    }
    return cppTests(bench, tests, "process");
}

// Every figure is the best of this many runs (the one least disturbed by the machine).
constexpr int kRepeats = 3;

std::string formatTime(double seconds);

// Targets to print beside a case's numbers; 0 when there is none.
struct Targets {
    double microsPerTest = 0;
    double kibPerTest = 0;
    double peakMiB = 0;  // for the largest run (10 000 tests)
};

struct Case {
    const char* name;
    Measurement (*measure)(Bench&, std::size_t);
    std::vector<std::size_t> sizes;  // the first is the baseline (1 test)
    std::vector<std::size_t> quickSizes;
    Targets targets;
};

std::vector<Case> cases() {
    return {
        {"C++ in-process", cppInProcess, {1, 1000, 10000}, {1, 10, 100}, {10, 2, 20}},
        {"C++ isolated", cppIsolated, {1, 1000, 10000}, {1, 10}, {500, 2, 20}},
    };
}

// ---- what a process costs on this machine ------------------------------------------------

// Runs `once` `count` times; the seconds it took, or -1 when an iteration failed.
template <typename Once>
double timeEach(int count, Once once) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        if (!once()) {
            return -1;
        }
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool forkExecTrivial() {
    const pid_t pid = ::fork();
    if (pid == 0) {
        char* argv[] = {const_cast<char*>("/bin/true"), nullptr};
        ::execv(argv[0], argv);
        ::_exit(127);
    }
    int status = 0;
    return pid > 0 && ::waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
}

bool bareFork() {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::_exit(0);
    }
    int status = 0;
    return pid > 0 && ::waitpid(pid, &status, 0) == pid;
}

// Prints the cost of `count` fork+exec and bare forks; false when one failed.
bool printProcessCosts(int count) {
    std::printf("\n%-22s %7s %10s %12s\n", "process cost", "times", "wall", "per time");
    std::printf("%s\n", std::string(100, '-').c_str());
    bool ok = true;
    const struct {
        const char* name;
        bool (*once)();
    } rows[] = {{"fork+exec /bin/true", forkExecTrivial}, {"bare fork+_exit", bareFork}};
    for (const auto& row : rows) {
        double best = -1;
        for (int i = 0; i < kRepeats; ++i) {
            const double seconds = timeEach(count, row.once);
            if (seconds < 0) {
                best = -1;
                break;
            }
            if (best < 0 || seconds < best) {
                best = seconds;
            }
        }
        if (best < 0) {
            std::printf("%-22s %7d  FAILED\n", row.name, count);
            ok = false;
            continue;
        }
        std::printf("%-22s %7d %10s %9.1f us\n", row.name, count, formatTime(best).c_str(),
                    best / count * 1e6);
        std::fflush(stdout);
    }
    return ok;
}

// ---- the table ---------------------------------------------------------------------------

std::string formatTime(double seconds) {
    char text[32];
    if (seconds >= 1)
        std::snprintf(text, sizeof text, "%.2f s", seconds);
    else if (seconds >= 1e-3)
        std::snprintf(text, sizeof text, "%.1f ms", seconds * 1e3);
    else
        std::snprintf(text, sizeof text, "%.1f us", seconds * 1e6);
    return text;
}

void printHeader() {
    std::printf("%-22s %7s %10s %12s %10s %12s  %s\n", "case", "tests", "wall", "per test",
                "peak RSS", "RSS/test", "vs targets");
    std::printf("%s\n", std::string(100, '-').c_str());
}

void printRow(const Case& c, std::size_t tests, const Measurement& m, const Measurement& base,
              bool largest, bool judged) {
    if (!m.ok) {
        std::printf("%-22s %7zu  FAILED: %s\n", c.name, tests, m.error.c_str());
        return;
    }
    char peak[32];
    std::snprintf(peak, sizeof peak, "%.1f MiB", m.peakKiB / 1024.0);
    if (tests <= 1) {
        std::printf("%-22s %7zu %10s %12s %10s %12s  %s\n", c.name, tests,
                    formatTime(m.seconds).c_str(), "(baseline)", peak, "(baseline)", "");
        return;
    }
    const double netTests = static_cast<double>(tests - 1);
    const double perTest = (m.seconds - base.seconds) / netTests;
    const double kibPerTest = static_cast<double>(m.peakKiB - base.peakKiB) / netTests;
    char perTestText[32];
    std::snprintf(perTestText, sizeof perTestText, "%.1f us", perTest * 1e6);
    char kibText[32];
    std::snprintf(kibText, sizeof kibText, "%.2f KiB", kibPerTest);

    std::string verdict = judged ? "" : "(--quick: not judged)";
    auto judge = [&](const char* what, bool within, double target, const char* unit) {
        char text[64];
        std::snprintf(text, sizeof text, "%s%s %s<= %g %s", verdict.empty() ? "" : ", ", what,
                      within ? "" : "OVER ", target, unit);
        verdict += text;
    };
    if (judged && c.targets.microsPerTest > 0)
        judge("time", perTest * 1e6 <= c.targets.microsPerTest, c.targets.microsPerTest, "us");
    if (judged && c.targets.kibPerTest > 0)
        judge("mem", kibPerTest <= c.targets.kibPerTest, c.targets.kibPerTest, "KiB");
    if (judged && largest && tests >= 10000 && c.targets.peakMiB > 0)
        judge("peak", m.peakKiB / 1024.0 <= c.targets.peakMiB, c.targets.peakMiB, "MB");
    std::printf("%-22s %7zu %10s %12s %10s %12s  %s\n", c.name, tests,
                formatTime(m.seconds).c_str(), perTestText, peak, kibText, verdict.c_str());
}

// The fastest of `repeats` runs (the one least disturbed by the rest of the machine).

Measurement best(const Case& c, Bench& bench, std::size_t tests, int repeats) {
    Measurement fastest;
    for (int i = 0; i < repeats; ++i) {
        Measurement m = c.measure(bench, tests);
        if (!m.ok)
            return m;
        if (!fastest.ok || m.seconds < fastest.seconds)
            fastest = m;
    }
    return fastest;
}

int usage(const char* program) {
    std::fprintf(stderr,
                 "usage: %s [--quick] [--filter TEXT] [--runner PATH] [--plugin PATH] "
                 "[--workdir DIR]\n",
                 program);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Bench bench;
    bool quick = false;
    std::string filter;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--quick")
            quick = true;
        else if (arg == "--filter" && hasValue)
            filter = argv[++i];
        else if (arg == "--runner" && hasValue)
            bench.runner = argv[++i];
        else if (arg == "--plugin" && hasValue)
            bench.trivialPlugin = argv[++i];
        else if (arg == "--workdir" && hasValue)
            bench.workdir = argv[++i];
        else
            return usage(argv[0]);
    }
    if (std::system(("mkdir -p '" + bench.workdir + "'").c_str()) != 0) {
        std::fprintf(stderr, "cannot create %s\n", bench.workdir.c_str());
        return 1;
    }
    // Each case names its mode; a runner from before isolation runs everything in process.
    bench.hasIsolation = bench.runnerHas("--isolation");

    std::string options;
    for (const auto& option : bench.runnerOptions)
        options += " " + option;
    std::printf("rtf-bench%s: %s%s\n", quick ? " --quick" : "", bench.runner.c_str(),
                options.c_str());
    std::printf(
        "targets: <= 10 us/test in process, <= 500 us/test isolated, <= 2 KiB/test, <= 20 MB "
        "peak for 10 000 tests\n\n");
    printHeader();

    bool allOk = true;
    for (const Case& c : cases()) {
        if (!filter.empty() && std::string(c.name).find(filter) == std::string::npos)
            continue;
        const auto& sizes = quick ? c.quickSizes : c.sizes;
        c.measure(bench, sizes.front());  // warm-up: caches, page cache, first dlopen
        Measurement base;
        for (std::size_t i = 0; i < sizes.size(); ++i) {
            const Measurement m = best(c, bench, sizes[i], kRepeats);
            if (i == 0)
                base = m;
            printRow(c, sizes[i], m, base, i + 1 == sizes.size(), !quick);
            std::fflush(stdout);
            allOk = allOk && m.ok;
        }
    }
    if (filter.empty() || std::string("process cost").find(filter) != std::string::npos) {
        allOk = printProcessCosts(quick ? 100 : 1000) && allOk;
    }
    return allOk ? 0 : 1;
}
