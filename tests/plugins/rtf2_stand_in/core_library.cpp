// A stand-in for RTF 2.x's core library, librobottestingframework.so.2: loaded into a process,
// it ends it (as RTF 2.x's library clashing with this version's did, with SIGABRT). A plug-in
// needing it must be refused before anything is loaded.
#include <cstdlib>

extern "C" int rtf2_stand_in_version() {
    return 2;
}

namespace {

struct AbortWhenLoaded {
    AbortWhenLoaded() { std::abort(); }
};

const AbortWhenLoaded loaded;

}  // namespace
