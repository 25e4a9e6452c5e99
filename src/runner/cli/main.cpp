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
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/WebProgressListener.h>

#include "coverage.h"
#include "process.h"
#include "process_tree.h"
#include "reporter_registry.h"
#include "runner/cli/command_line_suites.h"
#include "runner/cli/listing.h"
#include "runner/cli/options.h"
#include "runner/cli/output_paths.h"
#include "runner/cli/sharded_run_setup.h"
#include "runner/console/parallel_console.h"
#include "runner/execution/in_process_executor.h"
#include "runner/execution/isolated_executor.h"
#include "runner/execution/output_capture.h"
#include "runner/plan/run_gate.h"
#include "runner/plan/run_plan.h"
#include "runner/reports/merge_reports.h"
#include "runner/reports/rerun_report.h"
#include "runner/schedule/resources.h"
#include "runner/schedule/scheduler.h"
#include "signal_pipe.h"

#include "atomic_file.h"

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
    // `interrupt`: stops the run (called again and again until it ends).
    InterruptWatcher(std::function<void()> interrupt, std::FILE* console,
                     std::function<void()> quit)
        : signals_({SIGINT, SIGTERM}),
          interrupt_(std::move(interrupt)),
          quit_(std::move(quit)),
          thread_([this, console] { watch(console); }) {}
    ~InterruptWatcher() { stop(); }
    // Stops watching and returns the first signal received, 0 when none. A signal that came
    // as the run ended counts too (or it would be lost, e.g. during --web-linger).
    int stop() {
        if (thread_.joinable()) {
            done_ = true;
            signals_.wake();  // or the run would end up to one poll period (200 ms) late
            thread_.join();
            // The pipe may hold the wake-up byte (0) before the signal.
            for (int i = 0; i < 3 && received_ == 0; ++i) {
                received_ = signals_.take();
            }
        }
        return received_;
    }
    bool interrupted() const { return received_ != 0; }

private:
    void watch(std::FILE* console) {
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
                platform::flushCoverage();
                ::_exit(interruptedBy(received_));
            }
            if (received_ != 0) {
                // Again and again: an interruption that arrives while a test is being started
                // could be missed by it; the runner starts no new test once interrupted.
                interrupt_();
            }
        }
    }

    platform::SignalPipe signals_;
    std::function<void()> interrupt_;
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

// One requested output: its file and the reporter of its type (from the one table).
struct Output {
    OutputRequest request;
    std::unique_ptr<reporters::Reporter> reporter;
};

std::vector<Output> makeOutputs(const Options& options, const TestResultCollector& collector,
                                reporters::ReporterSettings settings) {
    settings.verbose = options.verbose;
    settings.summary = !options.noSummary;
    std::vector<Output> outputs;
    for (const auto& request : options.outputs) {
        // The option parser let only the table's types through.
        outputs.push_back(
            {request, reporters::findReporterType(request.type)->make(collector, settings)});
    }
    return outputs;
}

