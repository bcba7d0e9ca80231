#include "nmmSolid/boundary/initialVelocity/initialVelocity.H"

#include "nmmSolid/io/dictionary/dimensionSet.H"

#include <ostream>
#include <sstream>

namespace nmm
{

const keywordTable& initialVelocity::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("U", "initial velocity (0/U); no file: at rest");
        t.any("dimensions", "dimension set; if given, [0 1 -1 0 0 0 0]");
        t.declare("internalField", keywordTable::valueKind::any, "velocity"
            " at t = 0: a Function1 or an expression in x, y (reference"
            " position)", "m/s").required()
            .notes("dynamic analyses only");
        return t;
    }();
    return table;
}


void initialVelocity::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
}


initialVelocity::initialVelocity(const dictionary& dict)
{
    keywords().validate(dict);
    if (const entry* e = dict.findEntry("dimensions"))
    {
        checkDimensions(*e, {0, 1, -1, 0, 0, 0, 0}, "a velocity");
    }
    field_ = std::make_shared<const vectorSpaceTimeFunction>("internalField", dict);
    // A uniform value is checked now rather than at the first node
    if (field_->uniformInSpace()) value(Eigen::Vector2d::Zero());
}


initialVelocity initialVelocity::read(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file)) return initialVelocity();
    return initialVelocity(dictionary::read(file));
}


sourcePosition initialVelocity::where() const
{
    return field_ ? field_->where() : sourcePosition();
}


Eigen::Vector2d initialVelocity::value(const Eigen::Vector2d& x) const
{
    if (!field_) return Eigen::Vector2d::Zero();
    const Eigen::Vector2d v = field_->value(x, 0);
    if (!v.allFinite())
    {
        std::ostringstream os;
        os << "the initial velocity (" << v[0] << ' ' << v[1] << ") at ("
           << x[0] << ' ' << x[1] << ") is not a finite number";
        throw IOerror(os.str(), field_->where(), "internalField");
    }
    return v;
}

} // End namespace nmm
