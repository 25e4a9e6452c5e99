// robottestingframework-testrunner: options → suites → run → outputs, and the exit status.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/JUnitOutputter.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TextOutputter.h>

#include "in_process_executor.h"
#include "isolated_executor.h"
#include "options.h"
#include "output_capture.h"
#include "output_paths.h"
#include "process.h"
#include "process_tree.h"
#include "run_gate.h"
#include "run_plan.h"
#include "signal_pipe.h"
#include "test_sources.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

const char* const program = "robottestingframework-testrunner";

// Exit statuses (SPEC 3.1).
const int allPassed = 0;
const int somethingFailed = 1;
const int configurationError = 2;
// Interrupted: 128 + the signal, as shells report it (130 for Ctrl-C, 143 for SIGTERM).
int interruptedBy(int signal) {
    return 128 + signal;
}

// Turns Ctrl-C and SIGTERM into an orderly stop: the first one interrupts the run (the running
// test is stopped, tear-downs run, outputs are written); a second one ends the runner at once.
class InterruptWatcher {
public:
    // `console`: where to say so (stderr is captured while tests run). `quit`: what to do
    // before quitting at once (write what is known).
    InterruptWatcher(RunPlan& plan, std::FILE* console, std::function<void()> quit)
        : signals_({SIGINT, SIGTERM}),
          quit_(std::move(quit)),
          thread_([this, &plan, console] { watch(plan, console); }) {}
    ~InterruptWatcher() {
        done_ = true;
        signals_.wake();  // or the run would end up to one poll period (200 ms) late
        thread_.join();
    }
    // The first signal received, 0 when none.
    int received() const { return received_; }

private:
    void watch(RunPlan& plan, std::FILE* console) {
        while (!done_) {
            int signal = signals_.wait(200);
            if (signal != 0 && received_ == 0) {
                received_ = signal;
                std::fprintf(console,
                             "\n%s: interrupted; stopping the running test and tearing down "
                             "(again to quit at once)\n",
                             program);
                std::fflush(console);
            } else if (signal != 0) {
                std::fprintf(console, "%s: interrupted again; writing what is known and quitting\n",
                             program);
                std::fflush(console);
                // Whatever the run started goes with us: the fork server kills its workers when
                // we are gone; what the runner itself started (in-process tests) is killed here.
                platform::killDescendants(::getpid());
                quit_();
                ::_exit(interruptedBy(received_));
            }
            if (received_ != 0) {
                // Again and again: an interruption that arrives while a test is being started
                // could be missed by it; the runner starts no new test once interrupted.
                plan.runner().interrupt();
                plan.interruptFixtures();
            }
        }
    }

    platform::SignalPipe signals_;
    std::function<void()> quit_;
    std::atomic<bool> done_{false};
    std::atomic<int> received_{0};
    std::thread thread_;
};

bool wantColours() {
    const char* term = std::getenv("TERM");
    return ::isatty(1) && std::getenv("NO_COLOR") == nullptr &&
           !(term != nullptr && std::string(term) == "dumb");
}

// Writes every requested output; false when one could not be written (each is reported on
// `console`).
bool writeOutputs(const Options& options, TestResultCollector& collector, std::FILE* console) {
    bool ok = true;
    for (const auto& output : options.outputs) {
        TestMessage error;
        bool written = false;
        if (output.type == "junit") {
            written = JUnitOutputter(collector, options.verbose).write(output.file, &error);
        } else {
            written = TextOutputter(collector, options.verbose)
                          .write(output.file, !options.noSummary, &error);
        }
        if (!written) {
            std::fprintf(console, "%s: cannot write the %s output %s: %s\n", program,
                         output.type.c_str(), output.file.c_str(), error.toString().c_str());
            ok = false;
        }
    }
    return ok;
}

