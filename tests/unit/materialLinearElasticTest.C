// Isotropic linear elasticity: D, sigma_zz and wave speeds against closed
// forms in plane strain and plane stress, and every input error.

#include "nmmSolid/material/linearElastic/linearElastic.H"
#include "testTools.H"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using nmm::dictionary;
using nmm::IOerror;
using nmm::planeModel;
using testing::HasSubstr;
using testing::Not;

namespace
{

const char* const fileName = "constant/mechanicalProperties";

//- The material of "name { ... }" (the materials dictionary's body)
std::unique_ptr<nmm::solidMaterial> read
(
    const std::string& text,
    const std::string& name = "rock"
)
{
    const dictionary materials = dictionary::parse(text, fileName);
    return nmm::solidMaterial::New(materials.lookupEntry(name));
}

std::unique_ptr<nmm::solidMaterial> elastic(double E, double nu)
{
    return read("rock { type linearElastic; E " + nmm::formatScalar(E)
        + "; nu " + nmm::formatScalar(nu) + "; rho 2650; }");
}

const nmm::linearElastic& asElastic(const nmm::solidMaterial& m)
{
    return dynamic_cast<const nmm::linearElastic&>(m);
}

// The IOerror reading text raises (fails the test if none)
IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

// (E, nu) pairs covering auxetic, zero, rock-like and nearly incompressible
const std::vector<std::pair<double, double>> moduli
{
    {4e8, 0.3}, {4e10, 0.25}, {1, 0}, {7e9, -0.5}, {2.1e11, 0.49}, {3e6, -0.99}
};

// Relative closeness of two matrices, entry by entry
void expectMatrixNear
(
    const Eigen::Matrix3d& a,
    const Eigen::Matrix3d& b,
    const std::string& what
)
{
    const double scale = b.cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
        {
            EXPECT_NEAR(a(i, j), b(i, j), 1e-13*scale)
                << what << " entry (" << i << "," << j << ")";
        }
    }
}

