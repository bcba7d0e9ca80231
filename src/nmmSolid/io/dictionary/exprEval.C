#include "nmmSolid/io/dictionary/exprEval.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace nmm
{

namespace
{

//- Postfix operations; values are pushed on and popped off a stack
enum class op : std::uint8_t
{
    number, variable, makeVector, negate, logicalNot,
    add, subtract, multiply, divide, modulo,
    less, lessEqual, greater, greaterEqual, equal, notEqual,
    logicalAnd, logicalOr, select, call1, call2, minimum, maximum,
    magVector, magSqrVector
};

using instruction = compiledExpression::instruction;

instruction make(op o)
{
    instruction i;
    i.op = static_cast<std::uint8_t>(o);
    return i;
}

using scalarFunction = double (*)(double);

struct namedFunction
{
    const char* name;
    scalarFunction f;
};

// Captureless lambdas: plain function pointers, called without overhead
const namedFunction oneArgument[] =
{
    {"sin", [](double x) { return std::sin(x); }},
    {"cos", [](double x) { return std::cos(x); }},
    {"tan", [](double x) { return std::tan(x); }},
    {"asin", [](double x) { return std::asin(x); }},
    {"acos", [](double x) { return std::acos(x); }},
    {"atan", [](double x) { return std::atan(x); }},
    {"sinh", [](double x) { return std::sinh(x); }},
    {"cosh", [](double x) { return std::cosh(x); }},
    {"tanh", [](double x) { return std::tanh(x); }},
    {"exp", [](double x) { return std::exp(x); }},
    {"log", [](double x) { return std::log(x); }},
    {"log10", [](double x) { return std::log10(x); }},
    {"sqrt", [](double x) { return std::sqrt(x); }},
    {"cbrt", [](double x) { return std::cbrt(x); }},
    {"mag", [](double x) { return std::fabs(x); }},
    {"abs", [](double x) { return std::fabs(x); }},
    {"sqr", [](double x) { return x * x; }},
    {"magSqr", [](double x) { return x * x; }},
    {"floor", [](double x) { return std::floor(x); }},
    {"ceil", [](double x) { return std::ceil(x); }},
    {"round", [](double x) { return std::round(x); }},
    {"sign", [](double x) { return x < 0 ? -1.0 : 1.0; }},
    {"degToRad", [](double x) { return x * M_PI / 180.0; }},
    {"radToDeg", [](double x) { return x * 180.0 / M_PI; }},
};

scalarFunction findOneArgument(const std::string& name)
{
    for (const auto& f : oneArgument)
    {
        if (name == f.name) return f.f;
    }
    return nullptr;
}

using binaryFunction = double (*)(double, double);

binaryFunction findTwoArguments(const std::string& name)
{
    if (name == "pow") return [](double a, double b) { return std::pow(a, b); };
    if (name == "atan2") return [](double a, double b) { return std::atan2(a, b); };
    if (name == "hypot") return [](double a, double b) { return std::hypot(a, b); };
    return nullptr;
}


//- Recursive descent over the text, emitting postfix code; a stack of
//  the kinds (scalar or vector) of the values the code leaves checks types
class compiler
{
    std::string_view s_;
    const std::vector<std::string>& variables_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    std::vector<instruction> code_;
    std::vector<bool> kinds_;            // true: vector
    std::size_t maxDepth_ = 0;

    // Bounded nesting: deep input must fail cleanly, not exhaust the stack
    struct nesting
    {
        compiler& c;
        explicit nesting(compiler& cc) : c(cc)
        {
            if (++c.depth_ > 256) c.fail("expression nested too deeply");
        }
        ~nesting() { --c.depth_; }
    };

    [[noreturn]] void fail(const std::string& what) const
    {
        throw std::invalid_argument(what + " at character "
            + std::to_string(pos_ + 1) + " of \"" + std::string(s_) + "\"");
    }

    void skip()
    {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_])))
        {
            ++pos_;
        }
    }

    bool accept(std::string_view o)
    {
        skip();
        if (s_.substr(pos_, o.size()) == o)
        {
            pos_ += o.size();
            return true;
        }
        return false;
    }

    void expect(char c)
    {
        if (!accept(std::string_view(&c, 1)))
        {
            fail(std::string("expected '") + c + "'");
        }
    }

    // Code emission with the kind of value it leaves

    void emit(const instruction& i, std::size_t pops, bool resultIsVector)
    {
        code_.push_back(i);
        kinds_.resize(kinds_.size() - pops);
        kinds_.push_back(resultIsVector);
        maxDepth_ = std::max(maxDepth_, kinds_.size());
    }

    bool top(std::size_t fromTop = 0) const
    {
        return kinds_[kinds_.size() - 1 - fromTop];
    }

    void needScalars(std::size_t n, const std::string& what)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            if (top(i)) fail(what + " needs a scalar, not a vector");
        }
    }

    void binary(char o)
    {
        const bool b = top(0), a = top(1);
        if (o == '+' || o == '-')
        {
            if (a != b) fail("cannot add a scalar and a vector");
            emit(make(o == '+' ? op::add : op::subtract), 2, a);
            return;
        }
        if (a && b) fail("cannot multiply or divide two vectors");
        if (o == '/' && b) fail("cannot divide by a vector");
        if (o == '%' && (a || b)) fail("'%' needs scalars");
        const op code = o == '*' ? op::multiply : o == '/' ? op::divide : op::modulo;
        emit(make(code), 2, a || b);
    }

    void logical(op code, const char* what)
    {
        needScalars(2, what);
        emit(make(code), 2, false);
    }

    double number()
    {
        const std::string rest(s_.substr(pos_));
        char* end = nullptr;
        const double v = std::strtod(rest.c_str(), &end);
        if (end == rest.c_str()) fail("expected a number");
        pos_ += std::size_t(end - rest.c_str());
        return v;
    }

    std::string identifier()
    {
        const std::size_t start = pos_;
        while (pos_ < s_.size()
            && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
        {
            ++pos_;
        }
        return std::string(s_.substr(start, pos_ - start));
    }

    void pushNumber(double x)
    {
        instruction i = make(op::number);
        i.value = x;
        emit(i, 0, false);
    }

    // Calls (the arguments' code is emitted already)

    void callVector(std::size_t nArgs)
    {
        if (nArgs != 3) fail("vector() takes 3 components");
        needScalars(3, "vector()");
        emit(make(op::makeVector), 3, true);
    }

    void arity(const std::string& name, std::size_t given, std::size_t n)
    {
        if (given != n)
        {
            fail(name + "() takes " + std::to_string(n) + " argument(s), "
                + "given " + std::to_string(given));
        }
    }

    void callScalar(const std::string& name, std::size_t nArgs)
    {
        needScalars(nArgs, name + "()");
        if (const scalarFunction f = findOneArgument(name))
        {
            arity(name, nArgs, 1);
            instruction i = make(op::call1);
            i.f1 = f;
            emit(i, 1, false);
        }
        else if (const binaryFunction f = findTwoArguments(name))
        {
            arity(name, nArgs, 2);
            instruction i = make(op::call2);
            i.f2 = f;
            emit(i, 2, false);
        }
        else if (name == "pi" || name == "e")
        {
            arity(name, nArgs, 0);
            pushNumber(name == "pi" ? M_PI : M_E);
        }
        else if (name == "min" || name == "max")
        {
            if (nArgs == 0) fail(name + "() needs arguments");
            instruction i = make(name == "min" ? op::minimum : op::maximum);
            i.argc = static_cast<std::uint8_t>(std::min<std::size_t>(nArgs, 255));
            if (nArgs > 255) fail(name + "() takes at most 255 arguments");
            emit(i, nArgs, false);
        }
        else
        {
            fail("unknown function '" + name + "'");
        }
    }

    void call(const std::string& name, std::size_t nArgs)
    {
        if (name == "vector") return callVector(nArgs);
        if ((name == "mag" || name == "magSqr") && nArgs == 1 && top())
        {
            emit(make(name == "mag" ? op::magVector : op::magSqrVector), 1, false);
            return;
        }
        callScalar(name, nArgs);
    }

    void variable(const std::string& name, std::size_t nameStart)
    {
        const auto it = std::find(variables_.begin(), variables_.end(), name);
        if (it == variables_.end())
        {
            if (variables_.empty()) fail("expected '('");
            pos_ = nameStart;
            std::string known;
            for (const auto& v : variables_) known += " " + v;
            fail("unknown variable '" + name + "' (variables:" + known + ")");
        }
        instruction i = make(op::variable);
        i.index = static_cast<std::uint32_t>(it - variables_.begin());
        emit(i, 0, false);
    }

    void functionOrVariable()
    {
        const std::size_t nameStart = pos_;
        const std::string name = identifier();
        if (name == "true" || name == "false") return pushNumber(name == "true");
        skip();
        if (pos_ >= s_.size() || s_[pos_] != '(') return variable(name, nameStart);
        expect('(');
        std::size_t nArgs = 0;
        if (!accept(")"))
        {
            do { ternary(); ++nArgs; } while (accept(","));
            expect(')');
        }
        // Errors about the call point at its name
        const std::size_t end = pos_;
        pos_ = nameStart;
        call(name, nArgs);
        pos_ = end;
    }

    void primary()
    {
        skip();
        if (pos_ >= s_.size()) fail("unexpected end of expression");
        const char c = s_[pos_];
        if (c == '(')
        {
            ++pos_;
            ternary();
            expect(')');
        }
        else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
            pushNumber(number());
        }
        else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
        {
            functionOrVariable();
        }
        else
        {
            fail(std::string("unexpected '") + c + "'");
        }
    }

    void unary()
    {
        nesting guard(*this);
        if (accept("-"))
        {
            unary();
            emit(make(op::negate), 1, top());
        }
        else if (accept("+"))
        {
            unary();
        }
        else if (accept("!"))
        {
            unary();
            needScalars(1, "'!'");
            emit(make(op::logicalNot), 1, false);
        }
        else
        {
            primary();
        }
    }

    void product()
    {
        unary();
        while (true)
        {
            char o = 0;
            if (accept("*")) o = '*';
            else if (accept("/")) o = '/';
            else if (accept("%")) o = '%';
            else return;
            unary();
            binary(o);
        }
    }

    void sum()
    {
        product();
        while (true)
        {
            char o = 0;
            if (accept("+")) o = '+';
            else if (accept("-")) o = '-';
            else return;
            product();
            binary(o);
        }
    }

    void comparison()
    {
        sum();
        static const std::pair<const char*, op> ops[] =
        {
            {"<=", op::lessEqual}, {">=", op::greaterEqual}, {"==", op::equal},
            {"!=", op::notEqual}, {"<", op::less}, {">", op::greater}
        };
        for (const auto& [text, code] : ops)
        {
            if (!accept(text)) continue;
            sum();
            logical(code, "a comparison");
            return;
        }
    }

    void conjunction()
    {
        comparison();
        while (accept("&&"))
        {
            comparison();
            logical(op::logicalAnd, "'&&'");
        }
    }

    void disjunction()
    {
        conjunction();
        while (accept("||"))
        {
            conjunction();
            logical(op::logicalOr, "'||'");
        }
    }

    void ternary()
    {
        nesting guard(*this);
        disjunction();
        if (!accept("?")) return;
        const std::size_t at = pos_;
        ternary();
        expect(':');
        ternary();
        if (top(2))
        {
            pos_ = at;
            fail("'?:' needs a scalar, not a vector");
        }
        if (top(0) != top(1))
        {
            pos_ = at;
            fail("the two branches of '?:' are a scalar and a vector");
        }
        emit(make(op::select), 3, top());
    }

