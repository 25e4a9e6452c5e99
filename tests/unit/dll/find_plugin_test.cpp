// Finding plug-ins by path or bare name, like the platform finds libraries.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <robottestingframework/dll/DllPluginLoader.h>

#include "build_paths.h"

using robottestingframework::plugin::findPlugin;
namespace fs = std::filesystem;

namespace {

class FindPlugin : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("find_plugin_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "sub");
    }
    void TearDown() override { fs::remove_all(dir_); }
    void touch(const fs::path& path) { std::ofstream(path) << "x"; }
    fs::path dir_;
};

}  // namespace

TEST_F(FindPlugin, BareNameWithPrefixAndSuffixOmitted) {
    touch(dir_ / "libmotor.so");
    EXPECT_EQ(findPlugin("motor", dir_.string()), (dir_ / "libmotor.so").string());
    EXPECT_EQ(findPlugin("libmotor", dir_.string()), (dir_ / "libmotor.so").string());
    EXPECT_EQ(findPlugin("motor.so", dir_.string()), (dir_ / "libmotor.so").string());
    EXPECT_EQ(findPlugin("libmotor.so", dir_.string()), (dir_ / "libmotor.so").string());
}

TEST_F(FindPlugin, ExactNameWinsOverSpellings) {
    touch(dir_ / "check.py");
    touch(dir_ / "libcheck.py");
    EXPECT_EQ(findPlugin("check.py", dir_.string()), (dir_ / "check.py").string());
}

TEST_F(FindPlugin, RelativePathIsTakenFromTheSuiteFolder) {
    touch(dir_ / "sub" / "camera.py");
    EXPECT_EQ(findPlugin("sub/camera.py", dir_.string()), (dir_ / "sub" / "camera.py").string());
}

TEST_F(FindPlugin, LdLibraryPathIsSearched) {
    touch(dir_ / "sub" / "libonpath.so");
    const char* old = std::getenv("LD_LIBRARY_PATH");
    std::string saved = old != nullptr ? old : "";
    ::setenv("LD_LIBRARY_PATH", (dir_ / "sub").c_str(), 1);
    std::string found = findPlugin("onpath", "/nonexistent");
    if (old != nullptr) {
        ::setenv("LD_LIBRARY_PATH", saved.c_str(), 1);
    } else {
        ::unsetenv("LD_LIBRARY_PATH");
    }
    EXPECT_EQ(found, (dir_ / "sub" / "libonpath.so").string());
}

// RTF 2.x opened a script named bare in a suite (<test>arm_test.lua</test>) from the current
// folder; a shared library's bare name stays the loader's (never the current folder).
TEST_F(FindPlugin, ABareScriptNameIsFoundInTheCurrentFolderLast) {
    touch(dir_ / "arm_test.lua");
    touch(dir_ / "libgripper.so");
    touch(dir_ / "sub" / "beside.lua");
    touch(dir_ / "beside.lua");
    const auto here = fs::current_path();
    fs::current_path(dir_);
    const std::string script = findPlugin("arm_test.lua", (dir_ / "sub").string());
    const std::string library = findPlugin("libgripper.so", (dir_ / "sub").string());
    const std::string beside = findPlugin("beside.lua", (dir_ / "sub").string());
    fs::current_path(here);
    EXPECT_EQ(script, (dir_ / "arm_test.lua").string());
    EXPECT_EQ(library, "");
    EXPECT_EQ(beside, (dir_ / "sub" / "beside.lua").string());
}

TEST_F(FindPlugin, NotFoundSaysWhereItLooked) {
    std::string searched;
    EXPECT_EQ(findPlugin("nothing_here", dir_.string(), &searched), "");
    EXPECT_NE(searched.find("libnothing_here.so"), std::string::npos) << searched;
    EXPECT_NE(searched.find(" in the suite's folder " + dir_.string() + ";"), std::string::npos)
        << searched;
    EXPECT_NE(searched.find("/usr/lib"), std::string::npos) << searched;

    // Beside a folder given relative, the folder is said as it is, not as ".".
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(dir_);
    EXPECT_EQ(findPlugin("nothing_here", ".", &searched), "");
    std::filesystem::current_path(here);
    EXPECT_NE(
        searched.find(" in the suite's folder " + std::filesystem::canonical(dir_).string() + ";"),
        std::string::npos)
        << searched;

    EXPECT_EQ(findPlugin("sub/missing.so", dir_.string(), &searched), "");
    EXPECT_NE(searched.find("sub/missing.so"), std::string::npos) << searched;
}

TEST_F(FindPlugin, NotFoundNamesThePluginPathAndTheOptionThatWouldFindIt) {
    const char* old = std::getenv("RTF_PLUGIN_PATH");
    const std::string saved = old != nullptr ? old : "";
    ::unsetenv("RTF_PLUGIN_PATH");
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(dir_);
    std::string searched;
    EXPECT_EQ(findPlugin("gripper", "sub", &searched), "");
    EXPECT_NE(searched.find("in --plugin-path and RTF_PLUGIN_PATH: none given; in the library "
                            "path: "),
              std::string::npos)
        << searched;
    EXPECT_EQ(searched.find("below the working folder"), std::string::npos) << searched;

    // Built in a folder nothing searches: the message gives the option, relative to here.
    fs::create_directories(dir_ / "build" / "lib");
    fs::create_directories(dir_ / ".hidden");
    touch(dir_ / ".hidden" / "libgripper.so");
    touch(dir_ / "build" / "lib" / "libgripper.so");
    ::setenv("RTF_PLUGIN_PATH", "/nowhere/a:/nowhere/b", 1);
    EXPECT_EQ(findPlugin("gripper", "sub", &searched), "");
    std::filesystem::current_path(here);
    if (old != nullptr) {
        ::setenv("RTF_PLUGIN_PATH", saved.c_str(), 1);
    } else {
        ::unsetenv("RTF_PLUGIN_PATH");
    }
    EXPECT_NE(searched.find("in --plugin-path and RTF_PLUGIN_PATH: /nowhere/a, /nowhere/b;"),
              std::string::npos)
        << searched;
    EXPECT_NE(searched.find(". build/lib/libgripper.so is below the working folder: "
                            "--plugin-path build/lib (or RTF_PLUGIN_PATH=build/lib) finds it"),
              std::string::npos)
        << searched;
}
