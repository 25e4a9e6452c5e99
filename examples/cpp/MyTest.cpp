// A C++ test plug-in in the RTF 2.x style: a TestCase with setup/run/tearDown, the assertion
// macros, and the plug-in macro that lets the runner load it. Its param (from the suite or
// `--param`) is read in setup():  --speed <deg/s>  [--distance <deg>]
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/Asserter.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class MyTest : public TestCase {
public:
    MyTest() : TestCase("MyTest") {}

    bool setup(int argc, char** argv) override {
        std::string speed;
        // An error in setup: the test is not run (and tearDown is not called).
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            Arguments::getOption(argc, argv, "--speed", speed), "the param needs --speed <deg/s>");
        speed_ = std::stod(speed);
        std::string distance;
        if (Arguments::getOption(argc, argv, "--distance", distance))
            distance_ = std::stod(distance);
        ROBOTTESTINGFRAMEWORK_TEST_REPORT(
            Asserter::format("moving %.1f deg at %.1f deg/s (environment: '%s')", distance_, speed_,
                             getEnvironment().c_str()));
        return true;
    }

    void run() override {
        // Checks record a result and go on; a false one marks the test failed.
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(speed_ > 0, "the speed is positive");
        const double seconds = distance_ / speed_;
        ROBOTTESTINGFRAMEWORK_TEST_REPORT(Asserter::format("the move takes %.2f s", seconds));
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_TRUE(seconds > 60, "the move is too slow");
        // An assertion stops the test when it does not hold.
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL_IF_FALSE(seconds < 3600, "the move ends within an hour");
    }

    void tearDown() override { ROBOTTESTINGFRAMEWORK_TEST_REPORT("back to the home position"); }

private:
    double speed_ = 0;
    double distance_ = 90;
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(MyTest)
