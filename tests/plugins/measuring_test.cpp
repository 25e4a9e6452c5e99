// A test plug-in that records measurements and attachments through the C++ macros; its param
// says which (tests/e2e/test_measurements.py, test_attachments.py):
//   "in"           tracking error 0.012 rad within [0, 0.05], loop rate 99.5 Hz, 3 steps
//   "out"          tracking error 0.12 rad outside [0, 0.05], then a report (the test goes on)
//   "nan"          a value that is not a number
//   "attach FILE"  attaches FILE ("the log")
#include <cmath>
#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class MeasuringTest : public robottestingframework::TestCase {
public:
    MeasuringTest() : TestCase("MeasuringTest") {}
    void run() override {
        const std::string param = getParam();
        if (param == "in") {
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("tracking error", 0.012, "rad", 0, 0.05);
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE("loop rate", 99.5, "Hz");
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE("steps", 3, "");
        } else if (param == "out") {
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("tracking error", 0.12, "rad", 0, 0.05);
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("went on after the measurement");
        } else if (param == "nan") {
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE("tracking error", std::nan(""), "rad");
        } else if (param.rfind("attach ", 0) == 0) {
            ROBOTTESTINGFRAMEWORK_TEST_ATTACH(param.substr(7), "the log");
        }
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(MeasuringTest)
