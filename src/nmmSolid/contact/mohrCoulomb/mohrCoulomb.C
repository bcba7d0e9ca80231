#include "nmmSolid/contact/mohrCoulomb/mohrCoulomb.H"

#include <algorithm>
#include <cmath>

namespace nmm
{

addToRunTimeSelectionTable(contactLaw, mohrCoulomb, "mohrCoulomb");


namespace
{

double sign(double x)
{
    return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}

} // End anonymous namespace


const keywordTable& mohrCoulomb::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("mohrCoulomb",
            "Coulomb friction with a Mohr-Coulomb bond that breaks for good");
        t.include(contactLaw::commonKeywords());
        t.scalar("frictionAngle", "friction angle", "deg").required()
            .atLeast(0).below(90);
        t.scalar("cohesion", "cohesion of an intact bond", "Pa").atLeast(0)
            .defaultValue(0)
            .notes("0 unless given: cohesionless");
        t.scalar("tensileStrength", "tensile strength of an intact bond",
            "Pa").atLeast(0).defaultValue(0)
            .notes("0 unless given: no tensile strength");
        t.word("initialState", "state of contacts that touch at the start")
            .choices({"open", "bonded"}).defaultValue("open");
        return t;
    }();
    return table;
}


mohrCoulomb::mohrCoulomb(const dictionary& dict)
:
    contactLaw(dict, "mohrCoulomb", keywords())
{
    const keywordTable& k = keywords();
    frictionAngle_ = k.get<double>(dict, "frictionAngle");
    tanPhi_ = std::tan(frictionAngle_*M_PI/180.0);
    cohesion_ = k.get<double>(dict, "cohesion");
    tensileStrength_ = k.get<double>(dict, "tensileStrength");
    initialState_ = k.get<std::string>(dict, "initialState") == "bonded"
        ? contactState::bonded
        : contactState::open;
}


double mohrCoulomb::slidingFriction(const contactQuery& q) const
{
    return sign(q.Fs)*std::max(q.effectiveNormalForce(), 0.0)*tanPhi_;
}


contactDecision mohrCoulomb::decide(const contactQuery& q) const
{
    const double N = q.effectiveNormalForce();
    const double absFs = std::abs(q.Fs);

    contactDecision d;
    d.state = q.state;
    d.bondIntact = q.bondIntact;

    const auto breakBond = [&]
    {
        if (d.bondIntact)
        {
            d.bondBroken = true;
            d.bondIntact = false;
        }
    };
    // Strengths of the bond as it is now
    const auto C = [&] { return d.bondIntact ? cohesion_*q.length : 0.0; };
    const auto T = [&] { return d.bondIntact ? tensileStrength_*q.length : 0.0; };
    const auto slide = [&]
    {
        d.state = contactState::sliding;
        const double F = std::max(N, 0.0)*tanPhi_;
        const double dir = q.shearDisplacement != 0
            ? -sign(q.shearDisplacement)
            : sign(q.Fs);
        d.frictionForce = dir*F;
    };

    if (q.state == contactState::open)
    {
        if (q.gap >= 0) return d;
        if (absFs <= std::max(N, 0.0)*tanPhi_ + C())
        {
            d.state = contactState::bonded;
        }
        else
        {
            breakBond();
            slide();
        }
        return d;
    }

    // Closed: tension first (Eq. 9)
    if (-N > T())
    {
        breakBond();
        d.state = contactState::open;
        return d;
    }

    if (q.state == contactState::bonded)
    {
        if (absFs > N*tanPhi_ + C())     // Eq. (10)
        {
            breakBond();
            if (N < 0) d.state = contactState::open;
            else slide();
        }
        return d;
    }

    // Sliding
    if (absFs < N*tanPhi_ + C())
    {
        d.state = contactState::bonded;
    }
    else
    {
        slide();
    }
    return d;
}

} // End namespace nmm