// Writes every requested output, each whole or not at all; false when one could not be written
// (each is reported on `console`, and the others are still written).
bool writeOutputs(const std::vector<Output>& outputs, std::FILE* console) {
    bool ok = true;
    for (const auto& output : outputs) {
        TestMessage error;
        if (!output.reporter->write(output.request.file, &error)) {
            std::fprintf(console, "%s: cannot write the %s output %s: %s\n", program,
                         output.request.type.c_str(), output.request.file.c_str(),
                         error.toString().c_str());
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

// Keeps serving the final page for `seconds`, or until Ctrl-C or SIGTERM.
void lingerOn(const WebProgressListener& web, double seconds) {
    platform::SignalPipe signals({SIGINT, SIGTERM});  // before saying Ctrl-C works
    std::fprintf(stdout, "%s: the final page stays at %s for %g s (Ctrl-C to quit)\n", program,
                 web.url().c_str(), seconds);
    std::fflush(stdout);
    signals.wait(static_cast<int>(seconds * 1000));
}

// --merge OUT_TYPE:OUT_FILE REPORT...: runs nothing.
int mergeCommand(const Options& options) {
    MergeRequest request{options.merge.type, options.merge.file, options.mergeReports,
                         options.expectShards};
    std::string error;
    try {
        if (reporters::writeFileAtomically(request.file, mergeReports(request), error)) {
            std::fprintf(stdout, "%s: merged %zu reports into %s\n", program,
                         request.reports.size(), request.file.c_str());
            return allPassed;
        }
        error = "cannot write " + request.file + ": " + error;
    } catch (const std::exception& e) {
        error = e.what();
    }
    std::fprintf(stderr, "%s: %s\n", program, error.c_str());
    return configurationError;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    ParseResult parsed = parseOptions(argc, argv, options);
    if (parsed.outcome == ParseResult::Outcome::Exit) {
        std::fputs(parsed.text.c_str(), parsed.status == 0 ? stdout : stderr);
        return parsed.status;
    }
    if (!options.merge.type.empty()) {
        return mergeCommand(options);
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
    // Once the suites have read ${env:...} and before anything starts: the CI engines' shard
    // variables are read, then taken out of the environment the tests inherit.
    ShardChoice shard;
    {
        std::string error;
        if (!prepareShard(options, shard, error)) {
            std::fprintf(stderr, "%s: %s\n", program, error.c_str());
            return configurationError;
        }
    }
    reporters::ReporterSettings shardSettings;
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

    ResourcePools pools;
    if (!options.resources.empty()) {
        try {
            pools = readResourceFile(options.resources);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: --resources %s\n", program, e.what());
            return configurationError;
        }
    }
    const std::string poolProblem = checkPools(suites, pools);
    if (!poolProblem.empty()) {
        std::fprintf(stderr, "%s: %s\n", program, poolProblem.c_str());
        return configurationError;
    }

    if (!options.rerunFailed.empty()) {
        std::vector<FailedTest> failed;
        try {
            const Report earlier = readReport("--rerun-failed", options.rerunFailed);
            failed = failedTests(earlier);
            // A rerun of a shard's failures is that shard again: its tests as they are, and
            // its report says so, for --merge to put it in place of the first one.
            if (shard.sharded) {
                std::fprintf(stdout,
                             "%s: --rerun-failed: the failed tests of %s run again as they "
                             "are; the shard (%s) is not taken again\n",
                             program, options.rerunFailed.c_str(), shard.source.c_str());
                shard = ShardChoice();
            }
            shardSettings.rerun = true;
            shardSettings.sharded = earlier.shard.known;
            shardSettings.shardIndex = earlier.shard.index;
            shardSettings.shardCount = earlier.shard.count;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", program, e.what());
            return configurationError;
        }
        if (failed.empty()) {
            std::fprintf(stdout, "%s: %s has no failed test: nothing to rerun\n", program,
                         options.rerunFailed.c_str());
            return allPassed;
        }
        keepFailedTests(suites, failed);
        if (suites.empty()) {
            std::fprintf(stderr, "%s: warning: no test of this run is one that failed in %s\n",
                         program, options.rerunFailed.c_str());
        }
    }
    if (!options.selection.empty()) {
        applySelection(suites, options.selection);
        if (suites.empty()) {
            std::fprintf(stderr, "%s: warning: no test is selected\n", program);
        }
    }
    std::vector<unsigned int> shardOf;
    if (shard.sharded) {
        try {
            shardOf = shardsOf(suites, shard.count, options.durations);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s: %s\n", program, e.what());
            return configurationError;
        }
        std::size_t mine = 0;
        for (unsigned int of : shardOf) {
            mine += of == shard.index ? 1 : 0;
        }
        std::fprintf(
            stdout, "%s: shard %u of %u (from %s)%s: %zu of %zu suites\n", program, shard.index,
            shard.count, shard.source.c_str(),
            options.durations.empty() ? "" : (", balanced by " + options.durations).c_str(), mine,
            suites.size());
    } else if (!options.durations.empty()) {
        std::fprintf(stderr, "%s: warning: --durations %s: not sharded, nothing to balance\n",
                     program, options.durations.c_str());
    }
    if (options.list || options.listVariables) {
        // What would run, and nothing run: no plug-in is loaded, no fixture started.
        for (auto& suite : suites) {
            applyOverrides(suite, overrides);
        }
        std::fputs((options.listVariables ? listVariablesText(suites)
                                          : listText(suites, shardOf, shard.count))
                       .c_str(),
                   stdout);
        for (const auto& output : options.outputs) {
            std::string error;
            if (options.list && output.type == "json" &&
                !writeListJson(output.file, suites, error, shardOf)) {
                std::fprintf(stderr, "%s: cannot write the list %s: %s\n", program,
                             output.file.c_str(), error.c_str());
                return configurationError;
            }
        }
        return allPassed;
    }
    if (shard.sharded) {
        // Only this shard's suites run; each keeps its place in the whole selection, so the
        // shards' reports merge into the one a single machine would write.
        std::vector<SuiteSpec> mine;
        for (std::size_t i = 0; i < suites.size(); ++i) {
            if (shardOf[i] == shard.index) {
                shardSettings.suitePlaces.push_back(i);
                if (options.verbose) {
                    std::fprintf(stdout, "%s: shard %u runs suite %s%s\n", program, shard.index,
                                 suites[i].name.c_str(),
                                 suites[i].where.file.empty()
                                     ? ""
                                     : (" (" + suites[i].where.file + ")").c_str());
                }
                mine.push_back(std::move(suites[i]));
            }
        }
        suites = std::move(mine);
        if (suites.empty()) {
            std::fprintf(stdout, "%s: shard %u of %u has no suite to run\n", program, shard.index,
                         shard.count);
        }
        shardSettings.sharded = true;
        shardSettings.shardIndex = shard.index;
        shardSettings.shardCount = shard.count;
    }
    std::fflush(stdout);

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
        if (options.jobs > 1) {
            std::fprintf(stderr,
                         "%s: warning: --isolation none runs one suite at a time (tests share "
                         "the runner's process); --jobs %u is not used\n",
                         program, options.jobs);
            options.jobs = 1;
        }
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
    plan.setRetries(options.retries);
    for (auto& suite : suites) {
        applyOverrides(suite, overrides);
        plan.addSuite(std::move(suite));
    }
    suites.clear();

    // The page is served from before the first test until the run ends (and --web-linger).
    std::unique_ptr<WebProgressListener> web;
    if (options.webReporter) {
        if (options.webHost != "127.0.0.1") {
            std::fprintf(stderr,
                         "%s: warning: --web-host %s: the page of the run is served beyond "
                         "this machine's loopback address\n",
                         program, options.webHost.c_str());
        }
        web = std::make_unique<WebProgressListener>(
            options.webHost, static_cast<unsigned int>(options.webPort), options.verbose);
        if (!web->isListening()) {
            std::fprintf(stderr, "%s: --web-port %d: %s\n", program, options.webPort,
                         web->error().c_str());
            return configurationError;
        }
        std::fprintf(stdout, "%s: live web page at %s\n", program, web->url().c_str());
        std::fflush(stdout);
    }

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

    const bool parallel = options.jobs > 1;
    ConsoleListener console(options.verbose);
    console.setStream(capture.console());
    console.setColors(colours);
    console.showChecks(options.detail);
    console.showSummary(!options.noSummary);
    console.setRetries(options.retries);
    if (!options.verbose) {
        console.hideUncriticalMessages();
    }
    TestResultCollector collector;
    // The outputs read the per-test records only, and show checks only when verbose.
    collector.setKeepEventLog(false);
    collector.setKeepChecks(options.verbose);
    ParallelConsoleSettings parallelSettings;
    parallelSettings.verbose = options.verbose;
    parallelSettings.colours = colours;
    parallelSettings.summary = !options.noSummary;
    parallelSettings.retries = options.retries;
    parallelSettings.statusLine = ::isatty(::fileno(capture.console())) == 1;
    ParallelConsole parallelConsole(capture.console(), collector, parallelSettings);
    // One line per test as it ends, from any suite (-j N); else the console of one suite at a
    // time.
    // 64 KiB per test, but not for every one of 10 000 talkative tests (README: Output limits).
    collector.setOutputBudget(8 * 1024 * 1024);
    if (!parallel) {
        result.addListener(&console);
    }
    result.addListener(&collector);
    if (parallel) {
        result.addListener(&parallelConsole);  // the summary, after the collector has it all
    }
    // The gate (--fail-fast, depends) listens to each suite's events as they come: the
    // scheduler adds it to them.
    const std::vector<Output> outputs = makeOutputs(options, collector, shardSettings);
    for (const auto& output : outputs) {
        result.addListener(output.reporter.get());
    }
    if (web) {
        result.addListener(web.get());
    }

    // The lines the scheduler has to say when one suite runs at a time (a wait for a lock).
    class Notes : public SchedulerView {
    public:
        explicit Notes(std::FILE* stream) : stream_(stream) {}
        void note(const std::string& line) override {
            std::fprintf(stream_, "%s: %s\n", program, line.c_str());
            std::fflush(stream_);
        }

    private:
        std::FILE* stream_;
    } notes(capture.console());
    SchedulerSettings schedulerSettings;
    schedulerSettings.jobs = options.jobs;
    schedulerSettings.inlineSuites = options.isolation == "none";
    schedulerSettings.verbose = options.verbose;
    schedulerSettings.view = parallel ? static_cast<SchedulerView*>(&parallelConsole) : &notes;
    Scheduler scheduler(plan, pools, schedulerSettings);

    int interrupted = 0;
    {
        // A second signal quits at once: the collector is taken off the run (no event reaches
        // it any more), what is still open is ended as interrupted, and the outputs written.
        auto quit = [&] {
            result.removeListener(&collector);
            for (const auto& output : outputs) {
                result.removeListener(output.reporter.get());
            }
            collector.interruptOpen(TestMessage("interrupted: the runner quit"));
            writeOutputs(outputs, capture.console());
        };
        InterruptWatcher watcher([&scheduler] { scheduler.interrupt(); }, capture.console(), quit);
        // --repeat-until-fail N: the whole selection again, until a round fails (each round
        // is in the outputs, one after the other).
        const unsigned int rounds = options.repeatUntilFail == 0 ? 1 : options.repeatUntilFail;
        for (unsigned int round = 1; round <= rounds; ++round) {
            if (rounds > 1) {
                std::fprintf(capture.console(), "%s: round %u of %u\n", program, round, rounds);
                std::fflush(capture.console());
            }
            scheduler.run(result);
            if (watcher.interrupted() || anythingFailed(collector)) {
                if (rounds > 1 && !watcher.interrupted()) {
                    std::fprintf(capture.console(), "%s: round %u failed; stopping\n", program,
                                 round);
                }
                break;
            }
        }
        interrupted = watcher.stop();
    }
    capture.stop();
    if (options.isolation == "none") {
        platform::killDescendants(::getpid());
    }

    int status = anythingFailed(collector) ? somethingFailed : allPassed;
    if (options.failOnFlaky && collector.countOf(TestStatus::Flaky) > 0) {
        status = somethingFailed;
    }
    if (interrupted != 0) {
        status = interruptedBy(interrupted);
    }
    if (!writeOutputs(outputs, stderr)) {
        status = configurationError;
    }
    if (web && options.webLinger > 0 && interrupted == 0) {
        lingerOn(*web, options.webLinger);
    }
    return status;
}
