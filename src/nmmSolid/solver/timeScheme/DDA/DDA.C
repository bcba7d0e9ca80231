#include "nmmSolid/solver/timeScheme/DDA/DDA.H"

#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(timeScheme, DDA, "DDA");


const keywordTable& DDA::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("DDA", "Newmark beta 1/2, gamma 1, with the start"
            " velocity of a step scaled");
        t.word("type", "time scheme").required();
        t.scalar("velocityRatio", "factor on the start velocity of a step:"
            " 0 static relaxation, 1 all momentum kept", "").required()
            .range(0, 1);
        t.scalar("deformationVelocityRatio", "factor on each block's velocity"
            " less its rigid motion after a step: 1 keeps it, 0 drops it (its"
            " elastic ringing), momentum and angular momentum kept", "")
            .defaultValue(1).range(0, 1);
        return t;
    }();
    return table;
}


DDA::DDA(double velocityRatio, double deformationVelocityRatio)
:
    Newmark(0.5, 1),
    velocityRatio_(velocityRatio),
    deformationVelocityRatio_(deformationVelocityRatio)
{}


DDA::DDA(const dictionary& dict)
:
    DDA
    (
        (keywords().validate(dict), keywords().get<double>(dict, "velocityRatio")),
        keywords().get<double>(dict, "deformationVelocityRatio")
    )
{}


void DDA::update
(
    const Eigen::VectorXd& dd,
    double dt,
    const Eigen::VectorXd& V0,
    const Eigen::VectorXd& A0,
    Eigen::VectorXd& V1,
    Eigen::VectorXd& A1
) const
{
    Newmark::update(dd, dt, V0, A0, V1, A1);
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
    os << ')';
    return os.str();
}

} // End namespace nmm
