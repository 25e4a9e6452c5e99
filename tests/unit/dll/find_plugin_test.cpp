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

TEST_F(FindPlugin, NotFoundSaysWhereItLooked) {
    std::string searched;
    EXPECT_EQ(findPlugin("nothing_here", dir_.string(), &searched), "");
    EXPECT_NE(searched.find("libnothing_here.so"), std::string::npos) << searched;
    EXPECT_NE(searched.find(" in " + dir_.string() + ", "), std::string::npos) << searched;
    EXPECT_NE(searched.find("/usr/lib"), std::string::npos) << searched;

    // Beside a folder given relative, the folder is said as it is, not as ".".
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(dir_);
    EXPECT_EQ(findPlugin("nothing_here", ".", &searched), "");
    std::filesystem::current_path(here);
    EXPECT_NE(searched.find(" in " + std::filesystem::canonical(dir_).string() + ", "),
              std::string::npos)
        << searched;

    EXPECT_EQ(findPlugin("sub/missing.so", dir_.string(), &searched), "");
    EXPECT_NE(searched.find("sub/missing.so"), std::string::npos) << searched;
}
