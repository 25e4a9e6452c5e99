// Any executable as a test case. The param string is its argv; the environment string reaches
// it as RTF_ENVIRONMENT (and its name as RTF_TEST_NAME). TAP on its stdout becomes checks;
// without TAP, its exit status decides: 0 passes, 77 skips, anything else fails.
#include <atomic>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/Asserter.h>
#include <robottestingframework/TestResult.h>

#include "languages/exec/exec_process.h"
#include "languages/exec/tap_parser.h"
#include "languages/exec/tap_records.h"
#include "languages/executable_file.h"
#include "languages/language_loaders.h"
#include "languages/output_tail.h"
#include "languages/test_loader.h"
#include "platform/signal_name.h"

namespace robottestingframework {
namespace languages {

namespace {

// The status that means "skipped" for programs without TAP (the automake convention).
constexpr int kSkipStatus = 77;

std::string lastLine(const std::string& text) {
    std::size_t end = text.find_last_not_of(" \t\r\n");
    if (end == std::string::npos) {
        return {};
    }
    std::size_t begin = text.find_last_of('\n', end);
    begin = begin == std::string::npos ? 0 : begin + 1;
    return text.substr(begin, end + 1 - begin);
}

std::string pointLabel(const TapPoint& point) {
    std::string label = point.ok ? "ok " : "not ok ";
    label += std::to_string(point.number);
    if (!point.description.empty()) {
        label += " - " + point.description;
    }
    if (point.directive == TapPoint::Directive::Skip) {
        label += " # SKIP";
    } else if (point.directive == TapPoint::Directive::Todo) {
        label += " # TODO";
    }
    if (point.directive != TapPoint::Directive::None && !point.reason.empty()) {
        label += " " + point.reason;
    }
    return point.subtest.empty() ? label : point.subtest + " > " + label;
}

// Reports TAP as the program prints it, so that a test stopped half-way (timeout, Ctrl-C) keeps
// what it said; and bounds what it keeps, so that a program printing without end costs no
// more than a talkative one.
class TapReporter : public TapListener {
public:
    TapReporter(TestCase* test, const std::string& path, OutputTail& output)
        : test_(test), path_(path), output_(output) {}

    void point(const TapPoint& point) override {
        record(point);
        bool failed = point.failed();
        if (failed ? failedShown_ >= kMaxShown : shown_ >= kMaxShown) {
            ++(failed ? failedHidden_ : hidden_);
            if (failed && failedHidden_ == 1) {
                // Past the limit a failure is still one: the verdict never depends on volume.
                Asserter::testFail(false,
                                   TestMessage("more than " + std::to_string(kMaxShown) +
                                                   " TAP points failed: the rest are counted, "
                                                   "not listed",
                                               "", path_, point.line),
                                   test_);
            }
            return;
        }
        ++(failed ? failedShown_ : shown_);
        // The YAML's measurements and attachments are recorded as such, and its other keys
        // are the message's diagnostics: none of it is pasted into the point's text.
        TestMessage message(pointLabel(point), "", path_, point.line);
        message.setDiagnostics(tapDiagnostics(withoutTapRecords(point.diagnostics)));
        if (point.directive != TapPoint::Directive::None && !point.ok) {
            // TODO: expected to fail; SKIP: TAP 14 says a failing skipped point is no failure.
            Asserter::report(message, test_);
        } else {
            Asserter::testCheck(point.ok, message, test_);
        }
    }
    void comment(const std::string& text) override {
        if (comments_++ < kMaxShown) {
            Asserter::report(TestMessage("# " + text), test_);
        }
    }
    void problem(const TapProblem& problem) override {
        if (problems_++ < kMaxShown) {
            Asserter::testFail(
                false, TestMessage("TAP: " + problem.message, "", path_, problem.line), test_);
        }
    }
    void text(const std::string& line) override {
        output_.append(line);
        output_.append("\n", 1);
    }

    // One line for what was counted but not listed.
    void summarize() {
        if (hidden_ + failedHidden_ > 0) {
            Asserter::report(TestMessage(std::to_string(hidden_ + failedHidden_) +
                                         " more TAP points not listed (" +
                                         std::to_string(failedHidden_) + " of them failed)"),
                             test_);
        }
        std::size_t unlisted = (comments_ > kMaxShown ? comments_ - kMaxShown : 0) +
                               (problems_ > kMaxShown ? problems_ - kMaxShown : 0);
        if (unlisted > 0) {
            Asserter::report(
                TestMessage(std::to_string(unlisted) + " more TAP comments or problems not listed"),
                test_);
        }
    }

private:
    // The point's measurements and attachments (YAML `measurements:`, `attachments:`), each
    // recorded as the other languages record theirs.
    void record(const TapPoint& point) {
        if (point.diagnostics.find("measurements:") == std::string::npos &&
            point.diagnostics.find("attachments:") == std::string::npos) {
            return;
        }
        const TestMessage where("", "", path_, point.line);
        const TapRecords records = readTapRecords(point.diagnostics);
        for (const std::string& problem : records.problems) {
            // The error gives the test its state; no failed(), which would add a failure.
            test_->getResult()->addError(test_,
                                         TestMessage("TAP: " + problem, "", path_, point.line));
        }
        for (const Measurement& measurement : records.measurements) {
            Asserter::testMeasure(measurement, where, test_);
        }
        for (const TapAttachment& attachment : records.attachments) {
            Asserter::testAttach(attachment.path, attachment.description, where, test_);
        }
    }

