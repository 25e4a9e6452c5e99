// The RTF 2.x fixture example's layout: Plugin.h, `using namespace`, then the fixture's header.
#include <cstdio>

#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

#include "rtf2_header_fixture.h"

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(Rtf2HeaderFixture)

bool Rtf2HeaderFixture::setup(int argc, char** argv) {
    std::fprintf(stderr, "rtf2 header fixture: setting up with %d argument(s), first %s\n", argc,
                 argv[0]);
    return unused_ == nullptr;
}

void Rtf2HeaderFixture::tearDown() {
    std::fprintf(stderr, "rtf2 header fixture: tearing down\n");
}
