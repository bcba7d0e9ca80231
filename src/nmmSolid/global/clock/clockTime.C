#include "nmmSolid/global/clock/clockTime.H"

#include <cstdio>
#include <ctime>

namespace nmm
{

namespace
{

std::string formatNow(const char* format)
{
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char buf[64];
    const std::size_t n = std::strftime(buf, sizeof(buf), format, &local);
    return std::string(buf, n);
}

} // End anonymous namespace


double clockTime::elapsed() const
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start_
    ).count();
}


long long clockTime::elapsedSeconds() const
{
    return std::chrono::duration_cast<std::chrono::seconds>
    (
        std::chrono::steady_clock::now() - start_
    ).count();
}


std::string clockTime::date()
{
    // %b is locale dependent; the banner is always in the C locale's English
    static const char* months[] =
    {
        "Jan", "Feb", "Mar", "Apr", "May", "Jun",
        "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"
    };
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%s %02d %d",
        months[local.tm_mon], local.tm_mday, 1900 + local.tm_year);
    return buf;
}


std::string clockTime::clockTimeOfDay()
{
    return formatNow("%H:%M:%S");
}

} // End namespace nmm
