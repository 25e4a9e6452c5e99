// A fixture header written the RTF 2.x way: it includes FixtureManager.h only and names the base
// class unqualified, relying on the `using namespace` of the file that includes it.
#pragma once

#include <robottestingframework/FixtureManager.h>

class Rtf2HeaderFixture : public FixtureManager {
public:
    bool setup(int argc, char** argv) override;
    void tearDown() override;

private:
    TestResult* unused_ = nullptr;  // TestResult came along with FixtureManager.h in RTF 2.x
};
