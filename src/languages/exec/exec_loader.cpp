// Any executable as a test case. The param string is its argv; the environment string reaches
// it as RTF_ENVIRONMENT (and its name as RTF_TEST_NAME). TAP on its stdout becomes checks;
// without TAP, its exit status decides: 0 passes, 77 skips, anything else fails.
#include <robottestingframework/Arguments.h>
#include <robottestingframework/Asserter.h>
#include <robottestingframework/TestResult.h>

#include <sys/stat.h>
#include <unistd.h>

#include "backends.h"
#include "exec_process.h"
#include "tap_parser.h"

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

class ExecTestCase : public TestCase {
public:
    explicit ExecTestCase(const std::string& path) : TestCase(path), path_(path) {}

    void run() override {
        std::vector<std::string> argv{path_};
        for (auto& word : Arguments::split(getParam())) {
            argv.push_back(std::move(word));
        }
        ExecOutcome outcome = process_.run(
            argv, {{"RTF_ENVIRONMENT", getEnvironment()}, {"RTF_TEST_NAME", getName()}});
        if (!outcome.started) {
            Asserter::error(TestMessage("cannot run " + path_, outcome.startError, path_, 0));
        }
        TapStream tap = parseTap(outcome.out);
        std::string output;
        for (const auto& line : tap.otherText) {
            output += line + "\n";
        }
        output += outcome.err;
        if (!output.empty() && getResult()) {
            getResult()->addOutput(this, output);
        }
        if (interrupted()) {
            return;  // the runner reports the interruption
        }
        if (tap.isTap) {
            reportTap(tap);
        }
        std::string status = "exited with status " + std::to_string(outcome.exitStatus);
        if (outcome.signal != 0) {
            TestMessage crash("killed by " + signalName(outcome.signal), lastLine(outcome.err),
                              path_, 0);
            if (getResult()) {
                getResult()->addCrash(this, crash);  // the state: crashed
            }
            return;
        }
        if (tap.isTap) {
            if (tap.bailedOut) {
                Asserter::error(TestMessage("Bail out! " + tap.bailOutReason, "", path_, 0));
            }
            if (outcome.exitStatus != 0 && !tap.failed()) {
                Asserter::fail(TestMessage(status, lastLine(outcome.err), path_, 0));
            }
            if (tap.skipAll && !tap.failed() && getResult()) {
                getResult()->addSkipped(
                    this,
                    TestMessage(tap.skipReason.empty() ? "skipped (plan 1..0)" : tap.skipReason, "",
                                path_, 0));
            }
            return;
        }
        if (outcome.exitStatus == kSkipStatus) {
            if (getResult()) {
                getResult()->addSkipped(
                    this, TestMessage("skipped (exit status 77)",
                                      lastLine(outcome.err.empty() ? outcome.out : outcome.err),
                                      path_, 0));
            }
        } else if (outcome.exitStatus != 0) {
            Asserter::fail(TestMessage(status, lastLine(outcome.err), path_, 0));
        }
    }

    void interrupt() override {
        TestCase::interrupt();
        process_.terminate();
    }

private:
    void reportTap(const TapStream& tap) {
        for (const auto& comment : tap.comments) {
            Asserter::report(TestMessage("# " + comment), this);
        }
        for (const auto& point : tap.points) {
            TestMessage message(pointLabel(point), point.diagnostics, path_, point.line);
            if (point.directive == TapPoint::Directive::Todo && !point.ok) {
                Asserter::report(message, this);  // expected to fail
            } else {
                Asserter::testCheck(point.ok, message, this);
            }
        }
        for (const auto& problem : tap.problems) {
            Asserter::testFail(
                false, TestMessage("TAP: " + problem.message, "", path_, problem.line), this);
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

}  // namespace

std::unique_ptr<LoadedTest> loadExecTest(const std::string& path, std::string& error) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
        ::access(path.c_str(), X_OK) != 0) {
        error = path + " is not an executable file";
        return nullptr;
    }
    return std::make_unique<LoadedExecTest>(path);
}

}  // namespace languages
}  // namespace robottestingframework
