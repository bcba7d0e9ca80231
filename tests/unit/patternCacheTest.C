// Unit tests of nmm::patternCache: triplets summed into a kept pattern
// against Eigen's setFromTriplets of the same list, bit for bit, when the
// pattern is reused and when the positions change.

#include "nmmSolid/solver/patternCache/patternCache.H"

#include <gtest/gtest.h>

#include <random>

namespace
{

using nmm::patternCache;
using sparseMatrix = Eigen::SparseMatrix<double>;

//- n x n positions with duplicates (about a third of the list repeats an
//  earlier position, as element matrices sharing unknowns do)
std::vector<std::pair<int, int>> randomPositions(int n, int count, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_int_distribution<int> index(0, n - 1);
    std::vector<std::pair<int, int>> p;
    for (int t = 0; t < count; ++t)
    {
        if (t > 0 && t % 3 == 0) p.push_back(p[std::size_t(index(gen)) % p.size()]);
        else p.emplace_back(index(gen), index(gen));
    }
    return p;
}


void fill
(
    patternCache& cache,
    const std::vector<std::pair<int, int>>& positions,
    unsigned seed
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> value(-1, 1);
    auto& t = cache.triplets();
    t.clear();
    for (const auto& [i, j] : positions) t.emplace_back(i, j, value(gen)*1e3);
}


sparseMatrix direct(const std::vector<Eigen::Triplet<double>>& t, int n)
{
    sparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
}


//- A fixed matrix (the mass matrix's role) of count entries, inside and
//  outside a list's pattern
sparseMatrix extraMatrix(int n, int count, unsigned seed, double offset)
{
    std::vector<Eigen::Triplet<double>> m;
    for (const auto& [i, j] : randomPositions(n, count, seed)) m.emplace_back(i, j, offset + i - j);
    sparseMatrix M(n, n);
    M.setFromTriplets(m.begin(), m.end());
    return M;
}


//- The list with c times the entries of M appended, in M's order
std::vector<Eigen::Triplet<double>> withExtra
(
    std::vector<Eigen::Triplet<double>> t,
    const sparseMatrix& M,
    double c
)
{
    for (int j = 0; j < M.outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(M, j); it; ++it)
        {
            t.emplace_back(int(it.row()), j, c*it.value());
        }
    }
    return t;
}


void expectIdentical(const sparseMatrix& a, const sparseMatrix& b)
{
    ASSERT_EQ(a.rows(), b.rows());
    ASSERT_EQ(a.nonZeros(), b.nonZeros());
    for (int j = 0; j <= a.outerSize(); ++j)
    {
        ASSERT_EQ(a.outerIndexPtr()[j], b.outerIndexPtr()[j]);
    }
    for (int k = 0; k < a.nonZeros(); ++k)
    {
        ASSERT_EQ(a.innerIndexPtr()[k], b.innerIndexPtr()[k]);
        // Exactly equal: the runs must not depend on the path
        ASSERT_EQ(a.valuePtr()[k], b.valuePtr()[k]) << "entry " << k;
    }
}


//- The cache's sum of a list filled from seed plus c M, against
//  setFromTriplets of the list with c M's entries appended
void expectSumWithExtra
(
    patternCache& cache,
    const std::vector<std::pair<int, int>>& positions,
    unsigned seed,
    const sparseMatrix& M,
    double c
)
{
    const int n = int(M.rows());
    fill(cache, positions, seed);
    const auto appended = withExtra(cache.triplets(), M, c);
    expectIdentical(cache.assemble(n, n, &M, c), direct(appended, n));
}

} // End anonymous namespace


TEST(patternCache, sumsAsSetFromTripletsBitForBit)
{
    const int n = 40;
    const auto positions = randomPositions(n, 900, 1);
    patternCache cache;
    fill(cache, positions, 2);
    const sparseMatrix& A = cache.assemble(n, n);
    expectIdentical(A, direct(cache.triplets(), n));
    EXPECT_EQ(cache.made(), 1);
    EXPECT_EQ(cache.reused(), 0);
}


