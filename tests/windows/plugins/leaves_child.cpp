// A test that starts a child process and leaves it running (Windows): the child must end with
// the test's job object. Param: --pid-file FILE (where the child's pid goes) --child PROGRAM.
#include <windows.h>

#include <fstream>
#include <string>

#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

namespace {

std::string option(const std::string& param, const std::string& name) {
    const std::size_t at = param.find(name + " ");
    if (at == std::string::npos) {
        return {};
    }
    const std::size_t start = at + name.size() + 1;
    return param.substr(start, param.find(' ', start) - start);
}

}  // namespace

class LeavesChild : public robottestingframework::TestCase {
public:
    LeavesChild() : TestCase("leaves_child") {}
    void run() override {
        std::string commandLine = option(getParam(), "--child");
        STARTUPINFOA startup{};
        startup.cb = sizeof(startup);
        PROCESS_INFORMATION info{};
        ROBOTTESTINGFRAMEWORK_TEST_CHECK(
            ::CreateProcessA(nullptr, &commandLine[0], nullptr, nullptr, FALSE, 0, nullptr, nullptr,
                             &startup, &info) != 0,
            "started " + commandLine);
        std::ofstream(option(getParam(), "--pid-file")) << info.dwProcessId << "\n";
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("left child " + std::to_string(info.dwProcessId) +
                                          " behind");
        ::CloseHandle(info.hThread);
        ::CloseHandle(info.hProcess);
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(LeavesChild)
