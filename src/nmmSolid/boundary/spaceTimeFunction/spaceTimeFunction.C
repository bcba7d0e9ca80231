#include "nmmSolid/boundary/spaceTimeFunction/spaceTimeFunction.H"

#include "nmmSolid/boundary/Function1/expression/expression.H"

#include <sstream>

namespace nmm
{

template<class Type>
const std::vector<std::string>& spaceTimeFunction<Type>::variables()
{
    static const std::vector<std::string> names{"x", "y", "t"};
    return names;
}


template<class Type>
std::optional<std::string> spaceTimeFunction<Type>::expressionText
(
    const entry& e
)
{
    using io = Function1Types::expressionFor<Type>;
    if (e.isDict())
    {
        const entry* type = e.dict().findEntry("type");
        if (!type || dictionary::readEntryValue<std::string>(*type) != "expression")
        {
            return std::nullopt;
        }
        Function1Types::expression<Type>::keywords().validate(e.dict());
        return e.dict().template get<std::string>("expression");
    }
    tokenReader r(e.stream(), &e);
    if (r.atEnd() || !r.peek().isWord("expression")) return std::nullopt;
    r.next();
    std::string text = io::readText(r);
    r.expectEnd();
    return text;
}


template<class Type>
spaceTimeFunction<Type>::spaceTimeFunction
(
    const std::string& keyword,
    const dictionary& dict
)
:
    name_(keyword)
{
    // keyword, not e.keyword(): the entry may be a pattern that matched it
    const entry& e = dict.lookupEntry(keyword);
    where_ = e.where();
    if (const auto text = expressionText(e))
    {
        expression_ = Function1Types::expressionFor<Type>::compile
        (
            *text, variables(), where_, keyword
        );
    }
    else
    {
        function1_ = Function1<Type>::New(keyword, dict);
    }
}


template<class Type>
std::unique_ptr<spaceTimeFunction<Type>> spaceTimeFunction<Type>::NewIfPresent
(
    const std::string& keyword,
    const dictionary& dict
)
{
    if (!dict.findEntry(keyword)) return nullptr;
    return std::make_unique<spaceTimeFunction>(keyword, dict);
}


template<class Type>
bool spaceTimeFunction<Type>::uniformInSpace() const
{
    return function1_ || !(expression_->uses("x") || expression_->uses("y"));
}


template<class Type>
void spaceTimeFunction<Type>::invalid
(
    const exprValue& v,
    const Eigen::Vector2d& x,
    double t
) const
{
    std::ostringstream at;
    at << "x = " << x.x() << ", y = " << x.y() << ", t = " << t;
    throw Function1Types::expressionFor<Type>::invalid
    (
        v, *expression_, where_, name_, at.str()
    );
}


template<class Type>
Type spaceTimeFunction<Type>::value(const Eigen::Vector2d& x, double t) const
{
    if (function1_) return function1_->value(t);
    using io = Function1Types::expressionFor<Type>;
    const exprValue v = expression_->evaluate({x.x(), x.y(), t});
    if (!io::acceptable(v)) invalid(v, x, t);
    return io::convert(v);
}


template class spaceTimeFunction<double>;
template class spaceTimeFunction<Eigen::Vector2d>;

} // End namespace nmm