TEST(patternCache, theSamePositionsReuseThePatternWithNewValues)
{
    // On one thread, and on OpenMP's (the values split among them)
    for (const bool threaded : {false, true})
    {
        SCOPED_TRACE(threaded ? "on threads" : "on one thread");
        const int n = 40;
        const auto positions = randomPositions(n, 900, 3);
        patternCache cache;
        cache.threaded(threaded);
        fill(cache, positions, 4);
        cache.assemble(n, n);
        for (unsigned step = 5; step < 8; ++step)
        {
            fill(cache, positions, step);
            const sparseMatrix& A = cache.assemble(n, n);
            expectIdentical(A, direct(cache.triplets(), n));
        }
        EXPECT_EQ(cache.made(), 1);
        EXPECT_EQ(cache.reused(), 3);
    }
}


TEST(patternCache, changedPositionsMakeANewPattern)
{
    const int n = 40;
    auto positions = randomPositions(n, 900, 9);
    patternCache cache;
    fill(cache, positions, 10);
    cache.assemble(n, n);

    // One position moved, one added: a stale pattern would put a value
    // where the matrix has no entry, or drop one
    positions[17] = {n - 1, 0};
    positions.emplace_back(0, n - 1);
    fill(cache, positions, 11);
    expectIdentical(cache.assemble(n, n), direct(cache.triplets(), n));

    // Another size with the same list
    fill(cache, positions, 12);
    expectIdentical(cache.assemble(n + 5, n + 5), direct(cache.triplets(), n + 5));
    EXPECT_EQ(cache.made(), 3);
}


TEST(patternCache, slotsAreWhereEachTripletWasSummed)
{
    const int n = 30;
    const auto positions = randomPositions(n, 500, 13);
    patternCache cache;
    fill(cache, positions, 14);
    const sparseMatrix& A = cache.assemble(n, n);
    for (std::size_t t = 0; t < positions.size(); ++t)
    {
        const int s = cache.slot(t);
        const auto [i, j] = positions[t];
        ASSERT_GE(s, A.outerIndexPtr()[j]);
        ASSERT_LT(s, A.outerIndexPtr()[j + 1]);
        ASSERT_EQ(A.innerIndexPtr()[s], i);
    }
}


TEST(patternCache, anExtraMatrixIsSummedAsItsEntriesAppendedToTheList)
{
    const int n = 40;
    const auto positions = randomPositions(n, 900, 15);
    sparseMatrix M = extraMatrix(n, 300, 16, 0.25);

    patternCache cache;
    for (unsigned step = 17; step < 21; ++step)
    {
        expectSumWithExtra(cache, positions, step, M, 1.0/step);
    }
    EXPECT_EQ(cache.made(), 1);
    EXPECT_EQ(cache.reused(), 3);

    // Another extra pattern, and none: each a new pattern
    M.coeffRef(n - 1, 0) += 1;
    M.makeCompressed();
    expectSumWithExtra(cache, positions, 22, M, 2);
    fill(cache, positions, 23);
    expectIdentical(cache.assemble(n, n), direct(cache.triplets(), n));
    EXPECT_EQ(cache.made(), 3);
}


TEST(patternCache, onThreadsEachValueIsTheSameSumBitForBit)
{
    // The sums on OpenMP's threads against setFromTriplets, through
    // reuse, a moved position and an extra matrix, as a run's steps have
    const int n = 60;
    auto positions = randomPositions(n, 2000, 24);
    const sparseMatrix M = extraMatrix(n, 400, 25, 0.5);

    patternCache cache;
    cache.threaded(true);
    for (unsigned step = 26; step < 34; ++step)
    {
        if (step == 30) positions[101] = {0, n - 1};
        expectSumWithExtra(cache, positions, step, M, 3.0/step);
    }
    // The moved position is found by the gather, and the pattern made anew
    EXPECT_EQ(cache.made(), 2);
    EXPECT_EQ(cache.reused(), 6);
}

