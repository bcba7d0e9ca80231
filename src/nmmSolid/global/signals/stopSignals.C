#include "nmmSolid/global/signals/stopSignals.H"

#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace nmm
{

namespace
{

// Only lock-free atomics and write()/_exit() are safe in a signal handler
std::atomic<int> stopSignal{0};
std::atomic<int> pendingExit{0};
std::atomic<int> guardDepth{0};

struct sigaction previousInt{};
struct sigaction previousTerm{};
bool installed = false;

static_assert(std::atomic<int>::is_always_lock_free);

void say(const char* text)
{
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    (void)ignored;
}

extern "C" void onStopSignal(int sig)
{
    int expected = 0;
    if (stopSignal.compare_exchange_strong(expected, sig))
    {
        say(sig == SIGINT
            ? "\nCaught SIGINT: the current time will be written and the run "
              "stopped at the end of this step (send it again to stop at once)\n"
            : "\nCaught SIGTERM: the current time will be written and the run "
              "stopped at the end of this step (send it again to stop at once)\n");
        return;
    }
    if (guardDepth.load() > 0)
    {
        pendingExit.store(sig);
        return;
    }
    say("\nSecond stop signal: exiting now\n");
    ::_exit(128 + sig);
}

} // End anonymous namespace


void stopSignals::install()
{
    if (installed) return;
    struct sigaction action{};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    // Slow system calls resume: a signal must not turn a write into an error
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &previousInt);
    sigaction(SIGTERM, &action, &previousTerm);
    installed = true;
}


void stopSignals::uninstall()
{
    if (!installed) return;
    sigaction(SIGINT, &previousInt, nullptr);
    sigaction(SIGTERM, &previousTerm, nullptr);
    installed = false;
}


bool stopSignals::requested()
{
    return stopSignal.load() != 0;
}


int stopSignals::signalNumber()
{
    return stopSignal.load();
}


std::string stopSignals::signalName(int sig)
{
    switch (sig)
    {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        default: return "signal " + std::to_string(sig);
    }
}


void stopSignals::request(int sig)
{
    int expected = 0;
    stopSignal.compare_exchange_strong(expected, sig);
}


void stopSignals::reset()
{
    stopSignal.store(0);
    pendingExit.store(0);
}


stopSignals::exitGuard::exitGuard()
{
    ++guardDepth;
}


stopSignals::exitGuard::~exitGuard()
{
    if (--guardDepth == 0)
    {
        const int sig = pendingExit.load();
        if (sig)
        {
            say("\nSecond stop signal: exiting now\n");
            ::_exit(128 + sig);
        }
    }
}

} // End namespace nmm
