// RTF 2.x's examples/fixture-plugin/test.cpp, with the test made through shlibpp as RTF 2.x
// programs that load their own plug-ins do: run_fixture <fixture.so> <fixture param> <test.so>.
#include <cstdio>

#include <robottestingframework/ConsoleListener.h>
#include <robottestingframework/TestResultCollector.h>
#include <robottestingframework/TestRunner.h>
#include <robottestingframework/TestSuite.h>
#include <robottestingframework/dll/DllFixturePluginLoader.h>
#include <robottestingframework/dll/Plugin.h>
#include <robottestingframework/dll/SharedLibraryClass.h>
#include <robottestingframework/dll/SharedLibraryClassFactory.h>
#include <robottestingframework/dll/Vocab.h>

using namespace robottestingframework;
using namespace robottestingframework::plugin;

int main(int argc, char* argv[]) {
    if (argc < 4) {
        std::printf("Usage: %s <fixture plugin> <fixture param> <test plugin>\n", argv[0]);
        return 2;
    }
    DllFixturePluginLoader loader;
    FixtureManager* fixture = loader.open(argv[1]);
    if (fixture == nullptr) {
        std::fprintf(stderr, "%s\n", loader.getLastError().c_str());
        return 2;
    }
    fixture->setParam(argv[2]);

    shlibpp::SharedLibraryClassFactory<TestCase> factory(argv[3],
                                                         ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME);
    if (!factory.isValid()) {
        std::fprintf(stderr, "%s (status %s)\n", factory.getError().c_str(),
                     shlibpp::Vocab::decode(factory.getStatus()).c_str());
        return 2;
    }
    shlibpp::SharedLibraryClass<TestCase> test(factory);

    ConsoleListener listener(false);
    TestResultCollector collector;
    TestResult result;
    result.addListener(&listener);
    result.addListener(&collector);

    TestSuite suite("DemoSuite");
    suite.addFixtureManager(fixture);
    suite.addTest(&test.getContent());
    TestRunner runner;
    runner.addTest(&suite);
    runner.run(result);

    std::printf("class %s, passed %u of %u, suites failed %u\n", factory.getClassName().c_str(),
                static_cast<unsigned>(collector.passedCount()),
                static_cast<unsigned>(collector.testCount()),
                static_cast<unsigned>(collector.failedSuiteCount()));
    return collector.failedCount() == 0 && collector.failedSuiteCount() == 0 ? 0 : 1;
}
