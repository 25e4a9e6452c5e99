// Windows: how a worker gets its WorkRequest without a fork server. The runner writes it on the
// worker's calls pipe as the fork server's request (encodeRequest) behind its length (u32,
// little-endian), as a wire record is framed; fixture calls follow as wire records.
#pragma once

#include <string>

#include "isolation/wire_format.h"

namespace robottestingframework {
namespace isolation {

std::string frameRequest(const WorkRequest& request);
// Reads one framed request from `fd` (blocking). False on end of file or garbage.
bool readRequest(int fd, WorkRequest& request);

}  // namespace isolation
}  // namespace robottestingframework
