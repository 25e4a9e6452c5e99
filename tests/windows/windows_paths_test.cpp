// Windows paths where the runner and the plug-in search take paths apart: drive letters and
// backslashes are absolute paths, and RTF_PLUGIN_PATH is a list separated by ';' as PATH is.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>

#include <robottestingframework/dll/DllPluginLoader.h>

#include "build_paths.h"
#include "runner/model/test_id.h"

using robottestingframework::plugin::findPlugin;
using robottestingframework::runner::pluginIdPart;
namespace fs = std::filesystem;

namespace {

// The plug-ins' folder as Windows writes it: "Z:\work\...\plugins".
std::string windowsPluginDir() {
    return fs::absolute(build_paths::windowsPluginDir())
        .lexically_normal()
        .make_preferred()
        .string();
}

bool sameFile(const std::string& found, const std::string& expected) {
    return !found.empty() && fs::equivalent(found, expected);
}

}  // namespace

TEST(WindowsPaths, DriveLetterPathWithBackslashesIsFoundAsIs) {
    const std::string file = windowsPluginDir() + "\\passing_test.dll";
    ASSERT_EQ(file.find('/'), std::string::npos) << file;
    std::string searched;
    EXPECT_TRUE(sameFile(findPlugin(file, "some\\other\\folder", &searched), file)) << searched;
}

TEST(WindowsPaths, RelativePathWithBackslashesIsTakenFromTheSuitesFolder) {
    const std::string parent = fs::path(windowsPluginDir()).parent_path().string();
    std::string searched;
    EXPECT_TRUE(sameFile(findPlugin("plugins\\passing_test.dll", parent, &searched),
                         windowsPluginDir() + "\\passing_test.dll"))
        << searched;
}

TEST(WindowsPaths, PluginPathIsSplitOnSemicolons) {
    // Split on ':' (the drive letters' colons), the plug-ins' folder would be read as
    // "\work\...\plugins;C" and not be found.
    const std::string list = windowsPluginDir() + ";C:\\no\\such\\folder";
    ASSERT_EQ(_putenv_s("RTF_PLUGIN_PATH", list.c_str()), 0);
    std::string searched;
    const std::string found = findPlugin("failing_test", "", &searched);
    _putenv_s("RTF_PLUGIN_PATH", "");
    EXPECT_TRUE(sameFile(found, windowsPluginDir() + "\\libfailing_test.dll")) << searched;
}

TEST(WindowsPaths, TestIdOfADriveLetterPluginIsRelativeToTheSuitesFolder) {
    EXPECT_EQ(pluginIdPart("C:\\proj\\suites\\arm\\x.dll", "C:\\proj\\suites"), "arm/x.dll");
    EXPECT_EQ(pluginIdPart("C:\\proj\\build\\x.dll", "C:\\proj\\suites"), "x.dll");
    EXPECT_EQ(pluginIdPart("D:\\proj\\suites\\x.dll", "C:\\proj\\suites"), "x.dll");
    EXPECT_EQ(pluginIdPart("arm\\x.dll", "C:\\proj\\suites"), "arm/x.dll");
}