public:
    compiler(std::string_view s, const std::vector<std::string>& variables)
    :
        s_(s), variables_(variables)
    {}

    void run()
    {
        ternary();
        skip();
        if (pos_ != s_.size()) fail("unexpected text");
    }

    std::vector<instruction>& code() { return code_; }
    bool isVector() const { return kinds_.back(); }
    std::size_t maxDepth() const { return maxDepth_; }
};


// Evaluation

exprValue scalarValue(double x)
{
    exprValue r;
    r.v[0] = x;
    return r;
}

void scale(exprValue& a, const exprValue& b, op o)
{
    const double k = a.isVector ? b.v[0] : a.v[0];
    if (o == op::multiply && !a.isVector && b.isVector) a = b;
    const int n = a.isVector ? 3 : 1;
    for (int i = 0; i < n; ++i)
    {
        if (o == op::multiply) a.v[i] = a.isVector ? a.v[i]*k : a.v[0]*b.v[0];
        else if (o == op::divide) a.v[i] /= b.v[0];
        else a.v[0] = std::fmod(a.v[0], b.v[0]);
    }
}

double compare(op o, double a, double b)
{
    switch (o)
    {
        case op::less: return a < b;
        case op::lessEqual: return a <= b;
        case op::greater: return a > b;
        case op::greaterEqual: return a >= b;
        case op::equal: return a == b;
        case op::notEqual: return a != b;
        case op::logicalAnd: return a != 0 && b != 0;
        default: return a != 0 || b != 0;
    }
}

