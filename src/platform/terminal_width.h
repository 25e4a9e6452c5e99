// The width of the terminal a stream writes to.
#pragma once

#include <cstddef>
#include <cstdio>

namespace robottestingframework {
namespace platform {

// Its columns; `fallback` when the stream is no terminal or the width cannot be told.
std::size_t terminalWidth(std::FILE* stream, std::size_t fallback);

}  // namespace platform
}  // namespace robottestingframework
