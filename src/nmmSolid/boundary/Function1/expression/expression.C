#include "nmmSolid/boundary/Function1/expression/expression.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

#include <cmath>
#include <sstream>
#include <type_traits>

namespace nmm
{
namespace Function1Types
{

namespace
{

template<class Type>
constexpr bool isScalar = std::is_same_v<Type, double>;

std::string quoted(const compiledExpression& e)
{
    return "\"" + e.text() + "\"";
}

} // End anonymous namespace


template<class Type>
std::string expressionFor<Type>::readText(tokenReader& r)
{
    if (r.atEnd() || !r.peek().isString())
    {
        throw r.error("expression needs its formula in quotes, e.g. "
            + std::string(isScalar<Type> ? "expression \"1e5*t\""
                : "expression \"vector(1e-3*t, 0, 0)\""));
    }
    return r.next().text;
}


template<class Type>
compiledExpression expressionFor<Type>::compile
(
    const std::string& text,
    std::vector<std::string> variables,
    const sourcePosition& where,
    const std::string& keyword
)
{
    try
    {
        compiledExpression e(text, std::move(variables));
        if (e.isVector() == isScalar<Type>)
        {
            throw IOerror("expression " + quoted(e) + " for '" + keyword
                + "' is a " + (e.isVector() ? "vector" : "scalar") + "; a "
                + function1Traits<Type>::name + " is expected"
                + (isScalar<Type> ? "" : ", written vector(x, y, 0)"),
                where, keyword);
        }
        return e;
    }
    catch (const std::invalid_argument& err)
    {
        throw IOerror("expression for '" + keyword + "': " + err.what(),
            where, keyword);
    }
}


template<class Type>
bool expressionFor<Type>::acceptable(const exprValue& v)
{
    if constexpr (isScalar<Type>)
    {
        return std::isfinite(v.v[0]);
    }
    else
    {
        return std::isfinite(v.v[0]) && std::isfinite(v.v[1]) && v.v[2] == 0;
    }
}


template<class Type>
Type expressionFor<Type>::convert(const exprValue& v)
{
    if constexpr (isScalar<Type>)
    {
        return v.v[0];
    }
    else
    {
        return Eigen::Vector2d(v.v[0], v.v[1]);
    }
}


template<class Type>
IOerror expressionFor<Type>::invalid
(
    const exprValue& v,
    const compiledExpression& e,
    const sourcePosition& where,
    const std::string& keyword,
    const std::string& at
)
{
    const bool finite = std::isfinite(v.v[0]) && std::isfinite(v.v[1])
        && std::isfinite(v.v[2]);
    const std::string what = finite
        ? "has a non-zero third component at " + at
            + "; the solver is two-dimensional"
        : "is not a finite number at " + at
            + " (a division by zero or a value out of range)";
    return IOerror("expression " + quoted(e) + " for '" + keyword + "' "
        + what, where, keyword);
}


template<class Type>
const keywordTable& expression<Type>::keywords()
{
    static const keywordTable t = []
    {
        keywordTable k("expression", "a formula in time t (#eval arithmetic)");
        k.word("type", "Function1 type");
        k.string("expression", "the formula in t, e.g. \"1e5*t\"").required();
        return k;
    }();
    return t;
}


template<class Type>
expression<Type>::expression(const std::string& name, tokenReader& in)
:
    Function1<Type>(name, "expression"),
    expr_("0"),
    where_(in.owner() ? in.owner()->where() : sourcePosition{})
{
    const std::string text = expressionFor<Type>::readText(in);
    expr_ = expressionFor<Type>::compile(text, {"t"}, where_, name);
}


template<class Type>
expression<Type>::expression(const std::string& name, const dictionary& coeffs)
:
    Function1<Type>(name, "expression"),
    expr_("0")
{
    keywords().validate(coeffs);
    const entry& e = coeffs.lookupEntry("expression");
    where_ = e.where();
    const auto text = dictionary::readEntryValue<std::string>(e);
    expr_ = expressionFor<Type>::compile(text, {"t"}, where_, name);
}


template<class Type>
Type expression<Type>::value(double t) const
{
    const exprValue v = expr_.evaluate({t});
    using io = expressionFor<Type>;
    if (!io::acceptable(v))
    {
        std::ostringstream at;
        at << "t = " << t;
        throw io::invalid(v, expr_, where_, this->name(), at.str());
    }
    return io::convert(v);
}


template<class Type>
Type expression<Type>::integral(double t0, double t1) const
{
    // Gauss-Legendre nodes and weights on [-1, 1]
    static const double x[5] = {0, -0.5384693101056831, 0.5384693101056831,
        -0.9061798459386640, 0.9061798459386640};
    static const double w[5] = {0.5688888888888889, 0.4786286704993665,
        0.4786286704993665, 0.2369268850561891, 0.2369268850561891};
    constexpr int parts = 8;
    const double h = (t1 - t0)/parts;
    Type sum = function1Traits<Type>::zero();
    for (int p = 0; p < parts; ++p)
    {
        const double mid = t0 + (p + 0.5)*h;
        for (int i = 0; i < 5; ++i) sum += w[i]*value(mid + 0.5*h*x[i]);
    }
    return Type(0.5*h*sum);
}


template struct expressionFor<double>;
template struct expressionFor<Eigen::Vector2d>;
template class expression<double>;
template class expression<Eigen::Vector2d>;


namespace
{

[[maybe_unused]] const bool added =
    addInlineOrDictionary<expression>("expression");

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