//- Apply an operation that pops two values and pushes one
void applyBinary(op o, exprValue& a, const exprValue& b)
{
    if (o == op::add || o == op::subtract)
    {
        for (int i = 0; i < 3; ++i) a.v[i] = o == op::add ? a.v[i] + b.v[i] : a.v[i] - b.v[i];
    }
    else if (o == op::multiply || o == op::divide || o == op::modulo)
    {
        scale(a, b, o);
    }
    else
    {
        a = scalarValue(compare(o, a.v[0], b.v[0]));
    }
}

//- Run the program on a stack of at least maxDepth values
exprValue run
(
    const std::vector<instruction>& program,
    const double* variables,
    exprValue* stack
)
{
    std::size_t n = 0;
    for (const instruction& in : program)
    {
        const op o = static_cast<op>(in.op);
        switch (o)
        {
            case op::number: stack[n++] = scalarValue(in.value); break;
            case op::variable: stack[n++] = scalarValue(variables[in.index]); break;
            case op::makeVector:
                n -= 2;
                stack[n-1].isVector = true;
                stack[n-1].v = {stack[n-1].v[0], stack[n].v[0], stack[n+1].v[0]};
                break;
            case op::negate: for (double& x : stack[n-1].v) x = -x; break;
            case op::logicalNot: stack[n-1] = scalarValue(stack[n-1].v[0] == 0); break;
            case op::call1: stack[n-1].v[0] = in.f1(stack[n-1].v[0]); break;
            case op::call2:
                --n;
                stack[n-1].v[0] = in.f2(stack[n-1].v[0], stack[n].v[0]);
                break;
            case op::minimum:
            case op::maximum:
            {
                const std::size_t first = n - in.argc;
                for (std::size_t k = first + 1; k < n; ++k)
                {
                    const double x = stack[k].v[0];
                    double& r = stack[first].v[0];
                    r = o == op::minimum ? std::min(r, x) : std::max(r, x);
                }
                n = first + 1;
                break;
            }
            case op::magVector:
            case op::magSqrVector:
            {
                const auto& v = stack[n-1].v;
                const double m2 = v[0]*v[0] + v[1]*v[1] + v[2]*v[2];
                stack[n-1] = scalarValue(o == op::magVector ? std::sqrt(m2) : m2);
                break;
            }
            case op::select:
                n -= 2;
                stack[n-1] = stack[n-1].v[0] != 0 ? stack[n] : stack[n+1];
                break;
            default:
                --n;
                applyBinary(o, stack[n-1], stack[n]);
                break;
        }
    }
    return stack[0];
}

} // End anonymous namespace


