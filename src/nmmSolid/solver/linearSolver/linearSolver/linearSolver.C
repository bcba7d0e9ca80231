#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"

#include <cmath>
#include <sstream>

namespace nmm
{

const keywordTable& linearSolver::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("linearSolver", "sparse SPD solve of K d = f");
        t.word("type", "back-end: cholmod or simplicialLDLT")
            .defaultValue("cholmod");
        t.scalar("pivotTolerance", "pivot / diagonal of K below which"
            " K counts as singular", "").defaultValue(1e-12).atLeast(0);
        return t;
    }();
    return table;
}


linearSolver::linearSolver(const std::string& name, const dictionary& dict)
:
    name_(name),
    pivotTolerance_(keywords().get<double>(dict, "pivotTolerance"))
{}


std::uint64_t linearSolver::hashPattern(const sparseMatrix& K)
{
    // FNV-1a over both index arrays: one pass, no copy of the pattern
    std::uint64_t h = 14695981039346656037ull;
    const auto mix = [&h](const auto* p, long n)
    {
        for (long i = 0; i < n; ++i)
        {
            h ^= static_cast<std::uint64_t>(p[i]);
            h *= 1099511628211ull;
        }
    };
    mix(K.outerIndexPtr(), K.outerSize() + 1);
    mix(K.innerIndexPtr(), K.nonZeros());
    return h;
}


bool linearSolver::samePattern(const sparseMatrix& K, std::uint64_t hash) const
{
    return rows_ == K.rows() && nonZeros_ == K.nonZeros()
        && patternHash_ == hash;
}


void linearSolver::checkSquare(const sparseMatrix& K)
{
    if (K.rows() != K.cols())
    {
        throw fatalError("linearSolver: the matrix is not square ("
            + std::to_string(K.rows()) + " x " + std::to_string(K.cols())
            + ")");
    }
}


void linearSolver::factorise(const sparseMatrix& K)
{
    checkSquare(K);
    // The hash and the back-ends need the compressed arrays
    sparseMatrix compressedCopy;
    const sparseMatrix* A = &K;
    if (!K.isCompressed())
    {
        compressedCopy = K;
        compressedCopy.makeCompressed();
        A = &compressedCopy;
    }

    factorised_ = false;
    const std::uint64_t hash = hashPattern(*A);
    if (!samePattern(*A, hash))
    {
        // Forget the old pattern first: a failed analysis must not be reused
        rows_ = -1;
        if (A->rows() > 0) analyse(*A);
        rows_ = A->rows();
        nonZeros_ = A->nonZeros();
        patternHash_ = hash;
        ++nAnalyses_;
    }
    ++nFactorisations_;
    if (A->rows() > 0) factoriseNumeric(*A);
    factorised_ = true;
}


void linearSolver::checkSolvable(long rows) const
{
    if (!factorised_)
    {
        throw fatalError("linearSolver " + name_ + ": solve() without a"
            " successful factorise()");
    }
    if (rows != rows_)
    {
        throw fatalError("linearSolver " + name_ + ": right-hand side of size "
            + std::to_string(rows) + " for a system of "
            + std::to_string(rows_) + " unknowns");
    }
}


Eigen::VectorXd linearSolver::solve(const Eigen::VectorXd& f) const
{
    checkSolvable(f.size());
    if (rows_ == 0) return Eigen::VectorXd();
    return solveFactorised(f);
}


Eigen::MatrixXd linearSolver::solveColumns(const Eigen::MatrixXd& F) const
{
    checkSolvable(F.rows());
    if (rows_ == 0 || F.cols() == 0) return Eigen::MatrixXd(F.rows(), F.cols());
    return solveFactorised(F);
}


singularSystem linearSolver::singular(long dof, double pivot, double diagonal) const
{
    // A NaN pivot: the back-end stopped without keeping the value
    const bool known = !std::isnan(pivot);
    const bool indefinite =
        known && pivot < 0 && -pivot > pivotTolerance_*std::abs(diagonal);
    std::ostringstream os;
    os.precision(6);
    os << "linearSolver " << name_ << ": the stiffness matrix is ";
    if (!known) os << "not positive definite (zero or negative pivot";
    else if (indefinite) os << "not positive definite (negative pivot " << pivot;
    else os << "singular (zero pivot " << pivot;
    os << ", diagonal " << diagonal << ") at dof " << dof << ".\n"
       << "    A block may be floating (no fixed point, contact or spring"
          " holds it), or a stiffness is negative.";
    return singularSystem(os.str(), dof, indefinite);
}


void linearSolver::checkPivots
(
    const Eigen::VectorXd& d,
    const std::vector<long>& originalDof,
    const Eigen::VectorXd& diagK
) const
{
    pivotRatio_ = 0;
    for (long k = 0; k < d.size(); ++k)
    {
        const long dof = originalDof[k];
        // Relative to K's diagonal, so that the test does not depend on
        // the units of the stiffness; a NaN pivot fails it too
        const double scale = std::abs(diagK(dof));
        if (!(d(k) > pivotTolerance_*scale))
        {
            throw singular(dof, d(k), diagK(dof));
        }
    }
    if (d.size()) pivotRatio_ = d.maxCoeff()/d.minCoeff();
}

} // End namespace nmm
