// Using the library from a program's own main(): tests are objects of the program, run in
// process by a TestRunner, printed by a ConsoleListener and written by a TextOutputter.
//   library_example [report.txt]
// Exit status: 0 when every test passed, 1 otherwise.
#include <cstdio>
#include <string>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/TextOutputter.h>

using namespace robottestingframework;

class SumTest : public TestCase {
public:
    SumTest() : TestCase("SumTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("adding small numbers");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 + 2 == 4, "two and two make four");
    }
};

class StringTest : public TestCase {
public:
    StringTest() : TestCase("StringTest") {}
    void run() override {
        const std::string word = "robot";
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(word.size() == 5, "'robot' has five letters");
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(word.front() == 'r', "it starts with r");
    }
};

int main(int argc, char** argv) {
    const std::string report = argc > 1 ? argv[1] : "library-example-report.txt";

    SumTest sum;
    StringTest string;
    TestSuite suite("library example");
    suite.addTest(&sum);
    suite.addTest(&string);

    TestRunner runner;
    runner.addTest(&suite);

    TestResult result;
    ConsoleListener console;
    TestResultCollector collector;
    result.addListener(&console);
    result.addListener(&collector);

    runner.run(result);

    TestMessage error;
    TextOutputter outputter(collector);
    if (!outputter.write(report, true, &error)) {
        std::fprintf(stderr, "cannot write %s: %s\n", report.c_str(), error.toString().c_str());
        return 1;
    }
    std::printf("report written to %s\n", report.c_str());
    return collector.failedCount() == 0 ? 0 : 1;
}
