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

    double call(const std::string& name, const std::vector<double>& a)
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
        fail("unknown function '" + name + "'");
    }

    double primary()
    {
        skip();
        if (pos_ >= s_.size()) fail("unexpected end of expression");
        const char c = s_[pos_];
        if (c == '(')
        {
            ++pos_;
            const double v = ternary();
            expect(')');
            return v;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
        {
            return number();
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
        {
            const std::string name = identifier();
            if (name == "true") return 1;
            if (name == "false") return 0;
            expect('(');
            std::vector<double> args;
            if (!accept(")"))
            {
                do { args.push_back(ternary()); } while (accept(","));
                expect(')');
            }
            return call(name, args);
        }
        fail(std::string("unexpected '") + c + "'");
    }

    double unary()
    {
        nesting guard(*this);
        if (accept("-")) return -unary();
        if (accept("+")) return unary();
        if (accept("!")) return unary() == 0 ? 1 : 0;
        return primary();
    }

    double product()
    {
        double v = unary();
        while (true)
        {
            if (accept("*")) v *= unary();
            else if (accept("/")) v /= unary();
            else if (accept("%")) v = std::fmod(v, unary());
            else return v;
        }
    }

    double sum()
    {
        double v = product();
        while (true)
        {
            if (accept("+")) v += product();
            else if (accept("-")) v -= product();
            else return v;
        }
    }

    double comparison()
    {
        const double v = sum();
        if (accept("<=")) return v <= sum();
        if (accept(">=")) return v >= sum();
        if (accept("==")) return v == sum();
        if (accept("!=")) return v != sum();
        if (accept("<")) return v < sum();
        if (accept(">")) return v > sum();
        return v;
    }

    double conjunction()
    {
        double v = comparison();
        while (accept("&&"))
        {
            const double r = comparison();
            v = (v != 0 && r != 0) ? 1 : 0;
        }
        return v;
    }

    double disjunction()
    {
        double v = conjunction();
        while (accept("||"))
        {
            const double r = conjunction();
            v = (v != 0 || r != 0) ? 1 : 0;
        }
        return v;
    }

    double ternary()
    {
        nesting guard(*this);
        const double c = disjunction();
        if (!accept("?")) return c;
        const double a = ternary();
        expect(':');
        const double b = ternary();
        return c != 0 ? a : b;
    }

public:
    explicit evaluator(std::string_view s) : s_(s) {}

    double run()
    {
        const double v = ternary();
        skip();
        if (pos_ != s_.size()) fail("unexpected text");
        return v;
    }
};

} // End anonymous namespace


double evaluateExpression(std::string_view expression)
{
    return evaluator(expression).run();
}

} // End namespace nmm
