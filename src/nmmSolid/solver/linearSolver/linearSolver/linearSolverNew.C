#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"

#include "nmmSolid/solver/linearSolver/cholmod/cholmod.H"
#include "nmmSolid/solver/linearSolver/simplicialLDLT/simplicialLDLT.H"

namespace nmm
{

namespace
{

template<class Type>
bool add(const char* name)
{
    return linearSolver::selector::add
    (
        name,
        [](const dictionary& d) { return std::make_unique<Type>(d); },
        &linearSolver::keywords()
    );
}

//- Registered on first use, not by static objects in the types' files:
//  the library is static, and the linker drops object files that nothing
//  refers to
void addBuiltInTypes()
{
    static const bool added =
        add<cholmod>("cholmod") && add<simplicialLDLT>("simplicialLDLT");
    (void)added;
}

} // End anonymous namespace


std::unique_ptr<linearSolver> linearSolver::New(const dictionary& linearSolverDict)
{
    addBuiltInTypes();
    keywords().validate(linearSolverDict);
    const std::string type = keywords().get<std::string>(linearSolverDict, "type");
    return selector::New(type, linearSolverDict, linearSolverDict);
}


std::vector<std::string> linearSolver::types()
{
    addBuiltInTypes();
    return selector::names();
}

} // End namespace nmm