bool anythingFailed(const TestResultCollector& collector) {
    if (collector.failedCount() > 0) {
        return true;
    }
    for (const auto& suite : collector.suites()) {
        if (suite.fixtureFailed || !suite.succeeded()) {
            return true;
        }
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    ParseResult parsed = parseOptions(argc, argv, options);
    if (parsed.outcome == ParseResult::Outcome::Exit) {
        std::fputs(parsed.text.c_str(), parsed.status == 0 ? stdout : stderr);
        return parsed.status;
    }
    if (options.webReporter) {
        std::fprintf(stderr,
                     "%s: warning: the web reporter is not built yet; --web-reporter and "
                     "--web-port are ignored\n",
                     program);
    }

    std::vector<std::string> warnings;
    std::vector<SuiteSpec> suites;
    try {
        suites = readSources(options, warnings);
    } catch (const std::exception& e) {
        for (const auto& warning : warnings) {
            std::fprintf(stderr, "%s\n", warning.c_str());
        }
        std::fprintf(stderr, "%s: %s\n", program, e.what());
        return configurationError;
    }
    for (const auto& warning : warnings) {
        std::fprintf(stderr, "%s\n", warning.c_str());
    }
    const Overrides overrides{options.param, options.environment, options.repetition,
                              options.timeout, options.variables};
    for (const auto& warning : unreadVariables(suites, overrides)) {
        std::fprintf(stderr, "%s: %s\n", program, warning.c_str());
    }
    for (const std::string& problem : {findUnknownDependency(suites), findDependencyCycle(suites),
                                       checkOutputPaths(options.outputs, suites)}) {
        if (!problem.empty()) {
            std::fprintf(stderr, "%s: %s\n", program, problem.c_str());
            return configurationError;
        }
    }

    // The fork server is started here, on the main thread, which lives for the whole run: the
    // server's parent-death signal is tied to the thread that started it.
    std::unique_ptr<TestExecutor> executor;
    if (options.isolation == "none") {
        std::fprintf(stderr,
                     "%s: warning: --isolation none: a test that crashes, exits or blocks in "
                     "native code ends or holds the run; a timeout can only ask it to stop\n",
                     program);
        // Daemons the tests leave (out of their process groups) are adopted, and end with us.
        platform::becomeSubreaper();
        executor = std::make_unique<InProcessExecutor>();
    } else {
        isolation::IsolationOptions isolationOptions;
        isolationOptions.verbose = options.verbose;
        auto isolated = std::make_unique<isolation::IsolatedExecutor>(isolationOptions);
        std::string error;
        if (!isolated->start(error)) {
            std::fprintf(stderr, "%s: cannot start process isolation: %s\n", program,
                         error.c_str());
            return configurationError;
        }
        executor = std::move(isolated);
    }
    RunPlan plan(*executor);
    plan.gate().setFailFast(options.failFast);
    for (auto& suite : suites) {
        applyOverrides(suite, overrides);
        plan.addSuite(std::move(suite));
    }
    suites.clear();

    const bool colours = wantColours();
    TestResult result;
    OutputCapture capture;
    OutputCaptureListener captureListener(capture, result);
    std::string captureError;
    if (capture.start(captureError)) {
        result.addListener(&captureListener);  // first: output arrives before endTest
    } else {
        std::fprintf(stderr, "%s: warning: %s; the tests' output goes to the console\n", program,
                     captureError.c_str());
    }

    ConsoleListener console(options.verbose);
    console.setStream(capture.console());
    console.setColors(colours);
    console.showChecks(options.detail);
    console.showSummary(!options.noSummary);
    if (!options.verbose) {
        console.hideUncriticalMessages();
    }
    TestResultCollector collector;
    // The outputs read the per-test records only, and show checks only when verbose.
    collector.setKeepEventLog(false);
    collector.setKeepChecks(options.verbose);
    result.addListener(&console);
    result.addListener(&collector);
    result.addListener(&plan.gate());

    int interrupted = 0;
    {
        // A second signal quits at once: the collector is taken off the run (no event reaches
        // it any more), what is still open is ended as interrupted, and the outputs written.
        auto quit = [&] {
            result.removeListener(&collector);
            collector.interruptOpen(TestMessage("interrupted: the runner quit"));
            writeOutputs(options, collector, capture.console());
        };
        InterruptWatcher watcher(plan, capture.console(), quit);
        plan.runner().run(result);
        interrupted = watcher.received();
    }
    capture.stop();
    if (options.isolation == "none") {
        platform::killDescendants(::getpid());
    }

    int status = anythingFailed(collector) ? somethingFailed : allPassed;
    if (interrupted != 0) {
        status = interruptedBy(interrupted);
    }
    if (!writeOutputs(options, collector, stderr)) {
        status = configurationError;
    }
    return status;
}
