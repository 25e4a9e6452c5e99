#include "languages/ruby/ruby_vm.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>

#include <ruby.h>
#include <ruby/encoding.h>

namespace robottestingframework {
namespace languages {

void defineRubyModule();  // ruby_loader.cpp

namespace {

// Signals whose handling belongs to the host program, not to Ruby.
const int kHostSignals[] = {SIGINT,  SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGPIPE,
                            SIGCHLD, SIGSEGV, SIGBUS, SIGILL,  SIGFPE,  SIGABRT, SIGSYS};

class VmThread {
public:
    static VmThread& instance() {
        static VmThread* thread = new VmThread;  // never destroyed, like the VM
        return *thread;
    }

    void run(const std::function<void()>& job) {
        if (pthread_equal(pthread_self(), thread_)) {
            job();
            return;
        }
        if (::getpid() != pid_) {
            throw std::runtime_error("Ruby was started before this process forked");
        }
        // One job at a time: callers from other threads queue here.
        std::lock_guard<std::mutex> turn(callMutex_);
        std::unique_lock<std::mutex> lock(mutex_);
        job_ = &job;
        error_ = nullptr;
        wake_.notify_all();
        done_.wait(lock, [this] { return job_ == nullptr; });
        std::exception_ptr error = error_;
        lock.unlock();
        if (error) {
            std::rethrow_exception(error);
        }
    }

private:
    VmThread() : pid_(::getpid()) {
        pthread_attr_t attributes;
        pthread_attr_init(&attributes);
        pthread_attr_setstacksize(&attributes, 16 * 1024 * 1024);  // Ruby recurses deeply
        // Signals stay with the host's threads (Ruby's own timer thread inherits this mask).
        sigset_t host;
        sigemptyset(&host);
        for (int signal :
             {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGUSR1, SIGUSR2, SIGPIPE, SIGCHLD}) {
            sigaddset(&host, signal);
        }
        sigset_t previous;
        pthread_sigmask(SIG_BLOCK, &host, &previous);
        pthread_create(&thread_, &attributes, &VmThread::main, this);
        pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        pthread_attr_destroy(&attributes);
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return started_; });
    }

    static void* main(void* self) {
        static_cast<VmThread*>(self)->loop();
        return nullptr;
    }

    void loop() {
        RUBY_INIT_STACK;  // the bottom of every Ruby call: this thread's first frame
        struct sigaction saved[sizeof kHostSignals / sizeof kHostSignals[0]];
        for (std::size_t i = 0; i < sizeof kHostSignals / sizeof kHostSignals[0]; ++i) {
            sigaction(kHostSignals[i], nullptr, &saved[i]);
        }
        ruby_setup();
        // What `ruby` does before it runs a script, on an empty one that is never run: the load
        // path, RUBYOPT, and the core methods written in Ruby (Kernel#class, Dir.glob,
        // GC.start...), which ruby_setup() alone leaves out. Rubygems is loaded by the first
        // require that needs it (defineRubyModule), not by every test.
        char program[] = "ruby", noGems[] = "--disable-gems", script[] = "-e", empty[] = "";
        char* arguments[] = {program, noGems, script, empty};
        ruby_options(4, arguments);
        ruby_script("robottestingframework");
        // Files and strings read by scripts are UTF-8, as with ruby itself on a UTF-8 system,
        // whatever the runner's locale (it never calls setlocale: Ruby would see ASCII-8BIT).
        rb_enc_set_default_external(rb_enc_from_encoding(rb_utf8_encoding()));
        // Ruby installs handlers for Ctrl-C, SIGTERM, SIGSEGV...: the host keeps its own.
        for (std::size_t i = 0; i < sizeof kHostSignals / sizeof kHostSignals[0]; ++i) {
            sigaction(kHostSignals[i], &saved[i], nullptr);
        }
        defineRubyModule();
        std::unique_lock<std::mutex> lock(mutex_);
        started_ = true;
        done_.notify_all();
        for (;;) {
            wake_.wait(lock, [this] { return job_ != nullptr; });
            const std::function<void()>* job = job_;
            lock.unlock();
            try {
                (*job)();
            } catch (...) {
                error_ = std::current_exception();
            }
            lock.lock();
            job_ = nullptr;
            done_.notify_all();
        }
    }

    pid_t pid_;
    pthread_t thread_{};
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    std::mutex callMutex_;
    const std::function<void()>* job_ = nullptr;
    std::exception_ptr error_;
    bool started_ = false;
};

}  // namespace

void RubyVm::run(const std::function<void()>& job) {
    VmThread::instance().run(job);
}

void RubyVm::start() {
    VmThread::instance();
}

pid_t RubyVm::fork() {
    pid_t pid = -1;
    run([&pid] {
        pid = ::fork();
        if (pid == 0) {
            rb_thread_atfork();
        }
    });
    return pid;
}

}  // namespace languages
}  // namespace robottestingframework
