#include "nmmSolid/boundary/Function1/constant/constant.H"
#include "nmmSolid/boundary/Function1/Function1/addToFunction1Table.H"

namespace nmm
{
namespace Function1Types
{

template<class Type>
const keywordTable& constant<Type>::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("constant", "a value that does not change in time");
        t.word("type", "Function1 type (constant or uniform)");
        t.declare("value", function1Traits<Type>::kind, "the value").required();
        return t;
    }();
    return table;
}


namespace
{

template<class Type>
Type validatedValue(const dictionary& coeffs)
{
    constant<Type>::keywords().validate(coeffs);
    return readFunction1Value<Type>(coeffs.lookupEntry("value"));
}

} // End anonymous namespace


template<class Type>
constant<Type>::constant(const std::string& name, const Type& value)
:
    Function1<Type>(name, "constant"),
    value_(value)
{}


template<class Type>
constant<Type>::constant(const std::string& name, tokenReader& inlineValue)
:
    Function1<Type>(name, "constant"),
    value_(function1Traits<Type>::read(inlineValue))
{}


template<class Type>
constant<Type>::constant(const std::string& name, const dictionary& coeffs)
:
    Function1<Type>(name, "constant"),
    value_(validatedValue<Type>(coeffs))
{}


template class constant<double>;
template class constant<Eigen::Vector2d>;


namespace
{

[[maybe_unused]] const bool added =
    addInlineOrDictionary<constant>("constant")
 && addInlineOrDictionary<constant>("uniform");

} // End anonymous namespace

} // End namespace Function1Types
} // End namespace nmm
