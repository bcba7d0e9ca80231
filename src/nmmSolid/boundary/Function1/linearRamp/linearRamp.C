#include "nmmSolid/boundary/Function1/linearRamp/linearRamp.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

#include <algorithm>
#include <type_traits>

namespace nmm
{
namespace Function1Types
{

template<class Type>
const keywordTable& linearRamp<Type>::keywords()
{
    static const keywordTable t = []
    {
        constexpr bool scalar = std::is_same_v<Type, double>;
        keywordTable k("linearRamp", "0 before start, rising linearly to value");
        k.word("type", "Function1 type");
        k.scalar("start", "time the ramp starts", "s").defaultValue(0);
        k.scalar("duration", "time the ramp takes to rise", "s")
            .required().above(0);
        auto& v = k.declare("value", function1Traits<Type>::kind,
            "value at the top of the ramp");
        if (scalar) v.defaultValue(1);
        else v.required();
        return k;
    }();
    return t;
}


template<class Type>
linearRamp<Type>::linearRamp
(
    const std::string& name,
    double start,
    double duration,
    const Type& value
)
:
    Function1<Type>(name, "linearRamp"),
    start_(start),
    duration_(duration),
    value_(value)
{
    if (!(duration_ > 0)) throw this->error("duration must be > 0");
}


template<class Type>
linearRamp<Type>::linearRamp(const std::string& name, const dictionary& coeffs)
:
    Function1<Type>(name, "linearRamp"),
    value_(function1Traits<Type>::zero())
{
    const keywordTable& k = keywords();
    k.validate(coeffs);
    start_ = k.get<double>(coeffs, "start");
    duration_ = k.get<double>(coeffs, "duration");
    // A vector has no default (validate() required it); a scalar ramp
    // without value is OpenFOAM's 0..1 ramp
    if (const entry* v = coeffs.findEntry("value"))
    {
        value_ = readFunction1Value<Type>(*v);
    }
    else if constexpr (std::is_same_v<Type, double>)
    {
        value_ = 1;
    }
}


template<class Type>
Type linearRamp<Type>::value(double t) const
{
    const double f = std::clamp((t - start_)/duration_, 0.0, 1.0);
    return Type(f*value_);
}


template<class Type>
double linearRamp<Type>::rampIntegral(double a, double b) const
{
    const double end = start_ + duration_;
    double sum = 0;

    // Rising part, as (hi - lo) times the mean height: no cancellation of
    // squares for a short interval far from start
    const double lo = std::max(a, start_);
    const double hi = std::min(b, end);
    if (lo < hi) sum += (hi - lo)*((lo - start_) + (hi - start_))/(2*duration_);

    // Top part
    const double top = std::max(a, end);
    if (top < b) sum += b - top;

    return sum;
}


template<class Type>
Type linearRamp<Type>::integral(double t0, double t1) const
{
    if (t1 < t0) return Type(-integral(t1, t0));
    return Type(rampIntegral(t0, t1)*value_);
}


template class linearRamp<double>;
template class linearRamp<Eigen::Vector2d>;


namespace
{

template<class Type>
bool addLinearRamp()
{
    return addDictionaryOnly<Type>
    (
        "linearRamp",
        [](const std::string& key, const dictionary& coeffs)
        {
            return std::make_unique<linearRamp<Type>>(key, coeffs);
        },
        &linearRamp<Type>::keywords()
    );
}

[[maybe_unused]] const bool added =
    addLinearRamp<double>() && addLinearRamp<Eigen::Vector2d>();

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