void expectSymmetricPositiveDefinite(const Eigen::Matrix3d& D, const std::string& what)
{
    EXPECT_EQ(D, D.transpose()) << what;
    EXPECT_EQ(Eigen::LLT<Eigen::Matrix3d>(D).info(), Eigen::Success) << what;
    const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(D).eigenvalues();
    EXPECT_GT(eig.minCoeff(), 0) << what;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Elasticity  * * * * * * * * * * * * * * * //

TEST(materialLinearElastic, readsTheCaseFormatExample)
{
    const auto m = read("rock { type linearElastic; E 4e8; nu 0.3; rho 2650; }");
    EXPECT_EQ(m->name(), "rock");
    EXPECT_EQ(m->type(), "linearElastic");
    EXPECT_EQ(asElastic(*m).E(), 4e8);
    EXPECT_EQ(asElastic(*m).nu(), 0.3);
    EXPECT_TRUE(m->hasDensity());
    EXPECT_EQ(m->density(), 2650);
    EXPECT_EQ(m->stiffnessModulus(), 4e8);
    EXPECT_FALSE(m->hasThermalExpansion());
    EXPECT_EQ(m->where().fileName(), fileName);
    EXPECT_EQ(m->where().line, 1);
}


TEST(materialLinearElastic, planeStrainMatrixIsTheClosedForm)
{
    for (const auto& [E, nu] : moduli)
    {
        const std::string what = "E " + nmm::formatScalar(E) + " nu " + nmm::formatScalar(nu);
        const Eigen::Matrix3d D = elastic(E, nu)->elasticityMatrix(planeModel::planeStrain);

        Eigen::Matrix3d expected;
        expected << 1 - nu, nu, 0,
                    nu, 1 - nu, 0,
                    0, 0, (1 - 2*nu)/2;
        expected *= E/((1 + nu)*(1 - 2*nu));
        expectMatrixNear(D, expected, what);
        expectSymmetricPositiveDefinite(D, what);
    }
}


TEST(materialLinearElastic, planeStrainMatrixFromLameConstants)
{
    for (const auto& [E, nu] : moduli)
    {
        const auto m = elastic(E, nu);
        const double lambda = E*nu/((1 + nu)*(1 - 2*nu));
        const double mu = E/(2*(1 + nu));
        EXPECT_NEAR(asElastic(*m).lambda(), lambda, 1e-14*E);
        EXPECT_NEAR(asElastic(*m).mu(), mu, 1e-14*E);

        Eigen::Matrix3d expected;
        expected << lambda + 2*mu, lambda, 0,
                    lambda, lambda + 2*mu, 0,
                    0, 0, mu;
        expectMatrixNear(m->elasticityMatrix(planeModel::planeStrain), expected,
            "nu " + nmm::formatScalar(nu));
    }
}


TEST(materialLinearElastic, planeStressMatrixIsTheClosedForm)
{
    for (const auto& [E, nu] : moduli)
    {
        const std::string what = "E " + nmm::formatScalar(E) + " nu " + nmm::formatScalar(nu);
        const Eigen::Matrix3d D = elastic(E, nu)->elasticityMatrix(planeModel::planeStress);

        Eigen::Matrix3d expected;
        expected << 1, nu, 0,
                    nu, 1, 0,
                    0, 0, (1 - nu)/2;
        expected *= E/(1 - nu*nu);
        expectMatrixNear(D, expected, what);
        expectSymmetricPositiveDefinite(D, what);
    }
}


TEST(materialLinearElastic, bothModelsShareTheShearModulus)
{
    for (const auto& [E, nu] : moduli)
    {
        const auto m = elastic(E, nu);
        const double mu = E/(2*(1 + nu));
        EXPECT_NEAR(m->elasticityMatrix(planeModel::planeStrain)(2, 2), mu, 1e-14*mu);
        EXPECT_NEAR(m->elasticityMatrix(planeModel::planeStress)(2, 2), mu, 1e-14*mu);

        // Engineering shear strain: tau = mu gamma
        const Eigen::Vector3d sigma =
            m->elasticityMatrix(planeModel::planeStress)*Eigen::Vector3d(0, 0, 2e-4);
        EXPECT_NEAR(sigma(2), mu*2e-4, 1e-14*mu);
        EXPECT_EQ(sigma(0), 0);
        EXPECT_EQ(sigma(1), 0);
    }
}


TEST(materialLinearElastic, uniaxialStressInPlaneStress)
{
    // A bar pulled along x: eps = (s/E, -nu s/E, 0) gives (s, 0, 0)
    for (const auto& [E, nu] : moduli)
    {
        const double s = 1.7e6;
        const auto m = elastic(E, nu);
        const Eigen::Vector3d eps(s/E, -nu*s/E, 0);
        const Eigen::Vector3d sigma = m->elasticityMatrix(planeModel::planeStress)*eps;
        EXPECT_NEAR(sigma(0), s, 1e-12*s) << "nu " << nu;
        EXPECT_NEAR(sigma(1), 0, 1e-12*s) << "nu " << nu;
        EXPECT_EQ(sigma(2), 0);
        EXPECT_EQ(m->sigmaZZ(sigma, planeModel::planeStress), 0);
    }
}


TEST(materialLinearElastic, uniaxialStressInPlaneStrain)
{
    // sigma = (s, 0, 0) with eps_zz = 0 needs eps = ((1-nu^2) s/E,
    // -nu (1+nu) s/E, 0) and carries sigma_zz = nu s
    for (const auto& [E, nu] : moduli)
    {
        const double s = -3.2e5;
        const auto m = elastic(E, nu);
        const Eigen::Vector3d eps((1 - nu*nu)*s/E, -nu*(1 + nu)*s/E, 0);
        const Eigen::Vector3d sigma = m->elasticityMatrix(planeModel::planeStrain)*eps;
        const double tol = 1e-12*std::abs(s)/(1 - 2*nu);
        EXPECT_NEAR(sigma(0), s, tol) << "nu " << nu;
        EXPECT_NEAR(sigma(1), 0, tol) << "nu " << nu;
        EXPECT_EQ(sigma(2), 0);
        EXPECT_NEAR(m->sigmaZZ(sigma, planeModel::planeStrain), nu*s, tol) << "nu " << nu;
    }
}


TEST(materialLinearElastic, planeStrainSigmaZZKeepsEpsZZZero)
{
    for (const auto& [E, nu] : moduli)
    {
        const auto m = elastic(E, nu);
        const Eigen::Vector3d sigma(2.5e6, -1.1e6, 4e5);
        EXPECT_DOUBLE_EQ(m->sigmaZZ(sigma, planeModel::planeStrain), nu*(2.5e6 - 1.1e6));
        EXPECT_EQ(m->sigmaZZ(sigma, planeModel::planeStress), 0);

        // Three-dimensional Hooke's law with eps_zz = 0:
        // sigma_zz = lambda (eps_xx + eps_yy)
        const Eigen::Vector3d eps(3e-4, -1e-4, 2e-4);
        const Eigen::Vector3d s = m->elasticityMatrix(planeModel::planeStrain)*eps;
        const double lambda = E*nu/((1 + nu)*(1 - 2*nu));
        EXPECT_NEAR(m->sigmaZZ(s, planeModel::planeStrain), lambda*(eps(0) + eps(1)),
            1e-12*s.cwiseAbs().maxCoeff()) << "nu " << nu;
    }
}


TEST(materialLinearElastic, dimensionedValuesAsOpenFoamWritesThem)
{
    const auto m = read("rock { type linearElastic; E [1 -1 -2 0 0 0 0] 4e8;"
        " nu [0 0 0 0 0 0 0] 0.3; rho rho [1 -3 0 0 0 0 0] 2650; }");
    EXPECT_EQ(asElastic(*m).E(), 4e8);
    EXPECT_EQ(asElastic(*m).nu(), 0.3);
    EXPECT_EQ(m->density(), 2650);
}


// * * * * * * * * * * * * * * * * Wave speeds * * * * * * * * * * * * * * * //

TEST(materialLinearElastic, waveSpeedsAreTheClosedForms)
{
    const double E = 4e10, nu = 0.25, rho = 2650;
    const auto m = read("rock { type linearElastic; E 4e10; nu 0.25; rho 2650; }");

    const double lambda = E*nu/((1 + nu)*(1 - 2*nu));
    const double mu = E/(2*(1 + nu));
    const double cpStrain = std::sqrt((lambda + 2*mu)/rho);
    const double cpStress = std::sqrt(E/(rho*(1 - nu*nu)));
    const double cs = std::sqrt(mu/rho);
    const double c0 = std::sqrt(E/rho);

    EXPECT_NEAR(m->pWaveSpeed(planeModel::planeStrain), cpStrain, 1e-12*cpStrain);
    EXPECT_NEAR(m->pWaveSpeed(planeModel::planeStress), cpStress, 1e-12*cpStress);
    EXPECT_NEAR(m->sWaveSpeed(), cs, 1e-12*cs);
    EXPECT_NEAR(m->barWaveSpeed(), c0, 1e-12*c0);

    // nu = 1/4 in plane strain: lambda = mu, so c_p = sqrt(3) c_s
    EXPECT_NEAR(m->pWaveSpeed(planeModel::planeStrain), std::sqrt(3.0)*cs, 1e-12*cs);
    // A constrained body carries waves faster: c_p(strain) > c_p(stress) > c_0
    EXPECT_GT(cpStrain, cpStress);
    EXPECT_GT(cpStress, c0);
    EXPECT_GT(c0, cs);
}


TEST(materialLinearElastic, waveSpeedsAreTheDiagonalOfDOverRho)
{
    for (const auto& [E, nu] : moduli)
    {
        const auto m = elastic(E, nu);
        for (const planeModel p : {planeModel::planeStrain, planeModel::planeStress})
        {
            const Eigen::Matrix3d D = m->elasticityMatrix(p);
            const double cp = std::sqrt(D(0, 0)/2650);
            const double cs = std::sqrt(D(2, 2)/2650);
            EXPECT_NEAR(m->pWaveSpeed(p), cp, 1e-12*cp) << planeModelName(p) << " nu " << nu;
            EXPECT_NEAR(m->sWaveSpeed(), cs, 1e-12*cs) << planeModelName(p) << " nu " << nu;
        }
    }
}


// * * * * * * * * * * * * * Density and thermal * * * * * * * * * * * * * * //

TEST(materialLinearElastic, densityMayBeAbsentUntilItIsNeeded)
{
    const auto m = read("\n\nrock { type linearElastic; E 4e8; nu 0.3; }");
    EXPECT_FALSE(m->hasDensity());
    // The stiffness needs no density: a static analysis runs without it
    EXPECT_NO_THROW(m->elasticityMatrix(planeModel::planeStrain));

    for (const auto& err :
    {
        nmm::test::errorOf([&] { m->density(); }),
        nmm::test::errorOf([&] { m->pWaveSpeed(planeModel::planeStrain); }),
        nmm::test::errorOf([&] { m->sWaveSpeed(); }),
        nmm::test::errorOf([&] { m->barWaveSpeed(); })
    })
    {
        EXPECT_THAT(err.message(), HasSubstr("Material 'rock' (linearElastic)"));
        EXPECT_THAT(err.message(), HasSubstr("'rho' [kg/m^3]"));
        EXPECT_THAT(err.message(), HasSubstr("dynamic analysis"));
        EXPECT_EQ(err.keyword(), "rho");
        EXPECT_EQ(err.where().fileName(), fileName);
        EXPECT_EQ(err.where().line, 3);
    }
}


TEST(materialLinearElastic, thermalExpansionIsAPair)
{
    const auto m = read("rock { type linearElastic; E 4e8; nu 0.3; rho 2650;"
        " alpha 1.2e-5; Tref 293.15; }");
    EXPECT_TRUE(m->hasThermalExpansion());
    EXPECT_EQ(m->alpha(), 1.2e-5);
    EXPECT_EQ(m->Tref(), 293.15);

    const auto plain = read("rock { type linearElastic; E 4e8; nu 0.3; }");
    EXPECT_FALSE(plain->hasThermalExpansion());
    EXPECT_EQ(nmm::test::errorOf([&] { plain->alpha(); }).keyword(), "alpha");
    EXPECT_EQ(nmm::test::errorOf([&] { plain->Tref(); }).keyword(), "Tref");

    const IOerror noTref = errorReading
    (
        "rock { type linearElastic; E 4e8; nu 0.3; alpha 1e-5; }"
    );
    EXPECT_THAT(noTref.message(), HasSubstr("alpha is given without Tref"));
    EXPECT_EQ(noTref.keyword(), "alpha");

    const IOerror noAlpha = errorReading
    (
        "rock { type linearElastic; E 4e8; nu 0.3; Tref 293; }"
    );
    EXPECT_THAT(noAlpha.message(), HasSubstr("Tref is given without alpha"));
    EXPECT_EQ(noAlpha.keyword(), "Tref");

    const IOerror absoluteZero = errorReading
    (
        "rock { type linearElastic; E 4e8; nu 0.3; alpha 1e-5; Tref 0; }"
    );
    EXPECT_THAT(absoluteZero.message(), HasSubstr("out of range > 0"));
    EXPECT_EQ(absoluteZero.keyword(), "Tref");
}


// * * * * * * * * * * * * * * * * * Errors  * * * * * * * * * * * * * * * * //

TEST(materialLinearElastic, youngsModulusMustBePositive)
{
    for (const char* E : {"0", "-4e8", "-1e-300"})
    {
        const IOerror err = errorReading
        (
            std::string("rock\n{\n    type linearElastic;\n    E ") + E
          + ";\n    nu 0.3;\n}"
        );
        EXPECT_THAT(err.message(), HasSubstr("Material 'rock'")) << E;
        EXPECT_THAT(err.message(), HasSubstr("out of range > 0")) << E;
        EXPECT_THAT(err.message(), HasSubstr("Young's modulus")) << E;
        EXPECT_EQ(err.keyword(), "E");
        EXPECT_EQ(err.where().fileName(), fileName);
        EXPECT_EQ(err.where().line, 4);
    }
}


TEST(materialLinearElastic, valuesMustBeFinite)
{
    // 1e400 reads as infinity, which a "> 0" range alone would let through
    // (a reader that rejects the number itself is as good)
    const auto rejected = testing::AnyOf(HasSubstr("must be finite"), HasSubstr("1e"));

    const IOerror E = errorReading("rock\n{\n    type linearElastic;\n    E 1e400;\n    nu 0.3;\n}");
    EXPECT_THAT(E.message(), rejected);
    EXPECT_EQ(E.where().line, 4);

    const IOerror rho = errorReading("rock\n{\n    type linearElastic;\n    E 4e8;\n    nu 0.3;\n    rho 1e999;\n}");
    EXPECT_THAT(rho.message(), rejected);
    EXPECT_EQ(rho.where().line, 6);
}


TEST(materialLinearElastic, incompressibleIsRejected)
{
    const IOerror err = errorReading
    (
        "rock\n{\n    type linearElastic;\n    E 4e8;\n    nu 0.5;\n}"
    );
    EXPECT_THAT(err.message(), HasSubstr("Material 'rock'"));
    EXPECT_THAT(err.message(), HasSubstr("nu = 0.5 is an incompressible solid"));
    EXPECT_THAT(err.message(), HasSubstr("(-1, 0.5)"));
    EXPECT_EQ(err.keyword(), "nu");
    EXPECT_EQ(err.where().line, 5);

    // Also when written as OpenFOAM writes a dimensioned value
    const IOerror dimensioned = errorReading
    (
        "rock { type linearElastic; E 4e8; nu nu [0 0 0 0 0 0 0] 0.5; }"
    );
    EXPECT_THAT(dimensioned.message(), HasSubstr("incompressible"));
}


TEST(materialLinearElastic, poissonsRatioOutOfRange)
{
    for (const char* nu : {"0.7", "-1", "-1.5", "1"})
    {
        const IOerror err = errorReading
        (
            std::string("rock { type linearElastic; E 4e8; nu ") + nu + "; }"
        );
        EXPECT_THAT(err.message(), HasSubstr("out of range (-1, 0.5)")) << nu;
        EXPECT_EQ(err.keyword(), "nu") << nu;
    }
    // The ends are excluded, what is inside them is fine
    EXPECT_NO_THROW(read("rock { type linearElastic; E 4e8; nu 0.4999; }"));
    EXPECT_NO_THROW(read("rock { type linearElastic; E 4e8; nu -0.9999; }"));
}


TEST(materialLinearElastic, requiredKeywords)
{
    const IOerror noE = errorReading("rock { type linearElastic; nu 0.3; rho 2650; }");
    EXPECT_THAT(noE.message(), HasSubstr("Required keyword 'E'"));
    EXPECT_THAT(noE.message(), HasSubstr("Material 'rock'"));
    EXPECT_EQ(noE.keyword(), "E");

    const IOerror noNu = errorReading("rock { type linearElastic; E 4e8; }");
    EXPECT_THAT(noNu.message(), HasSubstr("Required keyword 'nu'"));
    EXPECT_EQ(noNu.keyword(), "nu");
}


TEST(materialLinearElastic, densityMustBePositive)
{
    for (const char* rho : {"0", "-2650"})
    {
        const IOerror err = errorReading
        (
            std::string("rock { type linearElastic; E 4e8; nu 0.3; rho ") + rho + "; }"
        );
        EXPECT_THAT(err.message(), HasSubstr("out of range > 0")) << rho;
        EXPECT_EQ(err.keyword(), "rho") << rho;
    }
}


TEST(materialLinearElastic, unknownKeywordHasDidYouMean)
{
    const IOerror err = errorReading
    (
        "rock\n{\n    type linearElastic;\n    E 4e8;\n    nu 0.3;\n    rhoo 2650;\n}"
    );
    EXPECT_THAT(err.message(), HasSubstr("Material 'rock'"));
    EXPECT_THAT(err.message(), HasSubstr("Unknown keyword 'rhoo' in linearElastic"));
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'rho'?"));
    EXPECT_EQ(err.where().line, 6);
}


TEST(materialLinearElastic, unknownTypeListsTheValidOnes)
{
    const IOerror err = errorReading
    (
        "rock\n{\n    type linearElastc;\n    E 4e8;\n    nu 0.3;\n}"
    );
    EXPECT_THAT(err.message(), HasSubstr("Material 'rock'"));
    EXPECT_THAT(err.message(), HasSubstr("Unknown solidMaterial type 'linearElastc'"));
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'linearElastic'?"));
    EXPECT_THAT(err.message(), HasSubstr("Valid solidMaterial types are"));
    EXPECT_THAT(err.message(), HasSubstr("\n    linearElastic"));
    EXPECT_EQ(err.keyword(), "type");
    EXPECT_EQ(err.where().line, 3);

    const IOerror far = errorReading("rock { type granite; E 4e8; nu 0.3; }");
    EXPECT_THAT(far.message(), Not(HasSubstr("did you mean")));
    EXPECT_THAT(far.message(), HasSubstr("\n    linearElastic"));
}


TEST(materialLinearElastic, missingTypeAndNotADictionary)
{
    const IOerror noType = errorReading("rock { E 4e8; nu 0.3; }");
    EXPECT_THAT(noType.message(), HasSubstr("Material 'rock': no 'type'"));
    EXPECT_THAT(noType.message(), HasSubstr("linearElastic"));

    const IOerror notDict = errorReading("rock linearElastic;");
    EXPECT_THAT(notDict.message(), HasSubstr("must be a dictionary"));
    EXPECT_EQ(notDict.keyword(), "rock");
}


// * * * * * * * * * * * * * * * * * Help  * * * * * * * * * * * * * * * * * //

TEST(materialLinearElastic, helpListsTheKeywords)
{
    EXPECT_THAT(nmm::solidMaterial::types(), testing::Contains("linearElastic"));

    std::ostringstream os;
    nmm::solidMaterial::printHelp(os);
    const std::string help = os.str();
    EXPECT_THAT(help, HasSubstr("linearElastic: isotropic linear elasticity"));
    EXPECT_THAT(help, HasSubstr("Young's modulus [Pa]"));
    EXPECT_THAT(help, HasSubstr("range (-1, 0.5)"));
    EXPECT_THAT(help, HasSubstr("density [kg/m^3]"));
    EXPECT_THAT(help, HasSubstr("Tref"));

    // Declared once, in this order: type, the law's keywords, shared ones
    std::vector<std::string> names;
    for (const auto& k : nmm::linearElastic::keywords().keywords()) names.push_back(k.name);
    EXPECT_EQ(names, (std::vector<std::string>{"type", "E", "nu", "rho", "alpha", "Tref"}));
}
