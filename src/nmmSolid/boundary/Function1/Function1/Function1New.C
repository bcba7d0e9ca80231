#include "nmmSolid/boundary/Function1/Function1/Function1.H"

#include "nmmSolid/boundary/Function1/constant/constant.H"

namespace nmm
{

namespace
{

using namespace Function1Types;


template<class Type>
std::string validTypes()
{
    std::string s;
    for (const auto& n : Function1<Type>::selector::names()) s += " " + n;
    return s;
}


//- "pressure { type sine; ... }"
template<class Type>
std::unique_ptr<Function1<Type>> fromDictionary
(
    const std::string& key,
    const entry& e
)
{
    const dictionary& coeffs = e.dict();
    const entry* typeEntry = coeffs.findEntry("type");
    if (!typeEntry)
    {
        throw IOerror("Function1 '" + key + "' is a dictionary without"
            " 'type'; valid types:" + validTypes<Type>(), e.where(), key);
    }
    const auto typeName = dictionary::readEntryValue<std::string>(*typeEntry);
    return Function1<Type>::selector::New
    (
        typeName, coeffs, key, &coeffs, nullptr
    );
}


//- "pressure 4.2e5;", "pressure table (...);", "pressure sine;" with
//  "pressureCoeffs { ... }"
template<class Type>
std::unique_ptr<Function1<Type>> fromTokens
(
    const std::string& key,
    const entry& e,
    const dictionary& dict
)
{
    using selector = typename Function1<Type>::selector;

    tokenReader r(e.stream(), &e);
    if (r.atEnd())
    {
        throw e.error("expected a " + std::string(function1Traits<Type>::name)
            + " or a Function1 type; valid types:" + validTypes<Type>());
    }

    // A bare value is a constant, as in OpenFOAM
    if (!r.peek().isWord())
    {
        auto f = std::make_unique<constant<Type>>(key, r);
        r.expectEnd();
        return f;
    }

    const std::string typeName = r.next().text;
    if (!r.atEnd())
    {
        auto f = selector::New(typeName, dict, key, nullptr, &r, key);
        r.expectEnd();
        return f;
    }

    const dictionary* coeffs = dict.findDict(key + "Coeffs");
    if (!coeffs && selector::find(typeName))
    {
        const bool hasInline = typeName == "constant" || typeName == "uniform"
            || typeName == "table" || typeName == "polynomial"
            || typeName == "expression";
        throw e.error("'" + key + " " + typeName + ";' gives no "
            + (hasInline ? "value or " : "") + "coefficients; write "
            + (hasInline ? key + " " + typeName + " <value>; or " : "")
            + key + " { type " + typeName + "; ... }");
    }
    return selector::New(typeName, dict, key, coeffs, nullptr, key);
}

} // End anonymous namespace


template<class Type>
std::unique_ptr<Function1<Type>> Function1<Type>::New
(
    const std::string& keyword,
    const dictionary& dict
)
{
    // keyword, not e.keyword(): the entry may be a pattern that matched it
    const entry& e = dict.lookupEntry(keyword);
    std::unique_ptr<Function1> f = e.isDict()
        ? fromDictionary<Type>(keyword, e)
        : fromTokens<Type>(keyword, e, dict);
    f->where_ = e.where();
    return f;
}


template<class Type>
std::unique_ptr<Function1<Type>> Function1<Type>::NewIfPresent
(
    const std::string& keyword,
    const dictionary& dict
)
{
    return dict.findEntry(keyword) ? New(keyword, dict) : nullptr;
}


template<class Type>
std::vector<std::string> Function1<Type>::types()
{
    return selector::names();
}


template class Function1<double>;
template class Function1<Eigen::Vector2d>;

} // End namespace nmm
