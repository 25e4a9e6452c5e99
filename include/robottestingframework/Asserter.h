// What the assertion macros call. Usable directly, too.
#pragma once

#include <string>

// What RTF 2.x's Asserter.h (and so TestAssert.h) brought along; tests rely on them.
#include <robottestingframework/Exception.h>
#include <robottestingframework/Measurement.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestMessage.h>
#include <robottestingframework/TestSuite.h>

namespace robottestingframework {

class TestCase;
class FixtureManager;

class Asserter {
public:
    // printf-style formatting into a std::string.
    static std::string format(const char* fmt, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 1, 2)))
#endif
        ;

    // Throws TestFailureException (the test stops as failed).
    [[noreturn]] static void fail(TestMessage msg);
    static void fail(bool condition, TestMessage msg);  // throws when condition is false
    // Throws TestErrorException (the test stops with an error).
    [[noreturn]] static void error(TestMessage msg);
    static void error(bool condition, TestMessage msg);  // throws when condition is false
    // Throws TestCriticalErrorException: the test stops and the rest of its suite is skipped.
    [[noreturn]] static void criticalError(TestMessage msg);

    // Reports to `testcase`, or to the running test when it is nullptr.
    static void report(TestMessage msg, TestCase* testcase = nullptr);
    static void report(TestMessage msg, FixtureManager* fixture);
    // Records a check: when `condition` is false the test is marked failed and goes on.
    static void testCheck(bool condition, TestMessage msg, TestCase* testcase = nullptr);
    // Marks the test failed (and goes on) when `condition` is false, as RTF 2.x's did: the
    // condition is what should hold.
    static void testFail(bool condition, TestMessage msg, TestCase* testcase = nullptr);
    // Records a measurement. Outside its limits the test is marked failed (a failure naming
    // value, limits and unit) and goes on; one that cannot be recorded (measurementProblem)
    // is an error of the test, which goes on too. `where` gives the source file and line.
    static void testMeasure(const Measurement& measurement, TestMessage where = TestMessage(),
                            TestCase* testcase = nullptr);
    // Copies the file at `path` into the run's attachments folder and records it; a file that
    // cannot be attached (missing, over a limit) is an error of the test, which goes on.
    static void testAttach(const std::string& path, const std::string& description,
                           TestMessage where = TestMessage(), TestCase* testcase = nullptr);
    // The same for a fixture: the file becomes an attachment of the suite it serves (a
    // process's log). One that cannot be attached is a report of the suite, which goes on;
    // false then.
    static bool attach(const std::string& path, const std::string& description,
                       FixtureManager* fixture);
    // The same, and `stored` is the attachment the suite got (to attach it to a record of the
    // fixture's own too: FixtureEvents::fixtureCheckFailed).
    static bool attach(const std::string& path, const std::string& description,
                       FixtureManager* fixture, Attachment& stored);
};

}  // namespace robottestingframework
