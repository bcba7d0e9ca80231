// The integrals of a first-order manifold element against closed forms:
// whole triangle, partition of unity, additivity, a non-convex polygon
// against a hand triangulation, slivers, orientation, rigid-body modes,
// patch test, strain energy and edge tractions.

#include "nmmSolid/cover/manifoldElementIntegrals/manifoldElementIntegrals.H"

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace nmm::manifoldElement;

namespace
{

//- A general (not right-angled, not axis-aligned) cover triangle, CCW
triangleNodes coverTriangle()
{
    triangleNodes T;
    T << 0.3, 2.1, 0.9,
         0.1, 0.4, 1.7;
    return T;
}


//- The right triangle (0,0), (4,0), (0,4) that holds the L-shape
triangleNodes rightTriangle()
{
    triangleNodes T;
    T << 0, 4, 0,
         0, 0, 4;
    return T;
}


Eigen::Matrix3d planeStressD(double E, double nu)
{
    Eigen::Matrix3d D;
    D << 1,  nu, 0,
         nu, 1,  0,
         0,  0,  (1 - nu)/2;
    return E/(1 - nu*nu)*D;
}


//- Hat-function values at x, independently of the code under test: solve
//  [1 1 1; x1 x2 x3; y1 y2 y3] lambda = [1; x; y]
Eigen::Vector3d hatValues(const triangleNodes& T, const Eigen::Vector2d& x)
{
    Eigen::Matrix3d A;
    A.row(0).setOnes();
    A.bottomRows<2>() = T;
    return A.partialPivLu().solve(Eigen::Vector3d(1, x.x(), x.y()));
}


//- Reference moments of a CCW Cartesian triangle a-b-c, from hatValues
polygonMoments triangleReference
(
    const triangleNodes& T,
    const Eigen::Vector2d& a,
    const Eigen::Vector2d& b,
    const Eigen::Vector2d& c
)
{
    const double A = 0.5*((b - a).x()*(c - a).y() - (b - a).y()*(c - a).x());
    const Eigen::Vector3d wa = hatValues(T, a);
    const Eigen::Vector3d wb = hatValues(T, b);
    const Eigen::Vector3d wc = hatValues(T, c);
    polygonMoments m;
    m.area = A;
    for (int i = 0; i < 3; ++i)
    {
        m.w(i) = A/3*(wa(i) + wb(i) + wc(i));
        for (int j = 0; j < 3; ++j)
        {
            // int f g = A/12 (2 sum f_a g_a + sum_{a != b} f_a g_b)
            m.ww(i, j) = A/12
                *(2*(wa(i)*wa(j) + wb(i)*wb(j) + wc(i)*wc(j))
                  + wa(i)*(wb(j) + wc(j)) + wb(i)*(wa(j) + wc(j))
                  + wc(i)*(wa(j) + wb(j)));
        }
    }
    return m;
}


polygonMoments operator+(const polygonMoments& a, const polygonMoments& b)
{
    polygonMoments m;
    m.area = a.area + b.area;
    m.w = a.w + b.w;
    m.ww = a.ww + b.ww;
    return m;
}


//- Largest relative difference of all moments, relative to each scale
double relativeDifference(const polygonMoments& a, const polygonMoments& b)
{
    double d = std::abs(a.area - b.area)/std::abs(b.area);
    d = std::max(d, (a.w - b.w).cwiseAbs().maxCoeff()/b.w.cwiseAbs().maxCoeff());
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            if (b.ww(i, j) != 0)
            {
                d = std::max(d, std::abs(a.ww(i, j) - b.ww(i, j))/std::abs(b.ww(i, j)));
            }
        }
    }
    return d;
}


//- x in scientific notation, for the recorded error properties
std::string scientific(double x)
{
    std::ostringstream os;
    os << std::scientific << x;
    return os.str();
}


const baryLoop wholeTriangle = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

//- A convex pentagon inside T, CCW in the lambda plane
const baryLoop pentagon =
{
    {0.6, 0.2, 0.2}, {0.3, 0.6, 0.1}, {0.1, 0.6, 0.3},
    {0.1, 0.3, 0.6}, {0.4, 0.1, 0.5}
};

