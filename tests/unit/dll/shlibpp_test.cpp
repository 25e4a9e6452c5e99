// RTF 2.x's shlibpp (dll/SharedLibrary*.h, dll/Vocab.h) and its plug-ins: libraries built with
// RTF 2.x's macros load through the framework's loaders, and ours load through shlibpp.
#include <gtest/gtest.h>

#include <string>

#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/DllFixturePluginLoader.h>
#include <robottestingframework/dll/DllPluginLoader.h>
#include <robottestingframework/dll/Plugin.h>
#include <robottestingframework/dll/SharedLibrary.h>
#include <robottestingframework/dll/SharedLibraryClass.h>
#include <robottestingframework/dll/SharedLibraryClassFactory.h>
#include <robottestingframework/dll/Vocab.h>

#include "build_paths.h"

using robottestingframework::FixtureManager;
using robottestingframework::TestCase;
using robottestingframework::plugin::DllFixturePluginLoader;
using robottestingframework::plugin::DllPluginLoader;

namespace {

std::string plugin(const std::string& name) {
    return std::string(build_paths::testPluginDir()) + "/" + name + ".so";
}

}  // namespace

TEST(Vocab, EncodesUpToFourCharactersFirstInTheLowByte) {
    EXPECT_EQ(shlibpp::VOCAB('o', 'k'), 'o' + ('k' << 8));
    EXPECT_EQ(shlibpp::Vocab::encode("SHPP"), shlibpp::VOCAB('S', 'H', 'P', 'P'));
    EXPECT_EQ(shlibpp::Vocab::encode("PLUGIN"), shlibpp::VOCAB('P', 'L', 'U', 'G'));
    EXPECT_EQ(shlibpp::Vocab::decode(shlibpp::VOCAB('f', 'a', 'c', 't')), "fact");
    EXPECT_EQ(shlibpp::Vocab::decode(shlibpp::Vocab::encode("ok")), "ok");
    EXPECT_EQ(shlibpp::Vocab::decode(0), "");
}

TEST(SharedLibrary, OpensFindsSymbolsAndSaysWhyNot) {
    shlibpp::SharedLibrary library;
    EXPECT_FALSE(library.isValid());
    EXPECT_FALSE(library.open("/no/such/library.so"));
    EXPECT_NE(library.error().find("/no/such/library.so"), std::string::npos) << library.error();
    ASSERT_TRUE(library.open(plugin("passing_test").c_str())) << library.error();
    EXPECT_TRUE(library.isValid());
    EXPECT_NE(library.getSymbol(ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME), nullptr);
    EXPECT_EQ(library.getSymbol("no_such_symbol"), nullptr);
    EXPECT_NE(library.error().find("no_such_symbol"), std::string::npos) << library.error();
    EXPECT_TRUE(library.close());
    EXPECT_FALSE(library.isValid());
}

TEST(SharedLibraryFactory, StatusSaysWhatFailed) {
    shlibpp::SharedLibraryFactory missing("/no/such/library.so",
                                          ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME);
    EXPECT_FALSE(missing.isValid());
    EXPECT_EQ(missing.getStatus(), shlibpp::SharedLibraryFactory::STATUS_LIBRARY_NOT_FOUND);

    shlibpp::SharedLibraryFactory noFactory(plugin("not_a_plugin").c_str(),
                                            ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME);
    EXPECT_EQ(noFactory.getStatus(), shlibpp::SharedLibraryFactory::STATUS_FACTORY_NOT_FOUND);
    EXPECT_NE(noFactory.getError().find("not_a_plugin.so"), std::string::npos)
        << noFactory.getError();

    // A symbol that is not a factory (our ABI function) is caught, not trusted.
    shlibpp::SharedLibraryFactory wrong(plugin("passing_test").c_str(),
                                        "robottestingframework_plugin_abi");
    EXPECT_EQ(wrong.getStatus(), shlibpp::SharedLibraryFactory::STATUS_FACTORY_NOT_FUNCTIONAL);
}

TEST(SharedLibraryClassFactory, MakesOurPluginsTestsAsRtf2ProgramsDid) {
    shlibpp::SharedLibraryClassFactory<TestCase> factory(plugin("passing_test").c_str(),
                                                         ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME);
    ASSERT_TRUE(factory.isValid()) << factory.getError();
    EXPECT_EQ(factory.getStatus(), shlibpp::SharedLibraryFactory::STATUS_OK);
    EXPECT_EQ(factory.getName(), ROBOTTESTINGFRAMEWORK_PLUGIN_FACTORY_NAME);
    EXPECT_NE(factory.getBaseClassName().find("TestCase"), std::string::npos);
    EXPECT_EQ(factory.getReferenceCount(), 1);
    {
        shlibpp::SharedLibraryClass<TestCase> test(factory);
        ASSERT_TRUE(test.isValid());
        EXPECT_EQ(test->getName(), "PassingTest");
        EXPECT_EQ(factory.getReferenceCount(), 2);
    }
    EXPECT_EQ(factory.getReferenceCount(), 1) << "the object went back to its factory";
}

TEST(SharedLibraryClassFactory, MakesOurPluginsFixtures) {
    shlibpp::SharedLibraryClassFactory<FixtureManager> factory(
        plugin("order_fixture").c_str(), ROBOTTESTINGFRAMEWORK_FIXTURE_FACTORY_NAME);
    ASSERT_TRUE(factory.isValid()) << factory.getError();
    shlibpp::SharedLibraryClass<FixtureManager> fixture(factory);
    EXPECT_TRUE(fixture.isValid());
}

TEST(DllPluginLoader, LoadsAPluginBuiltWithRtf2Macros) {
    DllPluginLoader loader;
    TestCase* test = loader.open(plugin("rtf2_shlibpp_test"));
    ASSERT_NE(test, nullptr) << loader.getLastError();
    EXPECT_EQ(test->getName(), "Rtf2ShlibppTest");
    loader.close();
}

TEST(DllPluginLoader, Rtf2FixturePluginGivenAsATestSaysWhatItIs) {
    DllPluginLoader loader;
    EXPECT_EQ(loader.open(plugin("rtf2_shlibpp_fixture")), nullptr);
    EXPECT_NE(loader.getLastError().find("it is a fixture plug-in"), std::string::npos)
        << loader.getLastError();
}

TEST(DllFixturePluginLoader, LoadsAFixtureBuiltWithRtf2Macros) {
    DllFixturePluginLoader loader;
    FixtureManager* fixture = loader.open(plugin("rtf2_shlibpp_fixture"));
    ASSERT_NE(fixture, nullptr) << loader.getLastError();
    char name[] = "f";
    char* argv[] = {name};
    EXPECT_TRUE(fixture->setup(1, argv));
    loader.close();
}

TEST(DllFixturePluginLoader, LibraryWithoutFactoryNamesTheFile) {
    DllFixturePluginLoader loader;
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(loader.open(plugin("not_a_plugin")), nullptr);
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
    EXPECT_NE(loader.getLastError().find("not_a_plugin.so"), std::string::npos)
        << loader.getLastError();
}
