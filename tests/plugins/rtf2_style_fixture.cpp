// A fixture manager written the way RTF 2.x fixture plug-ins are.
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class Rtf2StyleFixture : public FixtureManager {
public:
    Rtf2StyleFixture() {}
    virtual ~Rtf2StyleFixture() {}

    virtual bool setup(int argc, char** argv) {
        ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("rtf2 fixture is setting up the world");
        (void)argc;
        (void)argv;
        return true;
    }

    virtual bool check() {
        if (getDispatcher() == nullptr) {
            return false;  // an RTF 2.x fixture reports collapse through its dispatcher
        }
        return true;
    }

    virtual void tearDown() { ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("rtf2 fixture tore down"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(Rtf2StyleFixture)