//- An L-shape (re-entrant corner at (1, 1)) inside rightTriangle()
const cartesianLoop lShape =
{
    {0.5, 0.5}, {2.5, 0.5}, {2.5, 1.0}, {1.0, 1.0}, {1.0, 2.5}, {0.5, 2.5}
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Whole triangle  * * * * * * * * * * * * * * //

TEST(elementIntegrals, wholeTriangleClosedForms)
{
    const triangleNodes T = coverTriangle();
    const double A = signedArea(T);
    const polygonMoments m = moments(T, wholeTriangle);

    EXPECT_NEAR(m.area, A, 1e-15*A);
    EXPECT_NEAR(areaRatio(T, m), 1.0, 1e-15);
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(m.w(i), A/3, 1e-15*A);
        for (int j = 0; j < 3; ++j)
        {
            EXPECT_NEAR(m.ww(i, j), A/12*(1 + (i == j)), 1e-15*A);
        }
    }
    EXPECT_NEAR(m.ww.sum(), A, 1e-15*A);

    const Eigen::Vector2d c = centroid(T, m);
    EXPECT_NEAR((c - T.rowwise().mean()).norm(), 0, 1e-15);
}


TEST(elementIntegrals, wholeTriangleMassAndBodyForce)
{
    const triangleNodes T = coverTriangle();
    const double A = signedArea(T);
    const double rho = 2650, t = 0.5;
    const polygonMoments m = moments(T, wholeTriangle);

    const matrix66 M = mass(m, rho, t);
    EXPECT_NEAR(M(0, 0), rho*t*A/6, 1e-12*rho*t*A);
    EXPECT_NEAR(M(0, 2), rho*t*A/12, 1e-12*rho*t*A);
    EXPECT_EQ(M(0, 1), 0.0);
    EXPECT_LT((M - M.transpose()).norm(), 1e-12*M.norm());
    // A rigid translation in x carries the whole mass rho t A
    vector6 ex;
    ex << 1, 0, 1, 0, 1, 0;
    EXPECT_NEAR(ex.dot(M*ex), rho*t*A, 1e-12*rho*t*A);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<matrix66>(M).eigenvalues().minCoeff(), 0);

    const Eigen::Vector2d b(1.5, -9.81);
    const vector6 f = bodyForce(m, b, t);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_NEAR((f.segment<2>(2*k) - t*A/3*b).norm(), 0, 1e-14*t*A*b.norm());
    }
}


// * * * * * * * * * * * Partition of unity, additivity * * * * * * * * * * //

TEST(elementIntegrals, partitionOfUnity)
{
    const triangleNodes T = coverTriangle();
    const polygonMoments m = moments(T, pentagon);

    EXPECT_GT(m.area, 0);
    EXPECT_NEAR(m.w.sum(), m.area, 1e-14*m.area);
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(m.ww.row(i).sum(), m.w(i), 1e-14*m.area);
    }
    EXPECT_LT((m.ww - m.ww.transpose()).norm(), 1e-15*m.area);

    // Body force and mass of a translation both add up to the whole
    const vector6 f = bodyForce(m, Eigen::Vector2d(0, -1), 2.0);
    EXPECT_NEAR(f(1) + f(3) + f(5), -2.0*m.area, 1e-14*m.area);
}


TEST(elementIntegrals, additivity)
{
    const triangleNodes T = coverTriangle();
    // Split the pentagon along the chord from vertex 0 to vertex 2
    const baryLoop left = {pentagon[0], pentagon[1], pentagon[2]};
    const baryLoop right = {pentagon[0], pentagon[2], pentagon[3], pentagon[4]};

    const polygonMoments whole = moments(T, pentagon);
    const polygonMoments sum = moments(T, left) + moments(T, right);
    EXPECT_LT(relativeDifference(sum, whole), 1e-14);

    // And a split along a chord that is not a diagonal (new vertices)
    const baryPoint a = 0.5*(pentagon[0] + pentagon[1]);
    const baryPoint b = 0.25*pentagon[3] + 0.75*pentagon[4];
    const baryLoop one = {a, pentagon[1], pentagon[2], pentagon[3], b};
    const baryLoop two = {b, pentagon[4], pentagon[0], a};
    EXPECT_LT(relativeDifference(moments(T, one) + moments(T, two), whole), 1e-14);
}


// * * * * * * * * * * * * * * Non-convex polygon  * * * * * * * * * * * * * //

