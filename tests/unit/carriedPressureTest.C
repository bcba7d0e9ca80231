// Unit tests of the rule that carries a fracture's pressure onto the
// contacts of the next step: a contact that stays keeps its pressure, one
// that appears takes the nearest between the same bodies, else the
// nearest at all.
#include "nmmSolid/coupling/carriedPressure/carriedPressure.H"

#include <gtest/gtest.h>

using nmm::carriedPressure;
using nmm::locatedContact;

namespace
{

locatedContact contact(int id, double x, double y, int edgeBody, int vertexBody)
{
    locatedContact c;
    c.key = {id, 0, 0, 0};
    c.point = {x, y};
    c.bodies = {edgeBody, vertexBody};
    return c;
}

} // End anonymous namespace


TEST(carriedPressure, aContactThatStaysKeepsItsPressureInAnyOrder)
{
    const std::vector<locatedContact> before{contact(1, 0, 0, 0, 1), contact(2, 1, 0, 0, 1)};
    const std::vector<locatedContact> now{contact(2, 5, 5, 0, 1), contact(1, 9, 9, 0, 1)};
    EXPECT_EQ(carriedPressure(before, {10, 20}, now), (std::vector<double>{20, 10}));
}


TEST(carriedPressure, aNewContactTakesTheNearestBetweenTheSameBodies)
{
    const std::vector<locatedContact> before
        {contact(1, 0, 0, 0, 1), contact(2, 2, 0, 1, 0), contact(3, 1.1, 0, 2, 3)};
    // Nearest of all is contact 3 (bodies 2, 3); of bodies 0 and 1 (either
    // way round) contact 2
    EXPECT_EQ(carriedPressure(before, {10, 20, 30}, {contact(7, 1.2, 0, 0, 1)}),
              std::vector<double>{20});
    // Bodies with no contact before: the nearest at all
    EXPECT_EQ(carriedPressure(before, {10, 20, 30}, {contact(8, 0.2, 0, 4, 5)}),
              std::vector<double>{10});
}


TEST(carriedPressure, withoutAPressureBeforeThereIsNone)
{
    EXPECT_EQ(carriedPressure({}, {}, {contact(1, 0, 0, 0, 1), contact(2, 1, 0, 0, 1)}),
              (std::vector<double>{0, 0}));
}
