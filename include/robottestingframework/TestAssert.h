// The assertion macros. Each is one expression statement: safe in an unbraced if/else.
// Every message carries the source file and line of the macro.
#pragma once

#include <robottestingframework/Asserter.h>
#include <robottestingframework/Exception.h>
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestMessage.h>

#define ROBOTTESTINGFRAMEWORK_SOURCEFILE() __FILE__
#define ROBOTTESTINGFRAMEWORK_SOURCELINE() __LINE__

// The message is the user's text; the detail is the condition checked, when there is one.
#define ROBOTTESTINGFRAMEWORK_MESSAGE_(message, detail)                                           \
    ::robottestingframework::TestMessage((message), (detail), ROBOTTESTINGFRAMEWORK_SOURCEFILE(), \
                                         ROBOTTESTINGFRAMEWORK_SOURCELINE())

// A message in the test's report.
#define ROBOTTESTINGFRAMEWORK_TEST_REPORT(message) \
    ::robottestingframework::Asserter::report(ROBOTTESTINGFRAMEWORK_MESSAGE_(message, ""))

// Records the check; a false condition marks the test failed and the test goes on.
#define ROBOTTESTINGFRAMEWORK_TEST_CHECK(condition, message) \
    ::robottestingframework::Asserter::testCheck(            \
        static_cast<bool>(condition), ROBOTTESTINGFRAMEWORK_MESSAGE_(message, #condition))

// Records a measurement (a number with its unit, "" for none); with limits, a value outside
// [low, high] marks the test failed and the test goes on.
#define ROBOTTESTINGFRAMEWORK_TEST_MEASURE(name, value, unit)                                     \
    ::robottestingframework::Asserter::testMeasure(                                               \
        ::robottestingframework::Measurement{(name), static_cast<double>(value), (unit), {}, {}}, \
        ROBOTTESTINGFRAMEWORK_MESSAGE_("", ""))
#define ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN(name, value, unit, low, high)                        \
    ::robottestingframework::Asserter::testMeasure(                                                \
        ::robottestingframework::Measurement{(name), static_cast<double>(value), (unit),           \
                                             static_cast<double>(low), static_cast<double>(high)}, \
        ROBOTTESTINGFRAMEWORK_MESSAGE_("", ""))
// Copies a file (a plot, a log) into the run's attachments folder and records it with the test.
#define ROBOTTESTINGFRAMEWORK_TEST_ATTACH(path, description)             \
    ::robottestingframework::Asserter::testAttach((path), (description), \
                                                  ROBOTTESTINGFRAMEWORK_MESSAGE_("", ""))

// Marks the test failed (and goes on) when the condition is true / false.
#define ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(condition, message) \
    ::robottestingframework::Asserter::testFail(                    \
        !static_cast<bool>(condition), ROBOTTESTINGFRAMEWORK_MESSAGE_(message, #condition))
#define ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(condition, message) \
    ::robottestingframework::Asserter::testFail(                     \
        static_cast<bool>(condition),                                \
        ROBOTTESTINGFRAMEWORK_MESSAGE_(message, "!(" #condition ")"))

// A failure: the test stops.
#define ROBOTTESTINGFRAMEWORK_ASSERT_FAIL(message) \
    ::robottestingframework::Asserter::fail(ROBOTTESTINGFRAMEWORK_MESSAGE_(message, ""))
#define ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_TRUE(condition, message)      \
    ::robottestingframework::Asserter::fail(!static_cast<bool>(condition), \
                                            ROBOTTESTINGFRAMEWORK_MESSAGE_(message, #condition))
#define ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(condition, message) \
    ::robottestingframework::Asserter::fail(                           \
        static_cast<bool>(condition),                                  \
        ROBOTTESTINGFRAMEWORK_MESSAGE_(message, "!(" #condition ")"))

// An error: the test stops.
#define ROBOTTESTINGFRAMEWORK_ASSERT_ERROR(message) \
    ::robottestingframework::Asserter::error(ROBOTTESTINGFRAMEWORK_MESSAGE_(message, ""))
#define ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_TRUE(condition, message)      \
    ::robottestingframework::Asserter::error(!static_cast<bool>(condition), \
                                             ROBOTTESTINGFRAMEWORK_MESSAGE_(message, #condition))
#define ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(condition, message) \
    ::robottestingframework::Asserter::error(                           \
        static_cast<bool>(condition),                                   \
        ROBOTTESTINGFRAMEWORK_MESSAGE_(message, "!(" #condition ")"))

// Beyond RTF 2.x: a critical error. The test stops and the rest of its suite is skipped.
#define ROBOTTESTINGFRAMEWORK_ASSERT_CRITICAL(message) \
    ::robottestingframework::Asserter::criticalError(ROBOTTESTINGFRAMEWORK_MESSAGE_(message, ""))

// A message in a fixture manager's report (inside FixtureManager member functions).
#define ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT(message) \
    ::robottestingframework::Asserter::report(        \
        ROBOTTESTINGFRAMEWORK_MESSAGE_(message, ""),  \
        static_cast<::robottestingframework::FixtureManager*>(this))
