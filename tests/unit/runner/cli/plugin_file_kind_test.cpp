// What kind of RTF plug-in a shared library file is (cli/plugin_file_kind.h), read from the
// names in the file: the test factory, the fixture factory, or neither.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "build_paths.h"
#include "runner/cli/plugin_file_kind.h"

using namespace robottestingframework::runner;
namespace fs = std::filesystem;

namespace {

// A literal's bytes, its \0s included.
template <std::size_t N>
std::string bytes(const char (&text)[N]) {
    return std::string(text, N - 1);
}

class PluginFileKindTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(build_paths::unitTestTmpDir()) /
               ("plugin_file_kind_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& bytes) {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path.string();
    }

    fs::path dir_;
};

}  // namespace

TEST_F(PluginFileKindTest, TheTestFactorysNameMakesATestPlugin) {
    EXPECT_EQ(pluginFileKind(write("libtest.so", bytes("\x7f"
                                                       "ELF\0robottestingframework_plugin_abi\0"
                                                       "robottestingframework_dll_factory\0"))),
              PluginFileKind::Test);
}

TEST_F(PluginFileKindTest, TheFixtureFactorysNameAloneMakesAFixturePlugin) {
    EXPECT_EQ(pluginFileKind(write("libfix.so", bytes("\x7f"
                                                      "ELF\0robottestingframework_plugin_abi\0"
                                                      "robottestingframework_fixture_factory\0"))),
              PluginFileKind::Fixture);
}

TEST_F(PluginFileKindTest, ALibraryWithNeitherNameIsOther) {
    EXPECT_EQ(pluginFileKind(write("libhelper.so", bytes("\x7f"
                                                         "ELF\0robot_helper_answer\0"))),
              PluginFileKind::Other);
    EXPECT_EQ(pluginFileKind((dir_ / "missing.so").string()), PluginFileKind::Other);
}

TEST_F(PluginFileKindTest, ANameAcrossTwoReadBlocksIsFound) {
    // The file is read in blocks of 1 MiB: the name starts a few bytes before the first ends.
    std::string bytes((1 << 20) - 10, 'x');
    bytes += "robottestingframework_dll_factory";
    bytes += std::string(100, 'y');
    EXPECT_EQ(pluginFileKind(write("libbig.so", bytes)), PluginFileKind::Test);
}
