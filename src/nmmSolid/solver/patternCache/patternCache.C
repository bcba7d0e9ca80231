#include "nmmSolid/solver/patternCache/patternCache.H"

#include <algorithm>

namespace nmm
{

namespace
{

//- Per column j of A, -1 - j, then its entries' rows
std::vector<int> patternOf(const Eigen::SparseMatrix<double>* A)
{
    std::vector<int> p;
    if (!A) return p;
    p.reserve(std::size_t(A->outerSize() + A->nonZeros()));
    for (int j = 0; j < A->outerSize(); ++j)
    {
        p.push_back(-1 - j);
        for (Eigen::SparseMatrix<double>::InnerIterator it(*A, j); it; ++it)
        {
            p.push_back(int(it.row()));
        }
    }
    return p;
}

} // End anonymous namespace


bool patternCache::sameExtra(const sparseMatrix* extra) const
{
    // Compared in patternOf's layout, without making a list of it
    if (!extra) return extraPattern_.empty();
    if (extraPattern_.size() != std::size_t(extra->outerSize() + extra->nonZeros()))
    {
        return false;
    }
    std::size_t p = 0;
    for (int j = 0; j < extra->outerSize(); ++j)
    {
        if (extraPattern_[p++] != -1 - j) return false;
        for (sparseMatrix::InnerIterator it(*extra, j); it; ++it)
        {
            if (extraPattern_[p++] != int(it.row())) return false;
        }
    }
    return true;
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
    extraPattern_ = patternOf(extra);
    bySlot_.clear();
    if (threaded_) makeGather();
}


void patternCache::makeGather()
{
    // A counting sort of the triplets by slot keeps each slot's in list
    // order
    const std::size_t nnz = std::size_t(matrix_.nonZeros());
    bySlotStart_.assign(nnz + 1, 0);
    for (const int s : slots_) ++bySlotStart_[std::size_t(s) + 1];
    for (std::size_t s = 0; s < nnz; ++s) bySlotStart_[s + 1] += bySlotStart_[s];
    std::vector<int> next(bySlotStart_.begin(), bySlotStart_.end() - 1);
    bySlot_.resize(slots_.size());
    for (std::size_t t = 0; t < slots_.size(); ++t)
    {
        bySlot_[std::size_t(next[std::size_t(slots_[t])]++)] = int(t);
    }
    extraOfSlot_.assign(nnz, -1);
    for (std::size_t k = 0; k < extraSlots_.size(); ++k)
    {
        extraOfSlot_[std::size_t(extraSlots_[k])] = int(k);
    }
}


bool patternCache::gather(const sparseMatrix* extra, double c)
{
    // The extra matrix's entries in its storage order, as sameExtra saw
    if (positions_.size() != triplets_.size() || (extra && !extra->isCompressed()))
    {
        return false;
    }
    if (bySlot_.size() != triplets_.size()) makeGather();
    double* values = matrix_.valuePtr();
    const double* extraValues = extra ? extra->valuePtr() : nullptr;
    const long nnz = long(matrix_.nonZeros());
    bool same = true;
    #pragma omp parallel for schedule(static) reduction(&&: same)
    for (long s = 0; s < nnz; ++s)
    {
        double v = 0.0;
        for (int k = bySlotStart_[std::size_t(s)]; k < bySlotStart_[std::size_t(s) + 1]; ++k)
        {
            const std::size_t t = std::size_t(bySlot_[std::size_t(k)]);
            const triplet& x = triplets_[t];
            same = same && positions_[t].first == x.row() && positions_[t].second == x.col();
            v += x.value();
        }
        const int e = extraOfSlot_[std::size_t(s)];
        if (extraValues && e >= 0) v += c*extraValues[e];
        values[s] = v;
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
