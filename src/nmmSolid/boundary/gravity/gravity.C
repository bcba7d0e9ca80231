#include "nmmSolid/boundary/gravity/gravity.H"

#include "nmmSolid/boundary/Function1/Function1/function1Traits.H"
#include "nmmSolid/io/dictionary/dimensionSet.H"

#include <ostream>

namespace nmm
{

const keywordTable& gravity::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("g", "gravitational acceleration (constant/g);"
            " no file: no gravity");
        t.any("dimensions", "dimension set; if given, [0 1 -2 0 0 0 0]");
        t.vector("value", "acceleration (x y 0)", "m/s^2").required()
            .notes("the third component must be 0 (2D)");
        return t;
    }();
    return table;
}


void gravity::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
}


gravity::gravity(const dictionary& dict)
{
    keywords().validate(dict);
    if (const entry* e = dict.findEntry("dimensions"))
    {
        checkDimensions(*e, {0, 1, -2, 0, 0, 0, 0}, "an acceleration");
    }
    value_ = readFunction1Value<Eigen::Vector2d>(dict.lookupEntry("value"));
}


gravity gravity::read(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file)) return gravity();
    return gravity(dictionary::read(file));
}

} // End namespace nmm
