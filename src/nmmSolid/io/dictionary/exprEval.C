#include "nmmSolid/io/dictionary/exprEval.H"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace nmm
{

namespace
{

exprValue scalarValue(double x)
{
    exprValue r;
    r.v[0] = x;
    return r;
}

class evaluator
{
    std::string_view s_;
    std::size_t pos_ = 0;
    int depth_ = 0;

    // Bounded nesting: deep input must fail cleanly, not exhaust the stack
    struct nesting
    {
        evaluator& e;
        explicit nesting(evaluator& ev) : e(ev)
        {
            if (++e.depth_ > 256) e.fail("expression nested too deeply");
        }
        ~nesting() { --e.depth_; }
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

    bool accept(std::string_view op)
    {
        skip();
        if (s_.substr(pos_, op.size()) == op)
        {
            pos_ += op.size();
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

    double scalar(const exprValue& a, const char* what)
    {
        if (a.isVector) fail(std::string(what) + " needs a scalar, not a vector");
        return a.v[0];
    }

    exprValue combine(const exprValue& a, const exprValue& b, char op)
    {
        exprValue r;
        if (op == '+' || op == '-')
        {
            if (a.isVector != b.isVector) fail("cannot add a scalar and a vector");
            r.isVector = a.isVector;
            for (int i = 0; i < 3; ++i) r.v[i] = op == '+' ? a.v[i] + b.v[i] : a.v[i] - b.v[i];
            return r;
        }
        if (a.isVector && b.isVector) fail("cannot multiply or divide two vectors");
        if (op == '/' && b.isVector) fail("cannot divide by a vector");
        if (op == '%' && (a.isVector || b.isVector)) fail("'%' needs scalars");
        const exprValue& vec = a.isVector ? a : b;
        const double k = a.isVector ? b.v[0] : a.v[0];
        r.isVector = a.isVector || b.isVector;
        for (int i = 0; i < (r.isVector ? 3 : 1); ++i)
        {
            const double x = r.isVector ? vec.v[i] : a.v[0];
            if (op == '*') r.v[i] = r.isVector ? x * k : a.v[0] * b.v[0];
            else if (op == '/') r.v[i] = x / b.v[0];
            else r.v[i] = std::fmod(a.v[0], b.v[0]);
        }
        return r;
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

    exprValue call(const std::string& name, const std::vector<exprValue>& args)
    {
        if (name == "vector")
        {
            if (args.size() != 3) fail("vector() takes 3 components");
            exprValue r;
            r.isVector = true;
            for (int i = 0; i < 3; ++i) r.v[i] = scalar(args[i], "vector()");
            return r;
        }
        if ((name == "mag" || name == "magSqr") && args.size() == 1 && args[0].isVector)
        {
            const auto& v = args[0].v;
            const double m2 = v[0]*v[0] + v[1]*v[1] + v[2]*v[2];
            return scalarValue(name == "mag" ? std::sqrt(m2) : m2);
        }
        std::vector<double> a;
        for (const auto& x : args) a.push_back(scalar(x, (name + "()").c_str()));
        return scalarValue(callScalar(name, a));
    }

    double callScalar(const std::string& name, const std::vector<double>& a)
    {
        using f1 = double (*)(double);
        static const std::map<std::string, f1> one =
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
        auto arity = [&](std::size_t n)
        {
            if (a.size() != n)
            {
                fail(name + "() takes " + std::to_string(n) + " argument(s), "
                    + "given " + std::to_string(a.size()));
            }
        };
        if (auto it = one.find(name); it != one.end())
        {
            arity(1);
            return it->second(a[0]);
        }
        if (name == "pi") { arity(0); return M_PI; }
        if (name == "e") { arity(0); return M_E; }
        if (name == "pow") { arity(2); return std::pow(a[0], a[1]); }
        if (name == "atan2") { arity(2); return std::atan2(a[0], a[1]); }
        if (name == "hypot") { arity(2); return std::hypot(a[0], a[1]); }
        if (name == "min" || name == "max")
        {
            if (a.empty()) fail(name + "() needs arguments");
            double r = a[0];
            for (double v : a) r = (name == "min") ? std::min(r, v) : std::max(r, v);
            return r;
        }
        fail("unknown function '" + name + "' (#eval evaluates scalar "
            "expressions only)");
    }

    exprValue primary()
    {
        skip();
        if (pos_ >= s_.size()) fail("unexpected end of expression");
        const char c = s_[pos_];
        if (c == '(')
        {
            ++pos_;
            const exprValue v = ternary();
            expect(')');
            return v;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
            return scalarValue(number());
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
        {
            const std::size_t nameStart = pos_;
            const std::string name = identifier();
            if (name == "true") return scalarValue(1);
            if (name == "false") return scalarValue(0);
            expect('(');
            std::vector<exprValue> args;
            if (!accept(")"))
            {
                do { args.push_back(ternary()); } while (accept(","));
                expect(')');
            }
            // Errors about the call point at its name
            const std::size_t end = pos_;
            pos_ = nameStart;
            exprValue r = call(name, args);
            pos_ = end;
            return r;
        }
        fail(std::string("unexpected '") + c + "'");
    }

    exprValue unary()
    {
        nesting guard(*this);
        if (accept("-"))
        {
            exprValue v = unary();
            for (double& x : v.v) x = -x;
            return v;
        }
        if (accept("+")) return unary();
        if (accept("!")) return scalarValue(scalar(unary(), "'!'") == 0 ? 1 : 0);
        return primary();
    }

    exprValue product()
    {
        exprValue v = unary();
        while (true)
        {
            if (accept("*")) v = combine(v, unary(), '*');
            else if (accept("/")) v = combine(v, unary(), '/');
            else if (accept("%")) v = combine(v, unary(), '%');
            else return v;
        }
    }

    exprValue sum()
    {
        exprValue v = product();
        while (true)
        {
            if (accept("+")) v = combine(v, product(), '+');
            else if (accept("-")) v = combine(v, product(), '-');
            else return v;
        }
    }

    exprValue comparison()
    {
        const exprValue first = sum();
        static const char* ops[] = {"<=", ">=", "==", "!=", "<", ">"};
        for (const char* op : ops)
        {
            if (!accept(op)) continue;
            const double a = scalar(first, "a comparison");
            const double b = scalar(sum(), "a comparison");
            const std::string o(op);
            const bool r = o == "<=" ? a <= b : o == ">=" ? a >= b
                : o == "==" ? a == b : o == "!=" ? a != b : o == "<" ? a < b : a > b;
            return scalarValue(r ? 1 : 0);
        }
        return first;
    }

    exprValue conjunction()
    {
        exprValue v = comparison();
        while (accept("&&"))
        {
            const bool l = scalar(v, "'&&'") != 0;
            const bool r = scalar(comparison(), "'&&'") != 0;
            v = scalarValue(l && r ? 1 : 0);
        }
        return v;
    }

    exprValue disjunction()
    {
        exprValue v = conjunction();
        while (accept("||"))
        {
            const bool l = scalar(v, "'||'") != 0;
            const bool r = scalar(conjunction(), "'||'") != 0;
            v = scalarValue(l || r ? 1 : 0);
        }
        return v;
    }

    exprValue ternary()
    {
        nesting guard(*this);
        const exprValue c = disjunction();
        if (!accept("?")) return c;
        const exprValue a = ternary();
        expect(':');
        const exprValue b = ternary();
        return scalar(c, "'?:'") != 0 ? a : b;
    }

public:
    explicit evaluator(std::string_view s) : s_(s) {}

    exprValue run()
    {
        const exprValue v = ternary();
        skip();
        if (pos_ != s_.size()) fail("unexpected text");
        return v;
    }
};

} // End anonymous namespace


exprValue evaluateExpression(std::string_view expression)
{
    return evaluator(expression).run();
}

} // End namespace nmm
