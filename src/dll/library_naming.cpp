#include "dll/library_naming.h"

#include "dll/shared_library.h"

// What every system shares: its names are read from its row (library_naming-<system>.cpp).
namespace robottestingframework {
namespace plugin {

const char* SharedLibrary::prefix() {
    return kLibraryNaming.prefix;
}

const char* SharedLibrary::suffix() {
    return kLibraryNaming.suffix;
}

const char* libraryPathVariable() {
    return kLibraryNaming.pathVariable;
}

char pathListSeparator() {
    return kLibraryNaming.pathListSeparator;
}

}  // namespace plugin
}  // namespace robottestingframework
