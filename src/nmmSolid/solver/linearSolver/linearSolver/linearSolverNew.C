#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"

namespace nmm
{

std::unique_ptr<linearSolver> linearSolver::New(const dictionary& linearSolverDict)
{
    keywords().validate(linearSolverDict);
    const std::string type = keywords().get<std::string>(linearSolverDict, "type");
    return selector::New(type, linearSolverDict, linearSolverDict);
}


std::vector<std::string> linearSolver::types()
{
    return selector::names();
}

} // End namespace nmm
