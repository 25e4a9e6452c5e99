#include <robottestingframework/Asserter.h>

#include <cstdarg>
#include <cstdio>
#include <utility>
#include <vector>

#include <robottestingframework/Exception.h>
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>

#include "attachment_store.h"

namespace robottestingframework {

namespace {

// With no test to report to, the message still must not vanish.
void printOrphan(const char* label, const TestMessage& msg) {
    const std::string where = msg.getSourceLocation();
    std::fprintf(stderr, "robottestingframework: %s (no running test): %s%s%s%s\n", label,
                 msg.toString().c_str(), where.empty() ? "" : " [", where.c_str(),
                 where.empty() ? "" : "]");
}

TestCase* target(TestCase* testcase) {
    return testcase ? testcase : TestCase::current();
}

TestMessage at(const TestMessage& where, const std::string& text) {
    return TestMessage(text, where.getDetail(), where.getSourceFileName(),
                       where.getSourceLineNumber());
}

}  // namespace

std::string Asserter::format(const char* fmt, ...) {
    char small[256];
    va_list args;
    va_start(args, fmt);
    va_list copy;
    va_copy(copy, args);
    const int size = std::vsnprintf(small, sizeof(small), fmt, args);
    va_end(args);
    std::string text;
    if (size < 0) {
        va_end(copy);
        return text;
    }
    if (static_cast<std::size_t>(size) < sizeof(small)) {
        text.assign(small, static_cast<std::size_t>(size));
    } else {
        std::vector<char> buffer(static_cast<std::size_t>(size) + 1);
        std::vsnprintf(buffer.data(), buffer.size(), fmt, copy);
        text.assign(buffer.data(), static_cast<std::size_t>(size));
    }
    va_end(copy);
    return text;
}

void Asserter::fail(TestMessage msg) {
    throw TestFailureException(msg);
}

void Asserter::fail(bool condition, TestMessage msg) {
    if (!condition) {
        throw TestFailureException(msg);
    }
}

void Asserter::error(TestMessage msg) {
    throw TestErrorException(msg);
}

void Asserter::error(bool condition, TestMessage msg) {
    if (!condition) {
        throw TestErrorException(msg);
    }
}

void Asserter::criticalError(TestMessage msg) {
    throw TestCriticalErrorException(msg);
}

void Asserter::report(TestMessage msg, TestCase* testcase) {
    TestCase* test = target(testcase);
    TestResult* result = test ? test->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("report", msg);
        return;
    }
    result->addReport(test, msg);
}

void Asserter::report(TestMessage msg, FixtureManager* fixture) {
    TestResult* result = fixture ? fixture->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("fixture report", msg);
        return;
    }
    result->addReport(fixture->getOwner(), msg);
}

void Asserter::testCheck(bool condition, TestMessage msg, TestCase* testcase) {
    TestCase* test = target(testcase);
    TestResult* result = test ? test->getResult() : nullptr;
    if (result == nullptr) {
        if (!condition) {
            printOrphan("check failed", msg);
        }
        return;
    }
    if (condition) {
        result->addCheck(test, std::move(msg), true);  // most checks: the message is not copied
        return;
    }
    result->addCheck(test, msg, false);
    result->addFailure(test, std::move(msg));
    test->failureReported_ = true;
    test->failed();
}

void Asserter::testFail(bool condition, TestMessage msg, TestCase* testcase) {
    if (condition) {
        return;
    }
    TestCase* test = target(testcase);
    TestResult* result = test ? test->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("failure", msg);
        return;
    }
    result->addFailure(test, msg);
    test->failureReported_ = true;
    test->failed();
}

void Asserter::testMeasure(const Measurement& measurement, TestMessage where, TestCase* testcase) {
    TestCase* test = target(testcase);
    TestResult* result = test ? test->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("measurement", at(where, measurement.name));
        return;
    }
    const std::string problem = measurementProblem(measurement);
    if (!problem.empty()) {
        result->addError(test, at(where, problem));
        test->failureReported_ = true;  // the error says why: no "marked itself failed"
        test->failed();
        return;
    }
    const bool passed = measurement.withinLimits();
    result->addMeasurement(test, measurement, passed);
    if (!passed) {
        result->addFailure(test, at(where, outOfLimitsMessage(measurement)));
        test->failureReported_ = true;
        test->failed();
    }
}

void Asserter::testAttach(const std::string& path, const std::string& description,
                          TestMessage where, TestCase* testcase) {
    TestCase* test = target(testcase);
    TestResult* result = test ? test->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("attachment", at(where, path));
        return;
    }
    Attachment attachment;
    std::string error;
    if (!storeAttachment(path, description, attachment, error)) {
        result->addError(test, at(where, error));
        test->failureReported_ = true;
        test->failed();
        return;
    }
    result->addAttachment(test, attachment);
}

bool Asserter::attach(const std::string& path, const std::string& description,
                      FixtureManager* fixture) {
    Attachment stored;
    return attach(path, description, fixture, stored);
}

bool Asserter::attach(const std::string& path, const std::string& description,
                      FixtureManager* fixture, Attachment& stored) {
    TestResult* result = fixture ? fixture->getResult() : nullptr;
    if (result == nullptr) {
        printOrphan("fixture attachment", TestMessage(path));
        return false;
    }
    Attachment attachment;
    std::string error;
    if (!storeAttachment(path, description, attachment, error)) {
        result->addReport(fixture->getOwner(), TestMessage("not attached: " + error));
        return false;
    }
    result->addAttachment(fixture->getOwner(), attachment);
    stored = attachment;
    return true;
}

}  // namespace robottestingframework
