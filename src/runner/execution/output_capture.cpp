#include "runner/execution/output_capture.h"

#include <cerrno>
#include <cstring>

#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestSuite.h>

#include "platform/output_file.h"

namespace robottestingframework {
namespace runner {

namespace {

// More than this per test is cut to its tail: the last lines are the ones that explain. The
// same 64 KiB as a worker's output (docs/reference/isolation-timeouts-interrupts.md).
const long long maxOutput = 64 * 1024;

}  // namespace

OutputCapture::~OutputCapture() {
    stop();
}

bool OutputCapture::start(std::string& error) {
    if (active()) {
        return true;
    }
    platform::FileDescriptor file = platform::makeOutputFile(error);
    if (!file.valid()) {
        return false;
    }
    platform::flushStandardStreams();
    const int savedOut = platform::copyDescriptor(1);
    const int savedErr = platform::copyDescriptor(2);
    const int consoleFd = savedOut >= 0 ? platform::copyDescriptor(savedOut) : -1;
    std::FILE* console = consoleFd >= 0 ? platform::writeStreamOn(consoleFd) : nullptr;
    if (savedOut < 0 || savedErr < 0 || console == nullptr ||
        !platform::pointDescriptor(file.get(), 1) || !platform::pointDescriptor(file.get(), 2)) {
        error = std::string("cannot redirect the output to capture it: ") + std::strerror(errno);
        if (savedOut >= 0) {
            platform::pointDescriptor(savedOut, 1);
            platform::closeDescriptor(savedOut);
        }
        if (savedErr >= 0) {
            platform::pointDescriptor(savedErr, 2);
            platform::closeDescriptor(savedErr);
        }
        if (console != nullptr) {
            std::fclose(console);
        } else if (consoleFd >= 0) {
            platform::closeDescriptor(consoleFd);
        }
        return false;
    }
    // Line by line: if a test takes the runner down, the console still shows how far it got.
    // (The size is only a hint where the C library allocates the buffer; Windows needs one.)
    std::setvbuf(console, nullptr, _IOLBF, 1024);
    file_ = file.release();
    savedOut_ = savedOut;
    savedErr_ = savedErr;
    console_ = console;
    return true;
}

void OutputCapture::stop() {
    if (!active()) {
        return;
    }
    std::string rest = take();
    std::fflush(console_);
    platform::pointDescriptor(savedOut_, 1);
    platform::pointDescriptor(savedErr_, 2);
    platform::closeDescriptor(savedOut_);
    platform::closeDescriptor(savedErr_);
    platform::closeDescriptor(file_);
    std::fclose(console_);
    file_ = savedOut_ = savedErr_ = -1;
    console_ = nullptr;
    platform::writeAll(1, rest);
}

std::string OutputCapture::take() {
    if (!active()) {
        return {};
    }
    platform::flushStandardStreams();
    const long long size = platform::outputFileSize(file_);
    if (size <= 0) {
        return {};
    }
    const long long from = size > maxOutput ? size - maxOutput : 0;
    std::string text;
    if (from > 0) {
        text = "[" + std::to_string(from) + " bytes of output left out]\n";
    }
    const std::size_t start = text.size();
    text.resize(start + static_cast<std::size_t>(size - from));
    text.resize(start + platform::readOutputFile(file_, from, &text[start], text.size() - start));
    if (!platform::emptyOutputFile(file_)) {
        // Keeping it is harmless but the same text would come again: drop it from view.
        text += "\n[the capture file could not be emptied]\n";
    }
    return text;
}

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

void OutputCaptureListener::onEvent(const RunEvent& event) {
    if (isFrame(event.data.kind)) {
        TestListener::onEvent(event);
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
