// Fails with text XML cannot hold as is: markup, a CDATA end, control characters, and prints it.
#include <cstdio>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class NastyTextTest : public robottestingframework::TestCase {
public:
    NastyTextTest() : TestCase("NastyTextTest <&>") {}
    void run() override {
        std::printf("printed <b>bold</b> & ]]> \x01\x02\x1b[31m end\n");
        std::fprintf(stderr, "to stderr \"quoted\" \x07\n");
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("report <tag attr=\"x\"> & ]]> \x01");
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("failure <script>alert(1)</script> ]]> \x02\x1f end");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(NastyTextTest)
