// Passes, printing without a flush: printf with no newline at the end, std::cout with '\n'
// instead of std::endl, stderr. What stays in the C library's and iostream's buffers when the
// test ends must still reach the reports.
#include <cstdio>
#include <iostream>

#include <robottestingframework/dll/Plugin.h>

class UnflushedPrintingTest : public robottestingframework::TestCase {
public:
    UnflushedPrintingTest() : TestCase("UnflushedPrintingTest") {}
    void run() override {
        std::printf("CPP-PRINTF-LINE\n");
        std::cout << "CPP-COUT-LINE\n";
        std::fprintf(stderr, "CPP-STDERR-LINE\n");
        std::cout << "CPP-COUT-UNENDED ";
        std::printf("CPP-PRINTF-UNENDED");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(UnflushedPrintingTest)
