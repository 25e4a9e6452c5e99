// The one Ruby VM of this process. Ruby can be started once and never finalized, and only the
// thread that started it may call it; so it lives on a thread of its own, started on first use,
// and every call into Ruby is a job handed to that thread.
#pragma once

#include <sys/types.h>

#include <functional>

namespace robottestingframework {
namespace languages {

class RubyVm {
public:
    // Runs `job` on the Ruby thread (starting it if needed) and waits for it; an exception
    // thrown by `job` is thrown here. Runs it directly when called from the Ruby thread.
    static void run(const std::function<void()>& job);

    // Starts the VM (for a process that forks a worker per test, see script_module_interface.h).
    static void start();
    // fork() from the Ruby thread (the child's only thread), Ruby told of it in the child as
    // its own fork does (rb_thread_atfork).
    static pid_t fork();
};

}  // namespace languages
}  // namespace robottestingframework