compiledExpression::compiledExpression
(
    std::string_view text,
    std::vector<std::string> variables
)
:
    text_(text),
    variables_(std::move(variables)),
    used_(variables_.size(), false)
{
    compiler c(text_, variables_);
    c.run();
    program_ = std::move(c.code());
    isVector_ = c.isVector();
    maxDepth_ = c.maxDepth();
    for (const instruction& i : program_)
    {
        if (static_cast<op>(i.op) == op::variable) used_[i.index] = true;
    }
}


bool compiledExpression::uses(std::string_view variable) const
{
    for (std::size_t i = 0; i < variables_.size(); ++i)
    {
        if (variables_[i] == variable) return used_[i];
    }
    return false;
}


void compiledExpression::checkCount(std::size_t n) const
{
    if (n != variables_.size())
    {
        throw std::invalid_argument("expression \"" + text_ + "\" has "
            + std::to_string(variables_.size()) + " variable(s), given "
            + std::to_string(n) + " value(s)");
    }
}


exprValue compiledExpression::evaluate(const double* values) const
{
    // The usual expression needs a handful of stack slots
    constexpr std::size_t small = 16;
    if (maxDepth_ <= small)
    {
        exprValue stack[small];
        return run(program_, values, stack);
    }
    std::vector<exprValue> stack(maxDepth_);
    return run(program_, values, stack.data());
}


exprValue evaluateExpression(std::string_view expression)
{
    return compiledExpression(expression).evaluate(nullptr);
}


exprValue evaluateExpression
(
    std::string_view expression,
    const std::map<std::string, double>& variables
)
{
    std::vector<std::string> names;
    std::vector<double> values;
    for (const auto& [name, value] : variables)
    {
        names.push_back(name);
        values.push_back(value);
    }
    return compiledExpression(expression, std::move(names)).evaluate(values);
}

} // End namespace nmm
