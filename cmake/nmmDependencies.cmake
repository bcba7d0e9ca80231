# Third-party libraries, all from Debian packages (etc/debianPackages).
# The fuzz build (NMM_FUZZ) builds only the dictionary reader, which needs
# none of them.
if(NMM_FUZZ)
    return()
endif()
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CHOLMOD REQUIRED)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(CGAL REQUIRED)
find_package(Threads REQUIRED)
# The per-body parts of a step (nmm::bodySystems, the contact-space solve)
# run on OpenMP's threads; CHOLMOD already loads libgomp
find_package(OpenMP REQUIRED COMPONENTS CXX)
if(NOT NMM_FUZZ)
    if(NMM_BUILD_TESTS)
        find_package(GTest REQUIRED)
    endif()
    if(NMM_BUILD_BENCHMARKS)
        find_package(benchmark REQUIRED)
    endif()
endif()
