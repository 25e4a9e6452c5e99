// An RTF 2.x fixture plug-in (examples/fixture-plugin).
#include <cstdio>

#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class DemoFixture : public FixtureManager {
public:
    bool setup(int argc, char** argv) override {
        std::printf("demo fixture: setup with %d argument(s)\n", argc);
        return argc > 0 && std::string(argv[0]) == "--ready";  // RTF 2.x: no name first
    }
    void tearDown() override { std::printf("demo fixture: tear down\n"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(DemoFixture)