TEST(elementIntegrals, nonConvexAgainstHandTriangulation)
{
    const triangleNodes T = rightTriangle();

    // The L as two rectangles, each two CCW triangles, by hand
    const Eigen::Vector2d p0(0.5, 0.5), p1(2.5, 0.5), p2(2.5, 1.0),
        p3(0.5, 1.0), p4(1.0, 1.0), p5(1.0, 2.5), p6(0.5, 2.5);
    const polygonMoments reference =
        triangleReference(T, p0, p1, p2) + triangleReference(T, p0, p2, p3)
      + triangleReference(T, p3, p4, p5) + triangleReference(T, p3, p5, p6);
    ASSERT_NEAR(reference.area, 1.0 + 0.75, 1e-15);

    // Every starting vertex, so the fan apex is sometimes the reflex one
    for (std::size_t s = 0; s < lShape.size(); ++s)
    {
        cartesianLoop rotated(lShape);
        std::rotate(rotated.begin(), rotated.begin() + s, rotated.end());
        const polygonMoments m = moments(T, rotated);
        EXPECT_LT(relativeDifference(m, reference), 1e-14) << "start " << s;
    }

    // Centroid against the rectangles' centroids
    const Eigen::Vector2d c =
        (1.0*Eigen::Vector2d(1.5, 0.75) + 0.75*Eigen::Vector2d(0.75, 1.75))/1.75;
    EXPECT_NEAR((centroid(T, moments(T, lShape)) - c).norm(), 0, 1e-14);
}


TEST(elementIntegrals, orientationDoesNotMatter)
{
    const triangleNodes T = rightTriangle();
    cartesianLoop reversed(lShape.rbegin(), lShape.rend());

    const polygonMoments ccw = moments(T, lShape);
    const polygonMoments cw = moments(T, reversed);
    EXPECT_GT(cw.area, 0);
    EXPECT_LT(relativeDifference(cw, ccw), 1e-14);

    // A clockwise cover triangle too: same nodes, two swapped
    triangleNodes Tcw = T;
    Tcw.col(1).swap(Tcw.col(2));
    const polygonMoments swapped = moments(Tcw, lShape);
    EXPECT_NEAR(swapped.area, ccw.area, 1e-14);
    EXPECT_NEAR(swapped.w(0), ccw.w(0), 1e-14);
    EXPECT_NEAR(swapped.w(1), ccw.w(2), 1e-14);
    EXPECT_NEAR(swapped.ww(1, 1), ccw.ww(2, 2), 1e-14);
}


TEST(elementIntegrals, barycentricRoundTrip)
{
    const triangleNodes T = coverTriangle();
    const Eigen::Vector2d x(0.8, 0.7);
    const baryPoint lambda = toBarycentric(T, x);
    EXPECT_NEAR(lambda.sum(), 1.0, 1e-15);
    EXPECT_NEAR((lambda - hatValues(T, x)).norm(), 0, 1e-15);
    EXPECT_NEAR((toCartesian(T, lambda) - x).norm(), 0, 1e-15);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_NEAR((toBarycentric(T, Eigen::Vector2d(T.col(k)))
            - Eigen::Vector3d::Unit(k)).norm(), 0, 1e-15);
    }
}


// * * * * * * * * * * * * * * * * * Slivers  * * * * * * * * * * * * * * * //

