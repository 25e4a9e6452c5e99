#include "web/whole_answer.h"

namespace robottestingframework {
namespace web {

// Winsock has no option that holds a connection's writes until it closes; RTF 2.x's /status
// test, the one client known to need it, runs on POSIX systems only.
void holdAnswerUntilClosed(const std::string&, int, const std::string&, int) {}

}  // namespace web
}  // namespace robottestingframework
