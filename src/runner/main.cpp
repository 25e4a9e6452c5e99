// robottestingframework-testrunner: options → suites → run → outputs, and the exit status.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/JUnitOutputter.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TextOutputter.h>

#include "in_process_executor.h"
#include "options.h"
#include "output_capture.h"
#include "run_plan.h"
#include "test_sources.h"

using namespace robottestingframework;
using namespace robottestingframework::runner;

namespace {

const char* const program = "robottestingframework-testrunner";

// Exit statuses (SPEC 3.1).
const int allPassed = 0;
const int somethingFailed = 1;
const int configurationError = 2;

bool wantColours() {
    const char* term = std::getenv("TERM");
    return ::isatty(1) && std::getenv("NO_COLOR") == nullptr &&
           !(term != nullptr && std::string(term) == "dumb");
}

// Writes every requested output; false when one could not be written (each is reported).
bool writeOutputs(const Options& options, TestResultCollector& collector) {
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
            std::fprintf(stderr, "%s: cannot write the %s output %s: %s\n", program,
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

    InProcessExecutor executor;
    RunPlan plan(executor);
    const Overrides overrides{options.param, options.environment, options.repetition};
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
    result.addListener(&console);
    result.addListener(&collector);

    plan.runner().run(result);
    capture.stop();

    int status = anythingFailed(collector) ? somethingFailed : allPassed;
    if (!writeOutputs(options, collector)) {
        status = configurationError;
    }
    return status;
}
