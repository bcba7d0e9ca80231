#include "nmmSolid/solver/sparsePattern/sparsePattern.H"

#include <algorithm>

namespace nmm
{

bool sparsePattern::matches(const sparseMatrix& A) const
{
    return A.rows() == rows_ && A.cols() == cols_
        && std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1,
                      outer_.begin(), outer_.end())
        && std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(),
                      inner_.begin(), inner_.end());
}


void sparsePattern::keep(const sparseMatrix& A)
{
    rows_ = A.rows();
    cols_ = A.cols();
    outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

} // End namespace nmm
