// Checks that the process whose pid leaves_child wrote (--pid-file FILE) has ended (Windows):
// it fails while that process still runs, 5 s after the test that left it.
#include <windows.h>

#include <fstream>
#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

class ChildGone : public robottestingframework::TestCase {
public:
    ChildGone() : TestCase("child_gone") {}
    void run() override {
        const std::string param = getParam();
        const std::size_t at = param.find("--pid-file ");
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(at != std::string::npos, "no --pid-file");
        DWORD pid = 0;
        std::ifstream(param.substr(at + 11)) >> pid;
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(pid != 0, "no pid in the file");
        HANDLE process = ::OpenProcess(SYNCHRONIZE, FALSE, pid);
        bool gone = process == nullptr || ::WaitForSingleObject(process, 5000) == WAIT_OBJECT_0;
        if (process != nullptr) {
            ::CloseHandle(process);
        }
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(gone, "the child " + std::to_string(pid) + " is gone");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ChildGone)
