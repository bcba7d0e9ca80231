#include "nmmSolid/boundary/Function1/Function1/function1Traits.H"

namespace nmm
{

double function1Traits<double>::read(tokenReader& r)
{
    return readValue<double>(r);
}


Eigen::Vector2d function1Traits<Eigen::Vector2d>::read(tokenReader& r)
{
    r.expectPunct('(');
    double c[3];
    for (int i = 0; i < 3; ++i)
    {
        if (r.atEnd() || r.peek().isPunct(')'))
        {
            throw r.error("expected a vector (x y 0) with 3 components, found "
                + std::to_string(i));
        }
        c[i] = readValue<double>(r);
    }
    if (!r.atEnd() && !r.peek().isPunct(')'))
    {
        throw r.error("expected a vector (x y 0) with 3 components, found more");
    }
    if (c[2] != 0)
    {
        // Point at the third component rather than at the ')'
        r.putBack();
        throw r.error("the third component of a vector must be 0 in a 2D case,"
            " found " + formatScalar(c[2]));
    }
    r.expectPunct(')');
    return Eigen::Vector2d(c[0], c[1]);
}

} // End namespace nmm
