#include "nmmSolid/boundary/Function1/sine/sine.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

#include <cmath>
#include <type_traits>

namespace nmm
{
namespace Function1Types
{

namespace
{

constexpr double twoPi = 2*M_PI;

template<class Type>
keywordTable makeKeywords(const char* owner, const char* shape)
{
    keywordTable k(owner, std::string("level + amplitude*") + shape
        + "(omega*(t - start) + phase)");
    k.word("type", "Function1 type");
    k.declare("amplitude", function1Traits<Type>::kind, "amplitude").required();
    k.scalar("frequency", "frequency of the wave (or give period)", "1/s")
        .above(0);
    k.scalar("period", "period of the wave (or give frequency)", "s").above(0);
    k.scalar("start", "time origin of the wave", "s").defaultValue(0);
    k.declare("level", function1Traits<Type>::kind, "offset added to the wave")
        .defaultValue(std::is_same_v<Type, double> ? "0" : "(0 0 0)");
    k.scalar("phase", "phase angle", "rad").defaultValue(0);
    return k;
}

template<class Type>
Type readOrZero(const dictionary& coeffs, const std::string& key)
{
    const entry* e = coeffs.findEntry(key);
    return e ? readFunction1Value<Type>(*e) : function1Traits<Type>::zero();
}

} // End anonymous namespace


template<class Type>
const keywordTable& sine<Type>::keywords()
{
    static const keywordTable t = makeKeywords<Type>("sine", "sin");
    return t;
}


template<class Type>
const keywordTable& sine<Type>::cosineKeywords()
{
    static const keywordTable t = makeKeywords<Type>("cosine", "cos");
    return t;
}


template<class Type>
double sine<Type>::readOmega(const dictionary& coeffs, const keywordTable& k)
{
    const entry* f = coeffs.findEntry("frequency");
    const entry* p = coeffs.findEntry("period");
    if (f && p)
    {
        throw p->error("give either frequency or period, not both");
    }
    if (p)
    {
        // 2 pi/period rather than 2 pi*(1/period): period 2 pi gives
        // omega exactly 1
        return twoPi/k.get<double>(coeffs, "period");
    }
    if (!f) throw k.missing(coeffs, k.declared("frequency"));
    return twoPi*k.get<double>(coeffs, "frequency");
}


template<class Type>
sine<Type>::sine
(
    const std::string& name,
    wave kind,
    const Type& amplitude,
    double omega,
    double start,
    const Type& level,
    double phase
)
:
    Function1<Type>(name, kind == wave::sine ? "sine" : "cosine"),
    wave_(kind),
    amplitude_(amplitude),
    level_(level),
    omega_(omega),
    start_(start),
    phase_(phase)
{
    if (!(omega_ > 0)) throw this->error("the angular frequency must be > 0");
}


template<class Type>
sine<Type>::sine(const std::string& name, wave kind, const dictionary& coeffs)
:
    Function1<Type>(name, kind == wave::sine ? "sine" : "cosine"),
    wave_(kind),
    amplitude_(function1Traits<Type>::zero()),
    level_(function1Traits<Type>::zero())
{
    const keywordTable& k = kind == wave::sine ? keywords() : cosineKeywords();
    k.validate(coeffs);
    amplitude_ = readFunction1Value<Type>(coeffs.lookupEntry("amplitude"));
    level_ = readOrZero<Type>(coeffs, "level");
    omega_ = readOmega(coeffs, k);
    start_ = k.get<double>(coeffs, "start");
    phase_ = k.get<double>(coeffs, "phase");
}


template<class Type>
double sine<Type>::shape(double x) const
{
    return wave_ == wave::sine ? std::sin(x) : std::cos(x);
}


template<class Type>
Type sine<Type>::value(double t) const
{
    return Type(level_ + shape(omega_*(t - start_) + phase_)*amplitude_);
}


template<class Type>
Type sine<Type>::integral(double t0, double t1) const
{
    // The integral of sin (cos) from x0 to x1 is 2 sin(m) sin(h)
    // (2 cos(m) sin(h)) with m the mid-point and h the half-width: one
    // formula for both, and exact-to-rounding for short intervals
    const double mid = omega_*(0.5*(t0 + t1) - start_) + phase_;
    const double half = 0.5*omega_*(t1 - t0);
    const double area = 2*shape(mid)*std::sin(half)/omega_;
    return Type((t1 - t0)*level_ + area*amplitude_);
}


template class sine<double>;
template class sine<Eigen::Vector2d>;


namespace
{

//- sine and cosine: one class, told the wave by its type name
template<class Type>
bool addWaves()
{
    using wave = typename sine<Type>::wave;
    return addDictionaryOnly<Type>
    (
        "sine",
        [](const std::string& key, const dictionary& coeffs)
        {
            return std::make_unique<sine<Type>>(key, wave::sine, coeffs);
        },
        &sine<Type>::keywords()
    )
    && addDictionaryOnly<Type>
    (
        "cosine",
        [](const std::string& key, const dictionary& coeffs)
        {
            return std::make_unique<sine<Type>>(key, wave::cosine, coeffs);
        },
        &sine<Type>::cosineKeywords()
    );
}

[[maybe_unused]] const bool added =
    addWaves<double>() && addWaves<Eigen::Vector2d>();

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
