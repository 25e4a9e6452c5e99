// A fixture plug-in as RTF 2.x's ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN made it: only the
// SHLIBPP factory robottestingframework_fixture_factory.
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/dll/SharedLibraryClass.h>

using namespace robottestingframework;

class Rtf2ShlibppFixture : public FixtureManager {
public:
    bool setup(int, char**) override { return getParam() != "--refuse"; }
};

SHLIBPP_DEFINE_SHARED_SUBCLASS(robottestingframework_fixture_factory, Rtf2ShlibppFixture,
                               FixtureManager)
