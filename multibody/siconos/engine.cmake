# Siconos 4.4 kernel (Debian libsiconos-kernel-dev: kernel and numerics). Found by its headers and libraries, not by
# its CMake package: Debian's siconos-config.cmake fails unless the `siconos` Python front end (and numpy) is installed
# too. Only the kernel and numerics are linked: libsiconos_mechanics links Debian's single-precision Bullet, whose
# symbols have the same names as the double-precision Bullet of the Bullet adapter (docs/contributing/engines.md "The
# libraries as Debian ships them"). Optional: without it the build goes on with the other engines and says so.
vssw_engine(NAME siconos DISPLAY "Siconos" ORDER 40 LIBRARY libsiconos_kernel
  CONTACT_SCHEME "Moreau-Jean"
  COLOUR "#CC79A7"  # reddish purple (Okabe-Ito)
  MARKER 13 12      # diamond
  # The step.
  BENCH "dt={dt}: dt 2e-3 1e-3 5e-4 2.5e-4"
  DEBIAN libsiconos-kernel-dev
  HEADERS Siconos siconos TimeStepping TimeDiscretisation SolverOptions SimulationGraphs SimpleMatrix
  HEADERS NonSmoothDynamicalSystem NewtonImpact MoreauJeanOSI LagrangianLinearTIDS FrictionContact NumericsMatrix)

# Its own tests and its known differences, built into vssw_engine_tests whether or not Siconos is found (each test
# skips without it).
vssw_engine_tests(siconos tests/test_siconos.cpp tests/known_differences.cpp)

if(VSSW_WITH_SICONOS)
  find_path(SICONOS_KERNEL_INCLUDE_DIR SiconosKernel.hpp PATH_SUFFIXES siconos/kernel)
  find_path(SICONOS_NUMERICS_INCLUDE_DIR SiconosNumerics.h PATH_SUFFIXES siconos/numerics)
  find_library(SICONOS_KERNEL_LIBRARY siconos_kernel)
  find_library(SICONOS_NUMERICS_LIBRARY siconos_numerics)
  if(SICONOS_KERNEL_INCLUDE_DIR AND SICONOS_NUMERICS_INCLUDE_DIR AND SICONOS_KERNEL_LIBRARY AND SICONOS_NUMERICS_LIBRARY)
    vssw_engine_plugin(siconos siconos/siconos_engine.cpp siconos/siconos_plugin.cpp)
    # Siconos's headers (and the Boost headers they include) as system headers, so that our zero-warning rule holds.
    target_include_directories(vssw_engine_siconos SYSTEM PRIVATE ${SICONOS_KERNEL_INCLUDE_DIR}
                               ${SICONOS_NUMERICS_INCLUDE_DIR} ${SICONOS_KERNEL_INCLUDE_DIR}/..)
    target_link_libraries(vssw_engine_siconos PRIVATE ${SICONOS_KERNEL_LIBRARY} ${SICONOS_NUMERICS_LIBRARY})
  else()
    message(WARNING "Siconos (libsiconos-kernel-dev) not found: the siconos engine is not built "
                    "(bash scripts/setup.sh installs it)")
  endif()
endif()
