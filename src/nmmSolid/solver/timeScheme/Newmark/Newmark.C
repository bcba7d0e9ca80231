#include "nmmSolid/solver/timeScheme/Newmark/Newmark.H"

#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(timeScheme, Newmark, "Newmark");


const keywordTable& Newmark::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("Newmark", "Newmark-beta time integration");
        t.word("type", "time scheme").required();
        t.scalar("beta", "Newmark beta", "").defaultValue(0.25).range(0, 1)
            .notes("1/4 with gamma 1/2 is the trapezoidal rule; 1 with "
                   "gamma 3/2 damps the velocity of stiff (contact) modes "
                   "within a few steps");
        t.scalar("gamma", "Newmark gamma", "").defaultValue(0.5).range(0.5, 1.5);
        return t;
    }();
    return table;
}


Newmark::Newmark(double beta, double gamma)
:
    beta_(beta),
    gamma_(gamma)
{}


Newmark::Newmark(const dictionary& dict)
:
    Newmark
    (
        (keywords().validate(dict), keywords().get<double>(dict, "beta")),
        keywords().get<double>(dict, "gamma")
    )
{}


void Newmark::update
(
    const Eigen::VectorXd& dd,
    double dt,
    const Eigen::VectorXd& V0,
    const Eigen::VectorXd& A0,
    Eigen::VectorXd& V1,
    Eigen::VectorXd& A1
) const
{
    A1 = (dd - dt*V0 - dt*dt*(0.5 - beta_)*A0)/(beta_*dt*dt);
    V1 = V0 + dt*((1 - gamma_)*A0 + gamma_*A1);
}


std::string Newmark::name() const
{
    std::ostringstream os;
    os << "Newmark (beta " << beta_ << ", gamma " << gamma_ << ')';
    return os.str();
}

} // End namespace nmm
