#include "nmmSolid/material/linearElastic/linearElastic.H"

#include <cmath>

namespace nmm
{

addToRunTimeSelectionTable(solidMaterial, linearElastic, "linearElastic");


namespace
{

//- The entry, once it is known not to be incompressible: nu = 0.5 gets a
//  message of its own, as the range check alone would not say why the
//  end of the range is excluded
const entry& compressible(const entry& materialEntry)
{
    const entry* nu = materialEntry.isDict()
        ? materialEntry.dict().findEntry("nu")
        : nullptr;
    if (nu && !nu->isDict() && !nu->stream().empty())
    {
        // The value is the last token, also in the dimensioned forms
        const token& value = nu->stream().back();
        if (value.isNumber() && value.scalar == 0.5)
        {
            throw nu->error("nu = 0.5 is an incompressible solid, which a"
                " displacement formulation cannot represent (lambda ="
                " E nu/((1+nu)(1-2nu)) is infinite); nu must lie in"
                " (-1, 0.5), and close to 0.5 the constant-strain elements"
                " lock in plane strain");
        }
    }
    return materialEntry;
}

} // End anonymous namespace


const keywordTable& linearElastic::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("linearElastic", "isotropic linear elasticity");
        // type first, then the law's own keywords, then the shared ones
        t.word("type", "material model").required();
        t.scalar("E", "Young's modulus", "Pa").required().above(0);
        t.scalar("nu", "Poisson's ratio", "").required().above(-1).below(0.5)
            .notes("0.5 (incompressible) is excluded: lambda is infinite");
        t.include(solidMaterial::commonKeywords());
        return t;
    }();
    return table;
}


linearElastic::linearElastic(const entry& materialEntry)
:
    solidMaterial(compressible(materialEntry), "linearElastic", keywords())
{
    const dictionary& dict = materialEntry.dict();
    E_ = keywords().get<double>(dict, "E");
    nu_ = keywords().get<double>(dict, "nu");
}


Eigen::Matrix3d linearElastic::elasticityMatrix(planeModel p) const
{
    const double nu = nu_;
    Eigen::Matrix3d D;
    if (p == planeModel::planeStress)
    {
        D << 1,  nu, 0,
             nu, 1,  0,
             0,  0,  (1 - nu)/2;
        return E_/(1 - nu*nu)*D;
    }
    D << 1 - nu, nu,     0,
         nu,     1 - nu, 0,
         0,      0,      (1 - 2*nu)/2;
    return E_/((1 + nu)*(1 - 2*nu))*D;
}


double linearElastic::sigmaZZ(const Eigen::Vector3d& sigma, planeModel p) const
{
    // Plane strain holds eps_zz = 0, which takes nu (sxx + syy)
    return p == planeModel::planeStrain ? nu_*(sigma(0) + sigma(1)) : 0.0;
}


double linearElastic::pWaveSpeed(planeModel p) const
{
    const double modulus = p == planeModel::planeStress
        ? E_/(1 - nu_*nu_)
        : lambda() + 2*mu();
    return std::sqrt(modulus/density());
}


double linearElastic::sWaveSpeed() const
{
    return std::sqrt(mu()/density());
}


double linearElastic::barWaveSpeed() const
{
    return std::sqrt(E_/density());
}

} // End namespace nmm
