#include "nmmSolid/solver/timeScheme/DDA/DDA.H"

#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(timeScheme, DDA, "DDA");


const keywordTable& DDA::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("DDA", "Shi's scheme (Newmark beta 1/2, gamma 1, the"
            " acceleration constant over a step), with the start velocity of"
            " a step scaled; theta > 1/2 is Moreau and Jean's theta method");
        t.word("type", "time scheme").required();
        t.scalar("velocityRatio", "factor on the start velocity of a step:"
            " 0 static relaxation, 1 all momentum kept", "").required()
            .range(0, 1);
        t.scalar("deformationVelocityRatio", "factor on each block's velocity"
            " less its rigid motion after a step: 1 keeps it, 0 drops it (its"
            " elastic ringing), momentum and angular momentum kept", "")
            .defaultValue(1).range(0, 1);
        t.scalar("theta", "weight of the end velocity in the step's"
            " displacement: 1/2 Shi's DDA, 1 implicit Euler (a mode far"
            " faster than the step keeps (1 - theta)/theta of its velocity"
            " a step, reversed)", "").defaultValue(0.5).range(0.5, 1);
        return t;
    }();
    return table;
}


DDA::DDA(double velocityRatio, double deformationVelocityRatio, double theta)
:
    Newmark(theta, 1),
    velocityRatio_(velocityRatio),
    deformationVelocityRatio_(deformationVelocityRatio)
{}


DDA::DDA(const dictionary& dict)
:
    DDA
    (
        (keywords().validate(dict), keywords().get<double>(dict, "velocityRatio")),
        keywords().get<double>(dict, "deformationVelocityRatio"),
        keywords().get<double>(dict, "theta")
    )
{}


void DDA::update
(
    const Eigen::VectorXd& dd,
    double dt,
    const Eigen::VectorXd& V0,
    const Eigen::VectorXd&,
    Eigen::VectorXd& V1,
    Eigen::VectorXd& A1
) const
{
    // Dd = dt (theta V1 + (1 - theta) V0): the start's acceleration never
    // enters, so an impulsive step (a contact closing) leaves nothing
    // behind for the next one
    const double theta = beta();
    A1 = (dd - dt*V0)/(theta*dt*dt);
    V1 = V0 + dt*A1;
    V1 *= velocityRatio_;
}


std::string DDA::name() const
{
    std::ostringstream os;
    os << "DDA (velocityRatio " << velocityRatio_;
    if (deformationVelocityRatio_ < 1)
    {
        os << ", deformationVelocityRatio " << deformationVelocityRatio_;
    }
    if (beta() != 0.5) os << ", theta " << beta();
    os << ')';
    return os.str();
}

} // End namespace nmm