TEST(elementIntegrals, sliverStripAlongEdge)
{
    // The strip 0 <= lambda3 <= h: area ratio 2h - h^2 ~ 1e-10
    const triangleNodes T = coverTriangle();
    const double A = signedArea(T);
    const double h = 5e-11;
    const baryLoop strip = {{1, 0, 0}, {0, 1, 0}, {0, 1 - h, h}, {1 - h, 0, h}};
    const polygonMoments m = moments(T, strip);

    // Closed forms, from dA = 2A dlambda1 dlambda3 on 0 <= lambda3 <= h,
    // written without cancellation
    const double q4 = h*(4 - 6*h + 4*h*h - h*h*h);     // 1 - (1 - h)^4
    const double q3 = h*(3 - 3*h + h*h);               // 1 - (1 - h)^3
    polygonMoments exact;
    exact.area = 2*A*(h - h*h/2);
    exact.w << 2*A*q3/6, 2*A*q3/6, 2*A*(h*h/2 - h*h*h/3);
    exact.ww(0, 0) = exact.ww(1, 1) = 2*A*q4/12;
    exact.ww(0, 1) = exact.ww(1, 0) = 2*A*q4/24;
    exact.ww(0, 2) = exact.ww(2, 0) = exact.ww(1, 2) = exact.ww(2, 1) =
        A*(h*h/2 - 2*h*h*h/3 + h*h*h*h/4);
    exact.ww(2, 2) = 2*A*(h*h*h/3 - h*h*h*h/4);

    EXPECT_NEAR(areaRatio(T, m), 2*h - h*h, 1e-14*h);
    const double err = relativeDifference(m, exact);
    EXPECT_LT(err, 1e-12);
    RecordProperty("stripRelativeError", scientific(err));
    // Every entry on its own scale, including the h^3 one
    EXPECT_NEAR(m.ww(2, 2), exact.ww(2, 2), 1e-12*exact.ww(2, 2));

    // The mass stays positive definite, scaled with the area
    const matrix66 M = mass(m, 1.0, 1.0);
    EXPECT_TRUE(M.allFinite());
    EXPECT_NEAR(M.sum()/2, m.area, 1e-13*m.area);
}


TEST(elementIntegrals, sliverTinyCornerInCartesian)
{
    // A triangle of size delta at node 1, area ratio ~1e-10
    const triangleNodes T = coverTriangle();
    const double delta = 1e-5;
    const Eigen::Vector2d x1 = T.col(0);
    const Eigen::Vector2d a = x1 + delta*Eigen::Vector2d(0.2, 0.05);
    const Eigen::Vector2d b = x1 + delta*Eigen::Vector2d(0.9, 0.3);
    const Eigen::Vector2d c = x1 + delta*Eigen::Vector2d(0.4, 0.6);
    const polygonMoments m = moments(T, cartesianLoop{a, b, c});
    const polygonMoments reference = triangleReference(T, a, b, c);

    EXPECT_GT(areaRatio(T, m), 1e-11);
    EXPECT_LT(areaRatio(T, m), 1e-9);
    // Limited by the rounding of the vertices at the scale of T
    // (about eps |x1|/delta ~ 1e-11), not by the integration
    const double err = relativeDifference(m, reference);
    EXPECT_LT(err, 1e-9);
    RecordProperty("cornerRelativeError", scientific(err));
    EXPECT_NEAR(m.w.sum(), m.area, 1e-14*m.area);
}


// * * * * * * * * * * * * * * * * Stiffness  * * * * * * * * * * * * * * * //

TEST(elementIntegrals, rigidBodyModes)
{
    const triangleNodes T = coverTriangle();
    const double area = moments(T, pentagon).area;
    const matrix66 K = stiffness(T, area, planeStressD(4e8, 0.3), 0.7);

    vector6 tx, ty, rot;
    for (int k = 0; k < 3; ++k)
    {
        tx.segment<2>(2*k) << 1, 0;
        ty.segment<2>(2*k) << 0, 1;
        rot.segment<2>(2*k) << -T(1, k), T(0, k);
    }
    for (const vector6& mode : {tx, ty, rot})
    {
        EXPECT_LT((K*mode).norm(), 1e-12*K.norm()*mode.norm());
    }
    EXPECT_LT((K - K.transpose()).norm(), 1e-15*K.norm());
    // Exactly three zero modes: rank 3
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<matrix66>(K).eigenvalues();
    EXPECT_GT(ev(3), 1e-6*ev(5));
}


TEST(elementIntegrals, patchTestLinearField)
{
    const triangleNodes T = coverTriangle();
    Eigen::Matrix2d G;
    G << 1e-3, 4e-4,
         -2e-4, 3e-4;
    const Eigen::Vector2d c0(0.1, -0.2);
    vector6 d;
    for (int k = 0; k < 3; ++k)
    {
        d.segment<2>(2*k) = G*T.col(k) + c0;
    }
    const Eigen::Vector3d eps = strainMatrix(T)*d;
    EXPECT_NEAR(eps(0), G(0, 0), 1e-15);
    EXPECT_NEAR(eps(1), G(1, 1), 1e-15);
    EXPECT_NEAR(eps(2), G(0, 1) + G(1, 0), 1e-15);

    // A clockwise triangle gives the same B
    triangleNodes Tcw = T;
    Tcw.col(1).swap(Tcw.col(2));
    vector6 dcw = d;
    dcw.segment<2>(2).swap(dcw.segment<2>(4));
    EXPECT_NEAR((strainMatrix(Tcw)*dcw - eps).norm(), 0, 1e-15);
}


