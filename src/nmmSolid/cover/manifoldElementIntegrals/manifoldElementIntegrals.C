#include "nmmSolid/cover/manifoldElementIntegrals/manifoldElementIntegrals.H"

#include <cmath>
#include <stdexcept>

namespace nmm
{
namespace manifoldElement
{

namespace
{

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return a.x()*b.y() - a.y()*b.x();
}


//- |A_T|, refusing a degenerate triangle (its weights do not exist)
double checkedArea(const triangleNodes& T)
{
    const double A = std::abs(signedArea(T));
    const double scale = (T.col(1) - T.col(0)).squaredNorm()
        + (T.col(2) - T.col(1)).squaredNorm()
        + (T.col(0) - T.col(2)).squaredNorm();
    if (!(A > 1e-14*scale))
    {
        throw std::invalid_argument("manifoldElement: degenerate cover triangle");
    }
    return A;
}


//- The component to leave out of the area computation: the one of
//  largest magnitude on E. A lambda carries an absolute rounding error of
//  about eps |lambda|, so the two smaller ones resolve a thin element best
//  (a strip along edge 3 is measured by lambda3 ~ h, not by 1 - (1 - h)).
int droppedComponent(const baryLoop& E)
{
    Eigen::Vector3d largest = Eigen::Vector3d::Zero();
    for (const auto& p : E)
    {
        largest = largest.cwiseMax(p.cwiseAbs());
    }
    int k = 0;
    largest.maxCoeff(&k);
    return k;
}


//- Signed area of the fan triangle apex-p-q in the plane of the two
//  components after 'dropped' (cyclic order: every such plane has the
//  orientation and area of the (lambda1, lambda2) plane, as the lambdas
//  sum to one); differences to the apex keep a tiny polygon's digits
double fanArea
(
    int dropped,
    const baryPoint& apex,
    const baryPoint& p,
    const baryPoint& q
)
{
    const int i = (dropped + 1) % 3;
    const int j = (dropped + 2) % 3;
    const Eigen::Vector2d ap(p(i) - apex(i), p(j) - apex(j));
    const Eigen::Vector2d aq(q(i) - apex(i), q(j) - apex(j));
    return 0.5*cross(ap, aq);
}


//- Adds the signed triangle a-b-c (area A) to m; the weights at its
//  vertices are the lambdas themselves
void addTriangle
(
    polygonMoments& m,
    double A,
    const baryPoint& a,
    const baryPoint& b,
    const baryPoint& c
)
{
    const Eigen::Vector3d sum = a + b + c;
    m.area += A;
    m.w += (A/3)*sum;
    m.ww += (A/12)
        *(a*a.transpose() + b*b.transpose() + c*c.transpose()
          + sum*sum.transpose());
}


//- x_q - x_p from the lambda differences, relative to x3 so that large
//  coordinates of T do not cost digits
Eigen::Vector2d chord(const triangleNodes& T, const baryPoint& p, const baryPoint& q)
{
    const baryPoint d = q - p;
    return d(0)*(T.col(0) - T.col(2)) + d(1)*(T.col(1) - T.col(2));
}

} // End anonymous namespace


double signedArea(const triangleNodes& T)
{
    return 0.5*cross(T.col(1) - T.col(0), T.col(2) - T.col(0));
}


baryPoint toBarycentric(const triangleNodes& T, const Eigen::Vector2d& x)
{
    const double twoA = 2*signedArea(T);
    checkedArea(T);
    baryPoint lambda;
    for (int k = 0; k < 3; ++k)
    {
        const Eigen::Vector2d a = T.col((k + 1) % 3) - x;
        const Eigen::Vector2d b = T.col((k + 2) % 3) - x;
        lambda(k) = cross(a, b)/twoA;
    }
    return lambda;
}


baryLoop toBarycentric(const triangleNodes& T, const cartesianLoop& loop)
{
    baryLoop result;
    result.reserve(loop.size());
    for (const auto& x : loop)
    {
        result.push_back(toBarycentric(T, x));
    }
    return result;
}


Eigen::Vector2d toCartesian(const triangleNodes& T, const baryPoint& lambda)
{
    return T*lambda;
}


matrix36 strainMatrix(const triangleNodes& T)
{
    checkedArea(T);
    const double twoA = 2*signedArea(T);
    matrix36 B = matrix36::Zero();
    for (int k = 0; k < 3; ++k)
    {
        // Gradient of the hat function: the opposite edge rotated
        const Eigen::Vector2d& xi = T.col((k + 1) % 3);
        const Eigen::Vector2d& xj = T.col((k + 2) % 3);
        const double b = (xi.y() - xj.y())/twoA;
        const double c = (xj.x() - xi.x())/twoA;
        B(0, 2*k) = b;
        B(1, 2*k + 1) = c;
        B(2, 2*k) = c;
        B(2, 2*k + 1) = b;
    }
    return B;
}


polygonMoments moments(const triangleNodes& T, const baryLoop& E)
{
    if (E.size() < 3)
    {
        throw std::invalid_argument
        (
            "manifoldElement: a polygon needs at least three vertices"
        );
    }
    // Cartesian area = lambda-plane area * 2 |A_T|
    const double jacobian = 2*checkedArea(T);

    const int dropped = droppedComponent(E);

    polygonMoments m;
    const baryPoint& apex = E.front();
    for (std::size_t i = 1; i + 1 < E.size(); ++i)
    {
        const double A = jacobian*fanArea(dropped, apex, E[i], E[i + 1]);
        addTriangle(m, A, apex, E[i], E[i + 1]);
    }

    // Clockwise (in the lambda plane) gives all integrals negated
    if (m.area < 0)
    {
        m.area = -m.area;
        m.w = -m.w;
        m.ww = -m.ww;
    }
    return m;
}


polygonMoments moments(const triangleNodes& T, const cartesianLoop& E)
{
    return moments(T, toBarycentric(T, E));
}


Eigen::Vector2d centroid(const triangleNodes& T, const polygonMoments& m)
{
    // Relative to x3, for the same reason as chord()
    const Eigen::Vector2d rel =
        m.w(0)*(T.col(0) - T.col(2)) + m.w(1)*(T.col(1) - T.col(2));
    return T.col(2) + rel/m.area;
}


double areaRatio(const triangleNodes& T, const polygonMoments& m)
{
    return m.area/checkedArea(T);
}


matrix66 stiffness
(
    const triangleNodes& T,
    double area,
    const Eigen::Matrix3d& D,
    double thickness
)
{
    return stiffness(strainMatrix(T), area, D, thickness);
}


matrix66 stiffness
(
    const matrix36& B,
    double area,
    const Eigen::Matrix3d& D,
    double thickness
)
{
    const matrix66 K = (area*thickness)*(B.transpose()*D*B);
    // Exactly symmetric, for the global Cholesky factorisation
    return 0.5*(K + K.transpose());
}


matrix66 mass(const polygonMoments& m, double rho, double thickness)
{
    matrix66 M = matrix66::Zero();
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            const double mij = rho*thickness*0.5*(m.ww(i, j) + m.ww(j, i));
            M(2*i, 2*j) = mij;
            M(2*i + 1, 2*j + 1) = mij;
        }
    }
    return M;
}


vector6 bodyForce
(
    const polygonMoments& m,
    const Eigen::Vector2d& b,
    double thickness
)
{
    vector6 f;
    for (int i = 0; i < 3; ++i)
    {
        f.segment<2>(2*i) = thickness*m.w(i)*b;
    }
    return f;
}


vector6 edgeTraction
(
    const triangleNodes& T,
    const baryPoint& p,
    const baryPoint& q,
    const Eigen::Vector2d& tp,
    const Eigen::Vector2d& tq,
    double thickness
)
{
    checkedArea(T);
    const double L = chord(T, p, q).norm();
    vector6 f;
    for (int i = 0; i < 3; ++i)
    {
        // int_0^L of two linear functions: L/6 (2 f_p g_p + f_p g_q + ...)
        f.segment<2>(2*i) = (thickness*L/6)
            *((2*p(i) + q(i))*tp + (p(i) + 2*q(i))*tq);
    }
    return f;
}


vector6 edgeTraction
(
    const triangleNodes& T,
    const baryPoint& p,
    const baryPoint& q,
    const Eigen::Vector2d& tr,
    double thickness
)
{
    return edgeTraction(T, p, q, tr, tr, thickness);
}

} // End namespace manifoldElement
} // End namespace nmm
