#include "runner/execution/output_capture.h"

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {
namespace runner {

OutputCaptureListener::OutputCaptureListener(OutputCapture& capture, TestResult& result)
    : capture_(capture), result_(result) {}

void OutputCaptureListener::flushTo(const Test* owner) {
    std::string text = capture_.take();
    if (text.empty()) {
        return;
    }
    if (owner != nullptr) {
        result_.addOutput(owner, text);
    } else {
        // Printed outside any suite: nobody to give it to, so show it.
        std::fputs(text.c_str(), capture_.console());
    }
}

void OutputCaptureListener::startTestSuite(const TestSuite* suite) {
    flushTo(nullptr);
    suite_ = suite;
}

void OutputCaptureListener::endTestSuite(const TestSuite* suite) {
    flushTo(suite);  // the fixtures' tear-down
    suite_ = nullptr;
}

void OutputCaptureListener::startTest(const Test* /*test*/) {
    flushTo(suite_);  // the fixtures' set-up and checks
}

void OutputCaptureListener::endTest(const Test* test) {
    flushTo(test);
}

void OutputCaptureListener::endTestRunner() {
    flushTo(nullptr);
}

}  // namespace runner
}  // namespace robottestingframework
