// What goes wrong with a --history file: it is not a database, it is another program's
// database, it is newer than this runner, or it cannot be read or written. The message names
// the file and says which.
#pragma once

#include <stdexcept>
#include <string>

namespace robottestingframework {
namespace runner {

class HistoryError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace runner
}  // namespace robottestingframework
