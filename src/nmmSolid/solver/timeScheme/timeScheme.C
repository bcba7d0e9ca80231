#include "nmmSolid/solver/timeScheme/timeScheme.H"

#include <sstream>

namespace nmm
{

std::string timeScheme::name() const
{
    std::ostringstream os;
    switch (type)
    {
        case kind::staticAnalysis: return "static";
        case kind::DDA: os << "DDA (velocityRatio " << velocityRatio << ')'; break;
        case kind::Newmark: os << "Newmark (beta " << beta << ", gamma " << gamma << ')'; break;
    }
    return os.str();
}

} // End namespace nmm
