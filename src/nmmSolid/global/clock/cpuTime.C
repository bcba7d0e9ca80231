#include "nmmSolid/global/clock/cpuTime.H"

#include <ctime>

namespace nmm
{

double cpuTime::now()
{
    // std::clock() wraps after 72 minutes where clock_t is 32 bits wide;
    // the POSIX process clock does not
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9*double(ts.tv_nsec);
}

} // End namespace nmm