    // Points (passed and failed counted apart), comments and problems listed in the report.
    static constexpr std::size_t kMaxShown = 10000;

    TestCase* test_;
    std::string path_;
    OutputTail& output_;
    std::size_t shown_ = 0, failedShown_ = 0, hidden_ = 0, failedHidden_ = 0;
    std::size_t comments_ = 0, problems_ = 0;
};

class ExecTestCase : public TestCase {
public:
    explicit ExecTestCase(const std::string& path) : TestCase(path), path_(path) {}

    void run() override {
        std::vector<std::string> argv{path_};
        for (auto& word : Arguments::split(getParam())) {
            argv.push_back(std::move(word));
        }
        // What it printed, stdout (besides TAP) and stderr in the order they came, cut to
        // the last 64 KiB; and the ends of each, for the verdict's message.
        OutputTail output;
        OutputTail lastOut(4096), lastErr(4096);
        TapReporter reporter(this, path_, output);
        TapParser tap(reporter);
        bool stopped = false;
        auto onOut = [&](const char* data, std::size_t size) {
            if (!stopped) {
                lastOut.append(data, size);
                tap.feed(data, size);
            }
        };
        auto onErr = [&](const char* data, std::size_t size) {
            if (!stopped) {
                lastErr.append(data, size);
                output.append(data, size);
            }
        };
        // Asked to stop (timeout, Ctrl-C): report at once what was said, while we may.
        auto onStopping = [&]() {
            tap.abandon();
            reportOutput(output);
            stopped = true;
        };
        ExecOutcome outcome = process_.run(
            argv, {{"RTF_ENVIRONMENT", getEnvironment()}, {"RTF_TEST_NAME", getName()}}, onOut,
            onErr, onStopping);
        if (!stopped) {
            tap.finish();
            reportOutput(output);
        }
        const std::string err = lastErr.take();
        if (!outcome.started) {
            Asserter::error(TestMessage("cannot run " + path_, outcome.startError, path_, 0));
        }
        if (interrupted() || stopped) {
            return;  // the runner reports the interruption
        }
        reporter.summarize();
        std::string status = "exited with status " + std::to_string(outcome.exitStatus);
        if (outcome.signal != 0) {
            TestMessage crash(platform::programKilledBy(outcome.signal), lastLine(err), path_, 0);
            if (getResult()) {
                getResult()->addCrash(this, crash);  // the state: crashed
            }
            return;
        }
        if (tap.isTap()) {
            if (tap.bailedOut()) {
                Asserter::error(
                    TestMessage("Bail out! " + tap.bailOutReason(), "", path_, tap.bailOutLine()));
            }
            if (outcome.exitStatus != 0 && !tap.failed()) {
                Asserter::fail(TestMessage(status, lastLine(err), path_, 0));
            }
            if (tap.skipAll() && !tap.failed() && getResult()) {
                getResult()->addSkipped(
                    this,
                    TestMessage(tap.skipReason().empty() ? "the plan is 1..0" : tap.skipReason(),
                                "", path_, 0));
            }
            return;
        }
        if (outcome.exitStatus == kSkipStatus) {
            if (getResult()) {
                getResult()->addSkipped(
                    this, TestMessage("exit status 77",
                                      lastLine(err.empty() ? lastOut.take() : err), path_, 0));
            }
        } else if (outcome.exitStatus != 0) {
            Asserter::fail(TestMessage(status, lastLine(err), path_, 0));
        }
    }

    void interrupt() override {
        TestCase::interrupt();
        process_.terminate();
    }

private:
    void reportOutput(OutputTail& output) {
        if (!output.empty() && getResult()) {
            getResult()->addOutput(this, output.take());
        }
    }

    std::string path_;
    ExecProcess process_;
};

class LoadedExecTest : public LoadedTest {
public:
    explicit LoadedExecTest(const std::string& path) : test_(path) {}
    TestCase* get() override { return &test_; }

private:
    ExecTestCase test_;
};

std::atomic<std::string (*)()> execGuard{nullptr};

}  // namespace

void setExecGuard(std::string (*guard)()) {
    execGuard = guard;
}

std::string execGuardEntry() {
    std::string (*guard)() = execGuard;
    return guard != nullptr ? guard() : std::string();
}

std::unique_ptr<LoadedTest> loadExecTest(const std::string& path, std::string& error) {
    if (!isExecutableFile(path)) {
        error = path + " is not an executable file";
        return nullptr;
    }
    return std::make_unique<LoadedExecTest>(path);
}

}  // namespace languages
}  // namespace robottestingframework
