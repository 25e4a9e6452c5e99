// A user's fixture manager: its setup fails unless its param says --world ready.
#ifndef WORLD_FIXTURE_H
#define WORLD_FIXTURE_H

#include <robottestingframework/FixtureManager.h>

class WorldFixture : public robottestingframework::FixtureManager {
public:
    bool setup(int argc, char** argv) override;
    void tearDown() override;
};

#endif
