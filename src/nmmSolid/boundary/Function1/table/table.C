#include "nmmSolid/boundary/Function1/table/table.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace nmm
{
namespace Function1Types
{

template<class Type>
const keywordTable& table<Type>::keywords()
{
    static const keywordTable t = []
    {
        keywordTable k("table", "a value interpolated in a table of times");
        k.word("type", "Function1 type");
        k.list("values", "rows (time value), times strictly increasing")
            .required();
        k.word("outOfBounds", "what a time outside the table gives")
            .choices({"clamp", "error", "warn", "repeat"})
            .defaultValue("clamp");
        k.word("interpolationScheme", "how values between rows are found")
            .choices({"linear", "step"})
            .defaultValue("linear");
        return k;
    }();
    return t;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

template<class Type>
table<Type>::table
(
    const std::string& name,
    const std::vector<row>& rows,
    bounds outOfBounds,
    interpolation scheme
)
:
    Function1<Type>(name, "table"),
    bounds_(outOfBounds),
    interpolation_(scheme)
{
    for (const auto& [t, v] : rows)
    {
        if (!times_.empty() && !(t > times_.back()))
        {
            throw this->error("row " + std::to_string(times_.size() + 1)
                + " (time " + formatScalar(t) + ") is not after row "
                + std::to_string(times_.size()) + " (time "
                + formatScalar(times_.back())
                + "): times must be strictly increasing");
        }
        times_.push_back(t);
        values_.push_back(v);
    }
    if (times_.empty()) throw this->error("a table needs at least one row");
    if (bounds_ == bounds::repeat && times_.size() < 2)
    {
        throw this->error("outOfBounds repeat needs at least two rows");
    }
    finish();
}


template<class Type>
table<Type>::table(const std::string& name, tokenReader& inlineValue)
:
    Function1<Type>(name, "table")
{
    readRows(inlineValue);
    finish();
}


template<class Type>
table<Type>::table(const std::string& name, const dictionary& coeffs)
:
    Function1<Type>(name, "table")
{
    keywords().validate(coeffs);

    const entry& rows = coeffs.lookupEntry("values");
    tokenReader r(rows.stream(), &rows);
    readRows(r);
    r.expectEnd();

    setBounds(keywords().get<std::string>(coeffs, "outOfBounds"));
    setInterpolation(keywords().get<std::string>(coeffs, "interpolationScheme"));
    if (bounds_ == bounds::repeat && times_.size() < 2)
    {
        throw coeffs.lookupEntry("outOfBounds").error("table '" + this->name()
            + "': outOfBounds repeat needs at least two rows");
    }
    finish();
}


// * * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * //

template<class Type>
void table<Type>::readRows(tokenReader& r)
{
    const std::string key = r.owner() ? r.owner()->keyword() : this->name();
    const std::string prefix = "table '" + this->name() + "': ";

    // OpenFOAM writes lists with their size in front: "2((0 0) (1 1))"
    long long size = -1;
    if (!r.atEnd() && r.peek().isInteger()) size = r.next().label;

    r.expectPunct('(');
    while (!r.atEnd() && !r.peek().isPunct(')'))
    {
        const sourcePosition at = r.peek().where;
        r.expectPunct('(');
        const double t = readValue<double>(r);
        const Type v = function1Traits<Type>::read(r);
        r.expectPunct(')');

        if (!times_.empty() && !(t > times_.back()))
        {
            throw IOerror(prefix + "row " + std::to_string(times_.size() + 1)
                + " (time " + formatScalar(t) + ") is not after row "
                + std::to_string(times_.size()) + " (time "
                + formatScalar(times_.back())
                + "): times must be strictly increasing", at, key);
        }
        times_.push_back(t);
        values_.push_back(v);
    }
    r.expectPunct(')');

    if (times_.empty())
    {
        r.putBack();
        throw r.error(prefix + "a table needs at least one row");
    }
    if (size >= 0 && static_cast<std::size_t>(size) != times_.size())
    {
        r.putBack();
        throw r.error(prefix + "list declared with " + std::to_string(size)
            + " rows has " + std::to_string(times_.size()));
    }
}


template<class Type>
void table<Type>::setBounds(const std::string& word)
{
    if (word == "error") bounds_ = bounds::error;
    else if (word == "warn") bounds_ = bounds::warn;
    else if (word == "repeat") bounds_ = bounds::repeat;
    else bounds_ = bounds::clamp;
}


template<class Type>
void table<Type>::setInterpolation(const std::string& word)
{
    interpolation_ = word == "step" ? interpolation::step : interpolation::linear;
}


template<class Type>
void table<Type>::finish()
{
    periodIntegral_ = integrateInside(firstTime(), lastTime());
}


// * * * * * * * * * * * * * * * * Evaluation  * * * * * * * * * * * * * * //

template<class Type>
std::size_t table<Type>::interval(double t) const
{
    const auto above = std::upper_bound(times_.begin(), times_.end(), t);
    const std::size_t i = above == times_.begin() ? 0 : (above - times_.begin()) - 1;
    return std::min(i, times_.size() - 2);
}


template<class Type>
Type table<Type>::interpolate(double t) const
{
    if (times_.size() == 1) return values_.front();

    const std::size_t i = interval(t);
    if (interpolation_ == interpolation::step)
    {
        return t < times_[i + 1] ? values_[i] : values_[i + 1];
    }
    // Weights rather than y0 + w*(y1 - y0): exact at both rows, so that
    // whole intervals integrate to the plain trapezoidal rule
    const double w = (t - times_[i])/(times_[i + 1] - times_[i]);
    return Type((1 - w)*values_[i] + w*values_[i + 1]);
}


template<class Type>
Type table<Type>::integrateInside(double a, double b) const
{
    Type sum = function1Traits<Type>::zero();
    if (!(a < b)) return sum;

    for (std::size_t i = interval(a); a < b; ++i)
    {
        const double hi = std::min(b, times_[i + 1]);
        if (interpolation_ == interpolation::step)
        {
            sum += (hi - a)*values_[i];
        }
        else
        {
            sum += 0.5*(hi - a)*(interpolate(a) + interpolate(hi));
        }
        a = hi;
    }
    return sum;
}


template<class Type>
double table<Type>::wrap(double t) const
{
    double r = std::fmod(t - firstTime(), period());
    if (r < 0) r += period();
    return std::min(firstTime() + r, lastTime());
}


template<class Type>
void table<Type>::outside(double t) const
{
    const bool before = t < firstTime();
    const std::string side = before
        ? "before the first time " + formatScalar(firstTime())
        : "after the last time " + formatScalar(lastTime());

    if (bounds_ == bounds::error)
    {
        throw this->error("time " + formatScalar(t) + " is " + side
            + " of the table (outOfBounds error)");
    }
    if (bounds_ == bounds::warn)
    {
        std::atomic<bool>& warned = before ? warnedBefore_ : warnedAfter_;
        if (!warned.exchange(true))
        {
            printWarning(std::cout, this->type() + " '" + this->name()
                + "' (" + this->where().str() + "): time " + formatScalar(t)
                + " is " + side + " of the table; the "
                + (before ? "first" : "last")
                + " value is used (outOfBounds warn: warned once)");
        }
    }
}


template<class Type>
Type table<Type>::value(double t) const
{
    if (t >= firstTime() && t <= lastTime()) return interpolate(t);
    if (bounds_ == bounds::repeat) return interpolate(wrap(t));

    outside(t);
    return t < firstTime() ? values_.front() : values_.back();
}


template<class Type>
Type table<Type>::integral(double t0, double t1) const
{
    if (t1 < t0) return Type(-integral(t1, t0));

    const double first = firstTime();
    const double last = lastTime();

    if (bounds_ == bounds::repeat)
    {
        // Whole periods between the two times, then the remainders:
        // F(t) = k(t)*periodIntegral + integral from first to r(t)
        const double P = period();
        const double k0 = std::floor((t0 - first)/P);
        const double k1 = std::floor((t1 - first)/P);
        const double r0 = std::clamp(t0 - k0*P, first, last);
        const double r1 = std::clamp(t1 - k1*P, first, last);
        const Type rest = r0 <= r1
            ? integrateInside(r0, r1)
            : Type(-integrateInside(r1, r0));
        return Type((k1 - k0)*periodIntegral_ + rest);
    }

    if (t0 < first) outside(t0);
    if (t1 > last) outside(t1);

    Type sum = function1Traits<Type>::zero();
    if (t0 < first) sum += (std::min(t1, first) - t0)*values_.front();
    sum += integrateInside(std::max(t0, first), std::min(t1, last));
    if (t1 > last) sum += (t1 - std::max(t0, last))*values_.back();
    return sum;
}


template class table<double>;
template class table<Eigen::Vector2d>;


namespace
{

[[maybe_unused]] const bool added =
    addInlineOrDictionary<table>("table");

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
