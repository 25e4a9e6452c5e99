// Passes, printing on stdout (printf and iostream) and stderr: the runner captures it.
#include <cstdio>
#include <iostream>

#include <robottestingframework/dll/Plugin.h>

class PrintingTest : public robottestingframework::TestCase {
public:
    PrintingTest() : TestCase("PrintingTest") {}
    void run() override {
        std::printf("printf line from the test\n");
        std::cout << "iostream line from the test" << std::endl;
        std::fprintf(stderr, "stderr line from the test\n");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(PrintingTest)
