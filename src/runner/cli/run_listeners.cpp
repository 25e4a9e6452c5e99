#include "runner/cli/run_listeners.h"

#include <unistd.h>

#include <cstdlib>
#include <map>
#include <string>

#include "reporters/reporter_registry.h"
#include "runner/cli/output_stamp.h"
#include "runner/cli/program_name.h"
#include "runner/cli/run_facts.h"

namespace robottestingframework {
namespace runner {

namespace {

// --color auto: on a terminal, unless NO_COLOR (no-color.org) or a dumb terminal says no;
// always and never win over both.
bool wantColours(Colour colour) {
    if (colour != Colour::Auto) {
        return colour == Colour::Always;
    }
    const char* term = std::getenv("TERM");
    const char* noColour = std::getenv("NO_COLOR");
    return ::isatty(1) && (noColour == nullptr || *noColour == '\0') &&
           !(term != nullptr && std::string(term) == "dumb");
}

}  // namespace

// One requested output: its file and the reporter of its type (from the one table).
struct RunListeners::Output {
    OutputRequest request;
    std::unique_ptr<reporters::Reporter> reporter;
    std::string stamp;  // the file when the run started, or when this run last wrote it
};

// The lines the scheduler has to say when one suite runs at a time (a wait for a lock).
class RunListeners::Notes : public SchedulerView {
public:
    Notes(std::FILE* stream, ProgressLine* progress) : stream_(stream), progress_(progress) {}
    void note(const std::string& line) override {
        if (progress_ != nullptr) {
            progress_->pause();
        }
        std::fprintf(stream_, "%s: %s\n", programName, line.c_str());
        std::fflush(stream_);
        if (progress_ != nullptr) {
            progress_->resume();
        }
    }

private:
    std::FILE* stream_;
    ProgressLine* progress_;
};

RunListeners::RunListeners(const Options& options,
                           const reporters::ReporterSettings& reportSettings, TestListener* web,
                           ProgressSettings progress)
    : captureListener_(capture_, result_), console_(options.verbose) {
    const bool colours = wantColours(options.colour);  // before the capture takes stdout
    std::string captureError;
    if (capture_.start(captureError)) {
        result_.addListener(&captureListener_);  // first: output arrives before endTest
    } else {
        std::fprintf(stderr, "%s: warning: %s; the tests' output goes to the console\n",
                     programName, captureError.c_str());
    }

    const bool parallel = options.jobs > 1;
    console_.setStream(capture_.console());
    console_.setColors(colours);
    console_.showChecks(options.detail);
    console_.showSummary(!options.noSummary);
    console_.setRetries(options.retries);
    if (!options.verbose) {
        console_.hideUncriticalMessages();
    }
    // The outputs read the per-test records only. They keep every report and check whatever
    // -v/-d say: those change only what the console prints.
    collector_.setCountTestsNotRun(true);  // the reports list a failed fixture's tests as skipped
    collector_.setKeepEventLog(false);
    // Only the outputs and the console's --detail read a passed check from the records (the
    // history reads measurements): without them, 10 000 tests need not keep 10 000 of them.
    collector_.setKeepChecks(!options.outputs.empty() || options.detail);
    // The console reads the run's records (the collector hears each event before it).
    console_.readRecordsOf(&collector_);
    ParallelConsoleSettings parallelSettings;
    parallelSettings.verbose = options.verbose;
    parallelSettings.colours = colours;
    parallelSettings.summary = !options.noSummary;
    parallelSettings.retries = options.retries;
    // A terminal that can rewrite a line (not TERM=dumb) gets the progress line.
    const char* term = std::getenv("TERM");
    if (::isatty(::fileno(capture_.console())) == 1 &&
        !(term != nullptr && std::string(term) == "dumb")) {
        progress.colours = colours;
        progress.jobs = options.jobs;
        progress_ = std::make_unique<ProgressLine>(capture_.console(), std::move(progress));
        parallelSettings.progress = progress_.get();
    }
    parallelConsole_ =
        std::make_unique<ParallelConsole>(capture_.console(), collector_, parallelSettings);
    // One line per test as it ends, from any suite (-j N); else the console of one suite at a
    // time.
    // 64 KiB per test, but not for every one of 10 000 talkative tests (README: Output limits).
    collector_.setOutputBudget(8 * 1024 * 1024);
    result_.addListener(&collector_);  // first: the consoles read what it recorded
    if (!parallel && progress_) {
        result_.addListener(&progress_->before());  // erases the line before the console
    }
    if (!parallel) {
        result_.addListener(&console_);
    }
    if (!parallel && progress_) {
        result_.addListener(&progress_->after());  // and draws it again after
    }
    if (parallel) {
        result_.addListener(parallelConsole_.get());  // the summary, after the collector has it
    }
    // The gate (--fail-fast, depends) listens to each suite's events as they come: the
    // scheduler adds it to them.
    reporters::ReporterSettings settings = reportSettings;
    settings.passedChecks = true;
    settings.runFacts = runFacts(options);
    settings.summary = !options.noSummary;
    // Only the HTML report reads each test's facts (10 000 tests: a map of 10 000 entries), so
    // only it gets a copy of them.
    std::map<std::string, reporters::TestFacts> facts;
    facts.swap(settings.testFacts);
    for (const auto& request : options.outputs) {
        // The option parser let only the table's types through.
        if (request.type == "html") {
            settings.testFacts = facts;
        }
        outputs_.push_back({request,
                            reporters::findReporterType(request.type)->make(collector_, settings),
                            outputStamp(request.file)});
        settings.testFacts.clear();
    }
    for (const auto& output : outputs_) {
        result_.addListener(output.reporter.get());
    }
    if (web != nullptr) {
        result_.addListener(web);
    }
    if (!parallel) {
        notes_ = std::make_unique<Notes>(capture_.console(), progress_.get());
    }
}

RunListeners::~RunListeners() = default;

SchedulerView& RunListeners::schedulerView() {
    if (notes_) {
        return *notes_;
    }
    return *parallelConsole_;
}

void RunListeners::quit() {
    result_.removeListener(&collector_);
    for (const auto& output : outputs_) {
        result_.removeListener(output.reporter.get());
    }
    collector_.interruptOpen(TestMessage("interrupted: the runner quit"));
    writeOutputs(capture_.console());
}

bool RunListeners::writeOutputs(std::FILE* console) {
    bool ok = true;
    for (auto& output : outputs_) {
        const std::string meanwhile =
            outputWrittenMeanwhile(output.request.type, output.request.file, output.stamp);
        if (!meanwhile.empty()) {
            std::fprintf(console, "%s: warning: %s\n", programName, meanwhile.c_str());
        }
        TestMessage error;
        const bool written = output.reporter->write(output.request.file, &error);
        output.stamp = outputStamp(output.request.file);
        if (!written) {
            std::fprintf(console, "%s: cannot write the %s output %s: %s\n", programName,
                         output.request.type.c_str(), output.request.file.c_str(),
                         error.toString().c_str());
            ok = false;
        }
    }
    return ok;
}

}  // namespace runner
}  // namespace robottestingframework
