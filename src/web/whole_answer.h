// One answer leaves in one piece. RTF 2.x's clients of /status read its answer with a single
// read() of at most 255 bytes (RTF 2.0.1's own WebProgListener test does), while the web
// server writes an answer's headers and its body with two writes: a client woken between them
// reads the headers alone (6 % of the runs of that test here). So the connection of such a
// request holds what is written until it closes (TCP_CORK on Linux, TCP_NOPUSH where that is
// what the system has), and closing it sends the whole answer at once. One header;
// whole_answer-posix.cpp and whole_answer-windows.cpp (nothing held there).
#pragma once

#include <string>

namespace robottestingframework {
namespace web {

// Holds what this process writes to the TCP connection from `localAddress`:`localPort` to
// `remoteAddress`:`remotePort` (as the web server names them) until it is closed. For a
// connection that closes after its answer only: anything held is otherwise sent up to 200 ms
// late. Nothing happens when the connection is not found.
void holdAnswerUntilClosed(const std::string& localAddress, int localPort,
                           const std::string& remoteAddress, int remotePort);

}  // namespace web
}  // namespace robottestingframework