TEST(elementIntegrals, uniformStrainEnergy)
{
    const triangleNodes T = coverTriangle();
    const Eigen::Matrix3d D = planeStressD(2.1e11, 0.3);
    const double t = 0.25;
    const double area = moments(T, pentagon).area;
    Eigen::Matrix2d G;
    G << 2e-4, -1e-4,
         3e-4, -5e-4;
    vector6 d;
    for (int k = 0; k < 3; ++k)
    {
        d.segment<2>(2*k) = G*T.col(k);
    }
    const Eigen::Vector3d eps(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
    const double energy = 0.5*d.dot(stiffness(T, area, D, t)*d);
    const double exact = 0.5*area*t*eps.dot(D*eps);
    EXPECT_NEAR(energy, exact, 1e-12*exact);
}


// * * * * * * * * * * * * * * * * Tractions  * * * * * * * * * * * * * * * //

TEST(elementIntegrals, tractionAlongTriangleEdge)
{
    const triangleNodes T = coverTriangle();
    const double L = (T.col(1) - T.col(0)).norm();
    const double t = 0.4;
    const Eigen::Vector2d tr(3.0, -2.0);
    const vector6 f =
        edgeTraction(T, baryPoint(1, 0, 0), baryPoint(0, 1, 0), tr, t);
    EXPECT_NEAR((f.segment<2>(0) - t*L/2*tr).norm(), 0, 1e-14*L);
    EXPECT_NEAR((f.segment<2>(2) - t*L/2*tr).norm(), 0, 1e-14*L);
    EXPECT_EQ(f.segment<2>(4).norm(), 0.0);

    // A linear traction: 0 at node 1, tq at node 2, gives L/6 and L/3
    const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
    const vector6 g =
        edgeTraction(T, baryPoint(1, 0, 0), baryPoint(0, 1, 0), zero, tr, t);
    EXPECT_NEAR((g.segment<2>(0) - t*L/6*tr).norm(), 0, 1e-14*L);
    EXPECT_NEAR((g.segment<2>(2) - t*L/3*tr).norm(), 0, 1e-14*L);
}


TEST(elementIntegrals, tractionOnInteriorSegment)
{
    // A segment of an element's boundary across T: the loads add up to
    // the resultant, and the moment about x3 matches the segment's
    const triangleNodes T = coverTriangle();
    const baryPoint p(0.6, 0.2, 0.2), q(0.1, 0.3, 0.6);
    const Eigen::Vector2d xp = toCartesian(T, p), xq = toCartesian(T, q);
    const double L = (xq - xp).norm();
    const Eigen::Vector2d tr(0.0, 5.0);
    const vector6 f = edgeTraction(T, p, q, tr, 1.0);

    Eigen::Vector2d resultant = Eigen::Vector2d::Zero();
    double moment = 0;
    for (int k = 0; k < 3; ++k)
    {
        resultant += f.segment<2>(2*k);
        const Eigen::Vector2d r = T.col(k);
        moment += r.x()*f(2*k + 1) - r.y()*f(2*k);
    }
    EXPECT_NEAR((resultant - L*tr).norm(), 0, 1e-14*L*tr.norm());
    const Eigen::Vector2d mid = 0.5*(xp + xq);
    EXPECT_NEAR(moment, L*(mid.x()*tr.y() - mid.y()*tr.x()), 1e-13*L*tr.norm());
}


// * * * * * * * * * * * * * * * * Bad input  * * * * * * * * * * * * * * * //

TEST(elementIntegrals, badInput)
{
    triangleNodes flat;
    flat << 0, 1, 2,
            0, 1, 2;
    EXPECT_THROW(moments(flat, wholeTriangle), std::invalid_argument);
    EXPECT_THROW(strainMatrix(flat), std::invalid_argument);
    EXPECT_THROW
    (
        moments(coverTriangle(), baryLoop{{1, 0, 0}, {0, 1, 0}}),
        std::invalid_argument
    );
}
