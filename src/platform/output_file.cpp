#include "platform/output_file.h"

#include <cstdio>
#include <iostream>

// What every platform shares; the file and the descriptor operations are in
// output_file-<platform>.cpp.
namespace robottestingframework {
namespace platform {

void flushStandardStreams() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
}

}  // namespace platform
}  // namespace robottestingframework
