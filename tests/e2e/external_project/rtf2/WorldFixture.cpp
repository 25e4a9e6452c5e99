#include "WorldFixture.h"

#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

bool WorldFixture::setup(int argc, char** argv) {
    std::string world;
    robottestingframework::Arguments::getOption(argc, argv, "--world", world);
    ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("the world is " + world);
    return world == "ready";
}

void WorldFixture::tearDown() {
    ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("the world is gone");
}

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(WorldFixture)
