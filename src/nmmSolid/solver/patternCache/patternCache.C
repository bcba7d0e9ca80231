#include "nmmSolid/solver/patternCache/patternCache.H"

#include <algorithm>

namespace nmm
{

bool patternCache::samePositions(Eigen::Index rows, Eigen::Index cols) const
{
    if
    (
        matrix_.rows() != rows || matrix_.cols() != cols
     || positions_.size() != triplets_.size()
    )
    {
        return false;
    }
    for (std::size_t t = 0; t < triplets_.size(); ++t)
    {
        const triplet& x = triplets_[t];
        if (positions_[t].first != x.row() || positions_[t].second != x.col()) return false;
    }
    return true;
}


void patternCache::makePattern(Eigen::Index rows, Eigen::Index cols)
{
    std::vector<triplet> zeros;
    zeros.reserve(triplets_.size());
    positions_.resize(triplets_.size());
    for (std::size_t t = 0; t < triplets_.size(); ++t)
    {
        const triplet& x = triplets_[t];
        zeros.emplace_back(x.row(), x.col(), 0.0);
        positions_[t] = {x.row(), x.col()};
    }
    matrix_.resize(rows, cols);
    matrix_.setFromTriplets(zeros.begin(), zeros.end());
    matrix_.makeCompressed();

    const int* inner = matrix_.innerIndexPtr();
    const int* outer = matrix_.outerIndexPtr();
    slots_.resize(triplets_.size());
    for (std::size_t t = 0; t < triplets_.size(); ++t)
    {
        const auto [i, j] = positions_[t];
        slots_[t] = int(std::lower_bound(inner + outer[j], inner + outer[j + 1], i) - inner);
    }
}


const patternCache::sparseMatrix& patternCache::assemble
(
    Eigen::Index rows,
    Eigen::Index cols
)
{
    if (samePositions(rows, cols))
    {
        ++reused_;
    }
    else
    {
        makePattern(rows, cols);
        ++made_;
    }
    double* values = matrix_.valuePtr();
    std::fill(values, values + matrix_.nonZeros(), 0.0);
    for (std::size_t t = 0; t < triplets_.size(); ++t) values[slots_[t]] += triplets_[t].value();
    return matrix_;
}

} // End namespace nmm
