// What kind of RTF plug-in a shared library file is, read from the file without loading it: the
// name of the factory its plug-in macro exports (ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN's
// `robottestingframework_dll_factory`, ..._PREPARE_FIXTURE_PLUGIN's
// `robottestingframework_fixture_factory`, the same names in RTF 2.x and in this version) is
// among the file's exported names. A --tests folder holds what a build put there: test plug-ins,
// fixture plug-ins and other libraries side by side; RTF 2.x ran the test plug-ins only.
#pragma once

#include <string>

namespace robottestingframework {
namespace runner {

enum class PluginFileKind {
    Test,     // exports the test factory (whichever RTF built it)
    Fixture,  // exports the fixture factory only
    Other,    // neither: a library that is no RTF plug-in, or a file that cannot be read
};

PluginFileKind pluginFileKind(const std::string& path);

}  // namespace runner
}  // namespace robottestingframework
