#include "nmmSolid/solver/sparseLU/sparseLU.H"

#include <klu.h>

namespace nmm
{

struct sparseLU::klu
{
    klu_common common;
    klu_symbolic* symbolic = nullptr;
    klu_numeric* numeric = nullptr;

    klu()
    {
        klu_defaults(&common);
        common.btf = 0;
    }

    ~klu()
    {
        freeNumeric();
        if (symbolic) klu_free_symbolic(&symbolic, &common);
    }

    void freeNumeric()
    {
        if (numeric) klu_free_numeric(&numeric, &common);
    }

    // KLU's C interface takes the arrays it only reads as non-const
    static int* outer(const sparseMatrix& A) { return const_cast<int*>(A.outerIndexPtr()); }
    static int* inner(const sparseMatrix& A) { return const_cast<int*>(A.innerIndexPtr()); }
    static double* values(const sparseMatrix& A) { return const_cast<double*>(A.valuePtr()); }
};


sparseLU::sparseLU()
:
    klu_(std::make_unique<klu>())
{}


sparseLU::~sparseLU() = default;


void sparseLU::analyse(const sparseMatrix& A)
{
    klu_->freeNumeric();
    if (klu_->symbolic) klu_free_symbolic(&klu_->symbolic, &klu_->common);
    pattern_.forget();
    klu_->symbolic = klu_analyze(int(A.rows()), klu::outer(A), klu::inner(A), &klu_->common);
    if (klu_->symbolic) pattern_.keep(A);
    ++analyses_;
}


bool sparseLU::factoriseWithPivoting(const sparseMatrix& A)
{
    klu_->freeNumeric();
    klu_->numeric = klu_factor
    (
        klu::outer(A), klu::inner(A), klu::values(A), klu_->symbolic, &klu_->common
    );
    ++factorisations_;
    if
    (
        klu_->numeric && klu_->common.status == KLU_OK
     && klu_rcond(klu_->symbolic, klu_->numeric, &klu_->common)
    )
    {
        rcond_ = klu_->common.rcond;
        return true;
    }
    // A failed factor must not be refactorised next time
    klu_->freeNumeric();
    return false;
}


bool sparseLU::refactorise(const sparseMatrix& A)
{
    ++refactorisations_;
    return klu_refactor(klu::outer(A), klu::inner(A), klu::values(A),
                        klu_->symbolic, klu_->numeric, &klu_->common)
        && klu_rcond(klu_->symbolic, klu_->numeric, &klu_->common)
        && klu_->common.rcond >= refactorRcond*rcond_;
}


bool sparseLU::factorise(const sparseMatrix& A)
{
    if (!pattern_.matches(A)) analyse(A);
    if (!klu_->symbolic) return false;
    if (klu_->numeric && refactorise(A)) return true;
    return factoriseWithPivoting(A);
}


bool sparseLU::solveInPlace(Eigen::VectorXd& x)
{
    if (!klu_->numeric) return false;
    return klu_solve(klu_->symbolic, klu_->numeric, int(x.size()), 1, x.data(), &klu_->common)
        && x.allFinite();
}

} // End namespace nmm
