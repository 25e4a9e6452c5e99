// Everything that listens to a run, in the order it must hear it: the tests' output capture
// (first: a test's output arrives before its end), the collector, the console (one suite at a
// time, or one line per test with -j N; both read the collector's records), the requested
// outputs, the live page.
#pragma once

#include <cstdio>
#include <memory>
#include <vector>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestListener.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>

#include "reporters/reporter.h"
#include "runner/cli/options.h"
#include "runner/console/parallel_console.h"
#include "runner/console/progress_line.h"
#include "runner/execution/output_capture.h"
#include "runner/schedule/scheduler.h"

namespace robottestingframework {
namespace runner {

class RunListeners {
public:
    // Starts capturing the tests' output (a warning on stderr when it cannot, the output then
    // going to the console). `reportSettings`: the run's place (planned_run.h), for the
    // outputs. `web`: the live page, or nullptr. `progress`: what the progress line shows
    // (only on a terminal; its colours come from --color).
    RunListeners(const Options& options, const reporters::ReporterSettings& reportSettings,
                 TestListener* web, ProgressSettings progress);
    ~RunListeners();
    RunListeners(const RunListeners&) = delete;
    RunListeners& operator=(const RunListeners&) = delete;

    TestResult& result() { return result_; }
    const TestResultCollector& collector() const { return collector_; }
    // The real stdout while the tests' output is captured.
    std::FILE* console() const { return capture_.console(); }
    // What the scheduler has to say: to the parallel console with -j N, else as lines.
    SchedulerView& schedulerView();

    // A second signal quits at once: the collector is taken off the run (no event reaches it
    // any more), what is still open is ended as interrupted, and the outputs written.
    void quit();
    // The tests' output goes back to stdout and stderr.
    void stopCapture() { capture_.stop(); }
    // Writes every requested output, each whole or not at all; false when one could not be
    // written (each is said on `console`, and the others are still written). One that another
    // process wrote since the run started (or since this run last wrote it) is said on
    // `console` as a warning, and replaced.
    bool writeOutputs(std::FILE* console);

private:
    struct Output;
    class Notes;

    TestResult result_;
    OutputCapture capture_;
    OutputCaptureListener captureListener_;
    ConsoleListener console_;
    TestResultCollector collector_;
    std::unique_ptr<ProgressLine> progress_;  // on a terminal only
    std::unique_ptr<ParallelConsole> parallelConsole_;
    std::vector<Output> outputs_;
    std::unique_ptr<Notes> notes_;
};

}  // namespace runner
}  // namespace robottestingframework
