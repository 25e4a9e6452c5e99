// Exceptions thrown by the assertion macros to stop the running test.
#pragma once

#include <exception>
#include <string>

#include <robottestingframework/TestMessage.h>

namespace robottestingframework {

class Exception : public std::exception {
public:
    explicit Exception(const TestMessage& message);
    const char* what() const noexcept override;
    const TestMessage& message() const noexcept { return message_; }
    // what() whole: a C string ends at a NUL the message may hold (a process's output it
    // quotes), this does not.
    const std::string& text() const noexcept { return what_; }

private:
    TestMessage message_;
    std::string what_;
};

// A failure: the test ran and something it checked was wrong. The test stops.
class TestFailureException : public Exception {
public:
    using Exception::Exception;
};

// An error: the test could not do its job (bad set-up, missing resource). The test stops.
class TestErrorException : public Exception {
public:
    using Exception::Exception;
};

// A critical error: nothing after this test in its suite makes sense; the rest is skipped.
class TestCriticalErrorException : public TestErrorException {
public:
    using TestErrorException::TestErrorException;
};

// A fixture could not be set up or broke (RTF 2.x's name, for fixtures that throw it).
class FixtureException : public Exception {
public:
    using Exception::Exception;
};

}  // namespace robottestingframework
