#include "nmmSolid/contact/contactSolver/contactSolver/contactSolver.H"

namespace nmm
{

namespace
{

//- The paper's method, which a case that names none gets
const char* const defaultMethod = "penalty";

} // End anonymous namespace


void contactSolver::declareMethod(keywordTable& t)
{
    t.word("method", "how contacts are enforced").defaultValue(defaultMethod);
}


std::unique_ptr<contactSolver> contactSolver::New(const dictionary& contactDict)
{
    const entry* e = contactDict.findEntry("method");
    const std::string method = e
        ? dictionary::readEntryValue<std::string>(*e) : std::string(defaultMethod);
    return selector::New(method, contactDict, contactDict, "method");
}


std::vector<std::string> contactSolver::types()
{
    return selector::names();
}


void contactSolver::printHelp(std::ostream& os)
{
    selector::printKeywords(os);
}


std::vector<contactRecord> contactSolver::upcoming
(
    const Eigen::Matrix2Xd& patchD0,
    const std::vector<contactRecord>& history,
    bool atStart
)
{
    // The same search solve() starts with, so the same contacts
    contacts().beginStep(patchD0, history, atStart);
    return contacts().records();
}

} // End namespace nmm
