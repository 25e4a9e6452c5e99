// A test plug-in as one built against RTF 2.x is: it needs librobottestingframework.so.2 (here
// the stand-in beside this file, found through its run path).
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

extern "C" int rtf2_stand_in_version();

using namespace robottestingframework;

class BuiltAgainstRtf2 : public TestCase {
public:
    BuiltAgainstRtf2() : TestCase("BuiltAgainstRtf2") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(rtf2_stand_in_version() == 2, "2"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(BuiltAgainstRtf2)
