#include "nmmSolid/boundary/Function1/polynomial/polynomial.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

#include <algorithm>
#include <cmath>

namespace nmm
{
namespace Function1Types
{

namespace
{

bool isWhole(double e)
{
    return e == std::floor(e);
}

} // End anonymous namespace


template<class Type>
const keywordTable& polynomial<Type>::keywords()
{
    static const keywordTable t = []
    {
        keywordTable k("polynomial", "sum of coeff*t^exponent");
        k.word("type", "Function1 type");
        k.list("coeffs", "terms (coeff exponent)").required();
        return k;
    }();
    return t;
}


template<class Type>
polynomial<Type>::polynomial(const std::string& name, std::vector<term> terms)
:
    Function1<Type>(name, "polynomial"),
    terms_(std::move(terms))
{
    if (terms_.empty()) throw this->error("a polynomial needs at least one term");
}


template<class Type>
polynomial<Type>::polynomial(const std::string& name, tokenReader& inlineValue)
:
    Function1<Type>(name, "polynomial")
{
    readTerms(inlineValue);
}


template<class Type>
polynomial<Type>::polynomial(const std::string& name, const dictionary& coeffs)
:
    Function1<Type>(name, "polynomial")
{
    keywords().validate(coeffs);
    const entry& e = coeffs.lookupEntry("coeffs");
    tokenReader r(e.stream(), &e);
    readTerms(r);
    r.expectEnd();
}


template<class Type>
void polynomial<Type>::readTerms(tokenReader& r)
{
    r.expectPunct('(');
    while (!r.atEnd() && !r.peek().isPunct(')'))
    {
        r.expectPunct('(');
        const Type c = function1Traits<Type>::read(r);
        const double e = readValue<double>(r);
        r.expectPunct(')');
        terms_.emplace_back(c, e);
    }
    r.expectPunct(')');
    if (terms_.empty())
    {
        r.putBack();
        throw r.error("polynomial '" + this->name()
            + "': a polynomial needs at least one (coeff exponent) term");
    }
}


template<class Type>
double polynomial<Type>::power(double t, double e) const
{
    if (t == 0 && e < 0)
    {
        throw this->error("t^" + formatScalar(e) + " is infinite at t = 0");
    }
    if (t < 0 && !isWhole(e))
    {
        throw this->error("t^" + formatScalar(e) + " is not a real number at t = "
            + formatScalar(t));
    }
    return std::pow(t, e);
}


template<class Type>
double polynomial<Type>::powerIntegral(double e, double t0, double t1) const
{
    const bool throughZero = std::min(t0, t1) <= 0 && std::max(t0, t1) >= 0;
    if (e <= -1 && throughZero)
    {
        throw this->error("the integral of t^" + formatScalar(e) + " from "
            + formatScalar(t0) + " to " + formatScalar(t1)
            + " is infinite (t = 0 is inside)");
    }
    if (e == -1) return std::log(t1/t0);
    return (power(t1, e + 1) - power(t0, e + 1))/(e + 1);
}


template<class Type>
Type polynomial<Type>::value(double t) const
{
    Type sum = function1Traits<Type>::zero();
    for (const auto& [c, e] : terms_) sum += power(t, e)*c;
    return sum;
}


template<class Type>
Type polynomial<Type>::integral(double t0, double t1) const
{
    Type sum = function1Traits<Type>::zero();
    if (t0 == t1) return sum;
    for (const auto& [c, e] : terms_) sum += powerIntegral(e, t0, t1)*c;
    return sum;
}


template class polynomial<double>;
template class polynomial<Eigen::Vector2d>;


namespace
{

[[maybe_unused]] const bool added =
    addInlineOrDictionary<polynomial>("polynomial");

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
