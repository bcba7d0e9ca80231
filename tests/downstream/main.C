/*---------------------------------------------------------------------------*\
Description
    Downstream consumer of the installed nmmSolid package: links the
    library for real (parses a dictionary with a macro), finds a contact
    law that registered itself when the library was loaded (nothing here
    names its class) and prints the version it was built against.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/contact/contactLaw/contactLaw.H"
#include "nmmSolid/global/version.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include <algorithm>
#include <iostream>

int main()
{
    const nmm::dictionary d =
        nmm::dictionary::parse("a 20; b #eval \"$a + 1\";", "downstream");
    if (d.get<int>("b") != 21)
    {
        std::cerr << "unexpected value of b\n";
        return 1;
    }
    const auto laws = nmm::contactLaw::types();
    if (std::find(laws.begin(), laws.end(), "mohrCoulomb") == laws.end())
    {
        std::cerr << "contact law mohrCoulomb not registered\n";
        return 1;
    }
    std::cout << "nmmSolid " << nmm::versionString << '\n';
    return 0;
}
