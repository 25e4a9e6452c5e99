// The fork server's side: a process that has loaded no user code, started once per run. It
// forks the workers of the run's tests and fixtures, each one ahead of time (a spare, waiting
// for its request); it tells the runner each worker's pid and, later, how it ended. When the
// runner goes (even killed with SIGKILL), it freezes and kills every process the run started,
// then exits.
//
// It keeps two spares handed to the runner: for each it sends the runner a note
// (SpareNote::Announced, wire_format.h) with the spare's end of a socket pair. The runner sends
// a test's request straight to one of them, so that a fork in progress here never holds a test
// up, then claims it (SpareNote::Claimed) with the status pipe, on which the server writes
// Started and, once the worker ended, Exited (at the claim, if it ended before). A request sent
// to the server itself (script tests, below, or when no spare came) is handed to a spare
// forked then.
#pragma once

namespace robottestingframework {
namespace isolation {

// Script tests (Python, Lua, Ruby) are not forked from the server itself: the first request of
// a language starts a language server, a child that pre-starts that runtime (the interpreter
// initialised, its `robottestingframework` module ready, no user code loaded) and then serves
// that language's requests as the server does, each worker a fork of it (two spares forked
// ahead, each rehearsing a test: kLanguageSpares). So a test still gets a fresh module state
// and a process of its own, without paying for the start of the interpreter. The language
// server is refused (and its tests take the plain path, the worker starting the runtime) when
// the runtime cannot be pre-started or leaves a thread running besides the one that forks (a
// fork keeps only the calling thread; Ruby's VM thread runs the language server's loop itself,
// see LanguageModule::host), or when RTF_PRESTART=0. A request stays the server's until its
// language server says it took it, so one sent as that process dies takes the plain path. With
// `verbose`, which languages got one (or why not) is said on stderr.
//
// Serves requests read from `control` (a packet socket) until the runner closes it or dies.
// Returns the process exit code.
int serveForkRequests(int control, bool verbose = false);

}  // namespace isolation
}  // namespace robottestingframework
