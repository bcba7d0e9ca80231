#include "nmmSolid/solver/patternCache/patternCache.H"

#include "nmmSolid/solver/threadRanges/threadRanges.H"

#include <algorithm>

namespace nmm
{

bool patternCache::sameExtra(const sparseMatrix* extra) const
{
    // Its index arrays compared whole (a compressed matrix's): an entry at
    // a time cost a pile's step half a millisecond. An uncompressed one is
    // never taken for the same
    if (!extra) return !hasExtra_;
    if (!hasExtra_ || !extra->isCompressed()) return false;
    const std::size_t columns = std::size_t(extra->outerSize()) + 1;
    const std::size_t entries = std::size_t(extra->nonZeros());
    return extraOuter_.size() == columns && extraInner_.size() == entries
        && std::equal(extraOuter_.begin(), extraOuter_.end(), extra->outerIndexPtr())
        && std::equal(extraInner_.begin(), extraInner_.end(), extra->innerIndexPtr());
}


void patternCache::makePattern
(
    Eigen::Index rows,
    Eigen::Index cols,
    const sparseMatrix* extra
)
{
    std::vector<triplet> zeros;
    zeros.reserve(triplets_.size() + std::size_t(extra ? extra->nonZeros() : 0));
    positions_.resize(triplets_.size());
    for (std::size_t t = 0; t < triplets_.size(); ++t)
    {
        const triplet& x = triplets_[t];
        zeros.emplace_back(x.row(), x.col(), 0.0);
        positions_[t] = {x.row(), x.col()};
    }
    const std::size_t listed = zeros.size();
    for (int j = 0; extra && j < extra->outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(*extra, j); it; ++it)
        {
            zeros.emplace_back(int(it.row()), j, 0.0);
        }
    }
    matrix_.resize(rows, cols);
    matrix_.setFromTriplets(zeros.begin(), zeros.end());
    matrix_.makeCompressed();

    const int* inner = matrix_.innerIndexPtr();
    const int* outer = matrix_.outerIndexPtr();
    const auto slotOf = [&](const triplet& x)
    {
        return int(std::lower_bound(inner + outer[x.col()], inner + outer[x.col() + 1], x.row())
            - inner);
    };
    slots_.resize(listed);
    for (std::size_t t = 0; t < listed; ++t) slots_[t] = slotOf(zeros[t]);
    extraSlots_.resize(zeros.size() - listed);
    for (std::size_t k = listed; k < zeros.size(); ++k) extraSlots_[k - listed] = slotOf(zeros[k]);
    hasExtra_ = extra != nullptr;
    extraOuter_.clear();
    extraInner_.clear();
    if (extra && extra->isCompressed())
    {
        extraOuter_.assign(extra->outerIndexPtr(), extra->outerIndexPtr() + extra->outerSize() + 1);
        extraInner_.assign(extra->innerIndexPtr(), extra->innerIndexPtr() + extra->nonZeros());
    }
    gatherFor_ = 0;
    if (threaded_) makeGather();
}


void patternCache::makeGather()
{
    // Each range's triplets listed in list order: a thread reads its list
    // forwards and writes only its range
    std::vector<std::size_t> count(std::size_t(matrix_.nonZeros()), 0);
    for (const int s : slots_) ++count[std::size_t(s)];
    const std::vector<std::size_t> start = threadRanges(count);
    partStart_.assign(start.begin(), start.end());
    partTriplets_.assign(start.size() - 1, {});
    for (std::size_t t = 0; t < slots_.size(); ++t)
    {
        const auto p = std::upper_bound(partStart_.begin(), partStart_.end(), slots_[t])
            - partStart_.begin() - 1;
        partTriplets_[std::size_t(p)].push_back(int(t));
    }
    partExtra_.resize(partStart_.size());
    for (std::size_t p = 0; p < partStart_.size(); ++p)
    {
        partExtra_[p] = int(std::lower_bound(extraSlots_.begin(), extraSlots_.end(), partStart_[p])
            - extraSlots_.begin());
    }
    gatherFor_ = slots_.size();
}


bool patternCache::gather(const sparseMatrix* extra, double c)
{
    // The extra matrix's entries in its storage order, as sameExtra saw
    if (positions_.size() != triplets_.size() || (extra && !extra->isCompressed()))
    {
        return false;
    }
    if (gatherFor_ != triplets_.size()) makeGather();
    double* values = matrix_.valuePtr();
    const double* extraValues = extra ? extra->valuePtr() : nullptr;
    const long nParts = long(partTriplets_.size());
    bool same = true;
    #pragma omp parallel for schedule(static, 1) reduction(&&: same)
    for (long p = 0; p < nParts; ++p)
    {
        const std::size_t q = std::size_t(p);
        std::fill(values + partStart_[q], values + partStart_[q + 1], 0.0);
        for (const int t : partTriplets_[q])
        {
            const triplet& x = triplets_[std::size_t(t)];
            const auto& at = positions_[std::size_t(t)];
            same = same && at.first == x.row() && at.second == x.col();
            values[slots_[std::size_t(t)]] += x.value();
        }
        for (int k = partExtra_[q]; extraValues && k < partExtra_[q + 1]; ++k)
        {
            values[extraSlots_[std::size_t(k)]] += c*extraValues[k];
        }
    }
    return same;
}


bool patternCache::scatter()
{
    // The positions are checked in the same pass as the values are
    // summed: one pass over a list of a million entries, not two
    if (positions_.size() != triplets_.size()) return false;
    double* values = matrix_.valuePtr();
    std::fill(values, values + matrix_.nonZeros(), 0.0);
    for (std::size_t t = 0; t < triplets_.size(); ++t)
    {
        const triplet& x = triplets_[t];
        if (positions_[t].first != x.row() || positions_[t].second != x.col()) return false;
        values[slots_[t]] += x.value();
    }
    return true;
}


const patternCache::sparseMatrix& patternCache::assemble
(
    Eigen::Index rows,
    Eigen::Index cols,
    const sparseMatrix* extra,
    double c
)
{
    const bool kept = matrix_.rows() == rows && matrix_.cols() == cols && sameExtra(extra);
    if (kept && threaded_ && gather(extra, c))
    {
        ++reused_;
        return matrix_;
    }
    if (kept && !threaded_ && scatter())
    {
        ++reused_;
    }
    else
    {
        makePattern(rows, cols, extra);
        ++made_;
        scatter();
    }
    if (extra)
    {
        // After the list, in the extra matrix's order: as its entries
        // appended to the list would be summed
        double* values = matrix_.valuePtr();
        std::size_t k = 0;
        for (int j = 0; j < extra->outerSize(); ++j)
        {
            for (sparseMatrix::InnerIterator it(*extra, j); it; ++it)
            {
                values[extraSlots_[k++]] += c*it.value();
            }
        }
    }
    return matrix_;
}

} // End namespace nmm
