// Loading C++ plug-ins: the factory is found and used, and failures say why in the loader's words.
#include <gtest/gtest.h>

#include <string>

#include <robottestingframework/dll/DllPluginLoader.h>

#include "build_paths.h"

using robottestingframework::plugin::DllFixturePluginLoader;
using robottestingframework::plugin::DllPluginLoader;

namespace {

std::string plugin(const std::string& name) {
    return std::string(build_paths::testPluginDir()) + "/" + name + ".so";
}

}  // namespace

TEST(DllPluginLoader, MakesTheTestCaseThePluginDeclares) {
    DllPluginLoader loader;
    auto* test = loader.open(plugin("passing_test"));
    ASSERT_NE(test, nullptr) << loader.getLastError();
    EXPECT_EQ(test->getName(), "PassingTest");
    loader.close();
    EXPECT_EQ(loader.open(plugin("passing_test"))->getName(), "PassingTest") << "reopens";
}

TEST(DllPluginLoader, MissingFileGivesTheLoadersWordsAndTheFile) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open("/no/such/plugin.so"), nullptr);
    EXPECT_NE(loader.getLastError().find("/no/such/plugin.so"), std::string::npos);
    EXPECT_NE(loader.getLastError().find("No such file"), std::string::npos)
        << loader.getLastError();
}

TEST(DllPluginLoader, LibraryWithoutFactoryIsNotAPlugin) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(plugin("not_a_plugin")), nullptr);
    EXPECT_NE(loader.getLastError().find("is not a Robot Testing Framework plug-in"),
              std::string::npos)
        << loader.getLastError();
    EXPECT_NE(loader.getLastError().find("robottestingframework_plugin_abi"), std::string::npos)
        << "dlerror names the missing symbol: " << loader.getLastError();
}

TEST(DllPluginLoader, FixtureIsNotATestAndSaysSo) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(plugin("order_fixture")), nullptr);
    EXPECT_NE(loader.getLastError().find("it is a fixture plug-in"), std::string::npos)
        << loader.getLastError();

    DllFixturePluginLoader fixtures;
    EXPECT_NE(fixtures.open(plugin("order_fixture")), nullptr) << fixtures.getLastError();
    EXPECT_EQ(fixtures.open(plugin("passing_test")), nullptr);
    EXPECT_NE(fixtures.getLastError().find("it is a test plug-in"), std::string::npos)
        << fixtures.getLastError();
}

// The plug-in needs a stand-in of RTF 2.x's core library that aborts the process loading it:
// refused, it is never loaded, and the message says how to rebuild the plug-in.
TEST(DllPluginLoader, APluginBuiltAgainstRtf2IsRefusedBeforeLoading) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(plugin("built_against_rtf2")), nullptr);
    const std::string error = loader.getLastError();
    EXPECT_NE(error.find("built_against_rtf2.so' was built against RTF 2.x: it needs "
                         "librobottestingframework.so.2"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("compile unchanged against this version: rebuild it"), std::string::npos)
        << error;

    DllFixturePluginLoader fixtures;
    EXPECT_EQ(fixtures.open(plugin("built_against_rtf2")), nullptr);
    EXPECT_NE(fixtures.getLastError().find("was built against RTF 2.x"), std::string::npos)
        << fixtures.getLastError();
}
