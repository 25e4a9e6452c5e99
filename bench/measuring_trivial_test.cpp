// bench/measure_bench.py's test: the trivial test (trivial_test.cpp) that also records three
// measurements, one with limits, so a run measures what measurements cost the framework.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class MeasuringTrivialTest : public robottestingframework::TestCase {
public:
    MeasuringTrivialTest() : TestCase("trivial") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(true, "nothing to do");
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("tracking error", 0.012, "rad", 0, 0.05);
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE("loop rate", 99.5, "Hz");
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE("steps", 3, "");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(MeasuringTrivialTest)
