// A test plug-in as RTF 2.x's ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN made it: only the SHLIBPP
// factory robottestingframework_dll_factory, none of this framework's own symbols.
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/SharedLibraryClass.h>

using namespace robottestingframework;

class Rtf2ShlibppTest : public TestCase {
public:
    Rtf2ShlibppTest() : TestCase("Rtf2ShlibppTest") {}
    void run() override {
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("made by an SHLIBPP factory");
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(getParam() != "--fail", "param is not --fail");
    }
};

SHLIBPP_DEFINE_SHARED_SUBCLASS(robottestingframework_dll_factory, Rtf2ShlibppTest, TestCase)
