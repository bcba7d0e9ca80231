#include "nmmSolid/functionObjects/energy/energy.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <Eigen/LU>

namespace nmm
{

addToRunTimeSelectionTable(functionObject, energy, "energy");


const keywordTable& energy::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t
        (
            "energy",
            "kinetic, strain and contact energy, work of the external loads"
        );
        t.include(functionObject::commonKeywords());
        return t;
    }();
    return table;
}


energy::energy
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
:
    functionObject(name, runTime, model, dict, "energy", keywords())
{
    writeHeader({"time", "kinetic", "strain", "contact", "work", "total"});
}


double energy::kinetic() const
{
    const auto& M = model_.assembler().mass();
    if (!model_.scheme().dynamic() || M.nonZeros() == 0) return 0;
    const Eigen::VectorXd& V = model_.state().V;
    return 0.5*V.dot(model_.assembler().massTimes(V));
}


double energy::strain() const
{
    const nmmAssembler& a = model_.assembler();
    const manifoldSpace& space = model_.space();
    const Eigen::Matrix2Xd patchD = model_.patchDisplacements();
    const auto& sigma = model_.state().sigma;
    if (compliance_.size() != sigma.size())
    {
        compliance_.resize(sigma.size());
        for (std::size_t e = 0; e < sigma.size(); ++e)
        {
            compliance_[e] = a.material(nmmAssembler::label(e)).D.inverse();
        }
    }
    // Each element's on OpenMP's threads, summed in order on one
    std::vector<double> part(sigma.size(), 0.0);
    std::vector<char> stressed(sigma.size(), 0);
    const long nE = long(sigma.size());
    #pragma omp parallel for schedule(static) if (a.threadsElements())
    for (long n = 0; n < nE; ++n)
    {
        const std::size_t e = std::size_t(n);
        const auto label = nmmAssembler::label(e);
        const Eigen::Vector3d s = sigma[e].head<3>();
        // An unstressed element (a fixed block's) holds no energy
        if (s.isZero(0)) continue;
        stressed[e] = 1;
        const double area = space.currentArea(label, space.currentTriangle(label, patchD));
        part[e] = 0.5*s.dot(compliance_[e]*s)*area;
    }
    double sum = 0;
    for (std::size_t e = 0; e < part.size(); ++e)
    {
        if (stressed[e]) sum += part[e];
    }
    return sum*a.thickness();
}


double energy::contact() const
{
    const contactModel* c = model_.contacts();
    return c ? c->energy(model_.state().contacts) : 0.0;
}


void energy::accumulateWork()
{
    const solidState& s = model_.state();
    Eigen::VectorXd f1 = model_.assembler().externalForces(s, s.time);
    if (started_)
    {
        work_ += 0.5*(f0_ + f1).dot(s.D - D0_);
    }
    started_ = true;
    f0_ = std::move(f1);
    D0_ = s.D;
}


void energy::execute()
{
    accumulateWork();
    const double k = kinetic(), e = strain(), c = contact();
    writeRow({model_.time(), k, e, c, work_, k + e + c - work_});
}

} // End namespace nmm
