// Loads a script test with an RTF 2.x plug-in loader and runs it twice with our own runner,
// listener and collector. Prints "passed P of T"; exit 0 when all passed, 1 when not, 2 when
// the file did not load (the loader's error on stderr).
#include <cstdio>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/TestResult.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>

#include LOADER_HEADER

using namespace robottestingframework;
using namespace robottestingframework::plugin;

int main(int argc, char* argv[]) {
    if (argc < 2) {
        std::printf("Usage: %s <test file> [param]\n", argv[0]);
        return 2;
    }
    LOADER loader;
    TestCase* test = loader.open(argv[1]);
    if (test == nullptr) {
        std::fprintf(stderr, "%s\n", loader.getLastError().c_str());
        return 2;
    }
    test->setParam(argc > 2 ? argv[2] : "");
    test->setEnvironment("--robot demo");

    ConsoleListener listener(true);
    TestResultCollector collector;
    TestResult result;
    result.addListener(&listener);
    result.addListener(&collector);

    TestRunner runner;
    runner.addTest(test);
    runner.run(result);
    runner.run(result);  // a loaded test runs again
    loader.close();

    std::printf("passed %u of %u\n", static_cast<unsigned>(collector.passedCount()),
                static_cast<unsigned>(collector.testCount()));
    return collector.failedCount() == 0 ? 0 : 1;
}
