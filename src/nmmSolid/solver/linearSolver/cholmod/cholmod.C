#include "nmmSolid/solver/linearSolver/cholmod/cholmod.H"

#include <Eigen/CholmodSupport>
#include <cholmod.h>

#include <dlfcn.h>

#include <cmath>

namespace nmm
{

addToRunTimeSelectionTable(linearSolver, cholmod, "cholmod");


namespace
{

//- Eigen keeps the cholmod_factor protected; the failing column, the
//  permutation and the diagonal are read from it
class supernodalLLT
:
    public Eigen::CholmodSupernodalLLT<linearSolver::sparseMatrix, Eigen::Lower>
{
public:
    const cholmod_factor* factor() const { return this->m_cholmodFactor; }
};


const char* orderingName(int ordering)
{
    switch (ordering)
    {
        case CHOLMOD_NATURAL: return "natural";
        case CHOLMOD_GIVEN:   return "given";
        case CHOLMOD_AMD:     return "AMD";
        case CHOLMOD_METIS:   return "METIS";
        case CHOLMOD_NESDIS:  return "NESDIS";
        case CHOLMOD_COLAMD:  return "COLAMD";
        case CHOLMOD_POSTORDERED: return "postordered";
        default:              return "unknown";
    }
}

//- OpenMP's parallel regions inactive while it lives (see the
//  Description), and the setting as it was after: a host process (the
//  FMU's importer) keeps its own. The functions are looked up where
//  CHOLMOD loaded them: a CHOLMOD built without OpenMP needs nothing, and
//  the library is not compiled with -fopenmp (which would thread Eigen's
//  dense products as well)
class serialOpenMP
{
    using getLevels = int (*)();
    using setLevels = void (*)(int);
    static getLevels get() { return reinterpret_cast<getLevels>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels")); }
    static setLevels set() { return reinterpret_cast<setLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")); }
    int levels_ = -1;

public:
    serialOpenMP()
    {
        static const getLevels g = get();
        static const setLevels s = set();
        if (g && s)
        {
            levels_ = g();
            s(0);
        }
    }
    ~serialOpenMP()
    {
        static const setLevels s = set();
        if (levels_ >= 0) s(levels_);
    }
    serialOpenMP(const serialOpenMP&) = delete;
    serialOpenMP& operator=(const serialOpenMP&) = delete;
};

} // End anonymous namespace


struct cholmod::impl
{
    supernodalLLT llt;
};


cholmod::cholmod(const dictionary& dict)
:
    linearSolver("cholmod", dict),
    impl_(std::make_unique<impl>())
{
    auto& common = impl_->llt.cholmod();
    // A failure is reported by the exception, not by CHOLMOD's printing
    common.print = 0;
    // Larger supernodes than the default: see the Description
    constexpr std::size_t columns[3] = {32, 96, 256};
    constexpr double zeros[3] = {0.9, 0.3, 0.15};
    for (int i = 0; i < 3; ++i)
    {
        common.nrelax[i] = columns[i];
        common.zrelax[i] = zeros[i];
    }
}


cholmod::~cholmod() = default;


void cholmod::analyse(const sparseMatrix& K)
{
    impl_->llt.analyzePattern(K);
    if (impl_->llt.info() != Eigen::Success || !impl_->llt.factor())
    {
        throw fatalError("linearSolver cholmod: symbolic analysis failed"
            " (CHOLMOD status " + std::to_string(impl_->llt.cholmod().status)
            + ")");
    }
}


std::vector<long> cholmod::factorDofs() const
{
    // L L^T = K(p, p): factor column k is dof Perm[k]
    const cholmod_factor* L = impl_->llt.factor();
    const auto* perm = static_cast<const int*>(L->Perm);
    std::vector<long> dof(L->n);
    for (size_t k = 0; k < L->n; ++k) dof[k] = perm ? perm[k] : long(k);
    return dof;
}


Eigen::VectorXd cholmod::pivots() const
{
    // Supernode s holds columns super[s] .. super[s+1]-1 as a dense
    // column-major nsrow x nscol block at x + px[s]; its leading square is
    // the diagonal block
    const cholmod_factor* L = impl_->llt.factor();
    Eigen::VectorXd d = Eigen::VectorXd::Constant(L->n, -1.0);
    const auto* super = static_cast<const int*>(L->super);
    const auto* pi = static_cast<const int*>(L->pi);
    const auto* px = static_cast<const int*>(L->px);
    const auto* x = static_cast<const double*>(L->x);
    // Columns past a failed one were not computed
    const long nDone = static_cast<long>(L->minor);
    for (size_t s = 0; s < L->nsuper; ++s)
    {
        const long nsrow = pi[s + 1] - pi[s];
        for (long j = super[s]; j < super[s + 1] && j < nDone; ++j)
        {
            const double Ljj = x[px[s] + (j - super[s])*(nsrow + 1)];
            d(j) = Ljj*Ljj;
        }
    }
    return d;
}


void cholmod::factoriseNumeric(const sparseMatrix& K)
{
    auto& llt = impl_->llt;
    {
        const serialOpenMP serial;
        llt.factorize(K);
    }
    const cholmod_factor* L = llt.factor();
    if (!L || !L->is_super || L->xtype != CHOLMOD_REAL)
    {
        throw fatalError("linearSolver cholmod: numeric factorisation failed"
            " (CHOLMOD status " + std::to_string(llt.cholmod().status) + ")");
    }
    if (L->minor < L->n)
    {
        // CHOLMOD's first non-positive pivot; its value is not kept
        const long dof = factorDofs()[L->minor];
        throw singular(dof, std::nan(""), K.coeff(dof, dof));
    }
    checkPivots(pivots(), factorDofs(), K.diagonal());
}


Eigen::MatrixXd cholmod::solveFactorised(const Eigen::MatrixXd& f) const
{
    const serialOpenMP serial;
    return impl_->llt.solve(f);
}


std::string cholmod::ordering() const
{
    const cholmod_factor* L = impl_->llt.factor();
    return L ? orderingName(L->ordering) : "none";
}


double cholmod::factorisationWork() const
{
    // Column j of supernode s has the rows of s from j down
    const cholmod_factor* L = impl_->llt.factor();
    if (!L || !L->is_super) return 0;
    const auto* super = static_cast<const int*>(L->super);
    const auto* pi = static_cast<const int*>(L->pi);
    double work = 0;
    for (size_t s = 0; s < L->nsuper; ++s)
    {
        const long nsrow = pi[s + 1] - pi[s];
        for (long j = 0; j < super[s + 1] - super[s]; ++j)
        {
            const double c = double(nsrow - j);
            work += c*c;
        }
    }
    return work;
}


double cholmod::solveWork() const
{
    // A supernodal solve runs over the stored blocks, zeros and all, as
    // factorisationWork counts them
    const cholmod_factor* L = impl_->llt.factor();
    if (L && L->is_super) return 2.0*double(L->xsize);
    return linearSolver::solveWork();
}


long cholmod::factorNonZeros() const
{
    // lnz of the selected ordering: the true nonzeros, where the
    // supernodal storage (xsize) also holds explicit zeros
    return static_cast<long>(impl_->llt.cholmod().lnz);
}

} // End namespace nmm
