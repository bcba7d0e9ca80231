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
        return t;
    }();
    return table;
}


DDA::DDA(double velocityRatio)
:
    Newmark(0.5, 1),
    velocityRatio_(velocityRatio)
{}


DDA::DDA(const dictionary& dict)
:
    DDA((keywords().validate(dict), keywords().get<double>(dict, "velocityRatio")))
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
    os << "DDA (velocityRatio " << velocityRatio_ << ')';
    return os.str();
}

} // End namespace nmm
