// Fails with bytes that are not UTF-8 (a stray 0xFF, a cut sequence, a surrogate) in its name,
// its message and what it prints: every report must stay a well-formed file.
#include <cstdio>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

class BadBytesTest : public robottestingframework::TestCase {
public:
    BadBytesTest() : TestCase("BadBytesTest \xff\xc3 # \\ end") {}
    void run() override {
        std::printf("printed \xff\xfe \xed\xa0\x80 \xc3 \x01 end\n");
        ROBOTTESTINGFRAMEWORK_ASSERT_FAIL("failure \xff\xc3\x28 \x1b[31m </script> end");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(BadBytesTest)
