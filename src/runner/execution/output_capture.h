// Catches what tests print (file descriptors 1 and 2, so child processes too) so it reaches the
// outputs (JUnit <system-out>) instead of mixing with the console. The runner uses it; the
// library API without the runner does not capture.
#pragma once

#include <cstdio>
#include <string>

#include <robottestingframework/TestListener.h>

namespace robottestingframework {

class TestResult;

namespace runner {

class OutputCapture {
public:
    OutputCapture() = default;
    ~OutputCapture();
    OutputCapture(const OutputCapture&) = delete;
    OutputCapture& operator=(const OutputCapture&) = delete;

    // Points fd 1 and 2 at an unlinked temporary file (in $TMPDIR). False with `error` set
    // when it cannot; nothing is changed then.
    bool start(std::string& error);
    // Puts fd 1 and 2 back; what was printed and not taken goes to the real stdout.
    void stop();
    bool active() const { return file_ >= 0; }

    // What was printed since the last call (the tail only, when it is huge).
    std::string take();
    // The real stdout while capturing (for the console), else stdout.
    std::FILE* console() const { return console_ != nullptr ? console_ : stdout; }

private:
    int file_ = -1;
    int savedOut_ = -1;
    int savedErr_ = -1;
    std::FILE* console_ = nullptr;
};

// Sends what was captured to `result` as the output of the test that printed it: before the
// test's endTest (so every listener has it), and a suite's fixtures' output to the suite.
// Register it before every other listener.
class OutputCaptureListener : public TestListener {
public:
    OutputCaptureListener(OutputCapture& capture, TestResult& result);

    void startTestSuite(const TestSuite* suite) override;
    void endTestSuite(const TestSuite* suite) override;
    void startTest(const Test* test) override;
    void endTest(const Test* test) override;
    void endTestRunner() override;
    // The frames above only: a test's checks and reports pass by without their message copied.
    void onEvent(const RunEvent& event) override;

private:
    void flushTo(const Test* owner);

    OutputCapture& capture_;
    TestResult& result_;
    const TestSuite* suite_ = nullptr;
};

}  // namespace runner
}  // namespace robottestingframework
