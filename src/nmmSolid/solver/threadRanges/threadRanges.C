#include "nmmSolid/solver/threadRanges/threadRanges.H"

#include <algorithm>
#include <numeric>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace nmm
{

std::vector<std::size_t> threadRanges(const std::vector<std::size_t>& weights)
{
    std::size_t nParts = 1;
    #ifdef _OPENMP
    nParts = std::size_t(std::max(1, omp_get_max_threads()));
    #endif
    const std::size_t n = weights.size();
    const std::size_t total = std::accumulate(weights.begin(), weights.end(), std::size_t(0));
    std::vector<std::size_t> start(nParts + 1, n);
    start[0] = 0;
    std::size_t seen = 0, part = 1;
    for (std::size_t i = 0; i < n && part < nParts; ++i)
    {
        // Range part starts at the first item with part/nParts of the
        // weight before it
        while (part < nParts && seen*nParts >= total*part) start[part++] = i;
        seen += weights[i];
    }
    return start;
}

} // End namespace nmm
