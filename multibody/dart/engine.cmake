# DART 6.12 (Debian libdart-dev with libdart-collision-ode-dev). Found by its CMake package, which gives cxx_std_17 and
# /usr/include; not by dart.pc, which forces -std=c++11, puts /usr/include/dart on the include path and lacks libraries.
# DART's Bullet detector is never linked: it is Debian's single-precision Bullet, which aborted beside the Bullet
# adapter's double precision in one process. Its headers stay inside dart/dart_engine.cpp (about a minute to compile),
# as system headers, compiled as C++17 (docs/contributing/engines.md "DART"). Optional: without it the build goes on and
# says so. Its packages: DART, its ODE collision detector, and ikfast, which dart/dart.hpp needs though libdart-dev does
# not depend on it. Heavy: libdart-dev pulls libboost-all-dev, about 108 packages and 224 MB installed.
vssw_engine(NAME dart DISPLAY "DART" ORDER 60 LIBRARY libdart.so
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#E69F00"  # orange (Okabe-Ito)
  MARKER 3 3        # star (no filled form)
  # The step with the ODE detector (the default), and DART's own detector at the default step.
  BENCH "dt={dt}: dt 1e-3 5e-4 2e-4 1e-4"
  BENCH "dt={dt} detector=dart: detector 0"
  DEBIAN libdart-dev libdart-collision-ode-dev libdart-external-ikfast-dev
  HEADERS dart/)

# Its own tests and its known differences, built into vssw_engine_tests whether or not DART is found (each test
# skips without it).
vssw_engine_tests(dart tests/test_dart.cpp tests/known_differences.cpp)

# DART's CMake package finds ODE again for its ODE detector (DARTFindODE.cmake, FindODE.cmake) and takes the ODE
# adapter's pkg_check_modules(ODE) results when they exist (multibody/ode/engine.cmake is included first, by ORDER):
# their ODE_INCLUDE_DIRS is empty for /usr/include, which its find_package_handle_standard_args counts as not found.
# Looked for in a function, which gives it the directory.
function(vssw_find_dart)
  if(ODE_FOUND AND NOT ODE_INCLUDE_DIRS)
    set(ODE_INCLUDE_DIRS ${ODE_INCLUDEDIR})
  endif()
  find_package(DART 6.12 QUIET CONFIG COMPONENTS collision-ode)
  set(DART_FOUND ${DART_FOUND} PARENT_SCOPE)
endfunction()
if(VSSW_WITH_DART)
  vssw_find_dart()
  if(DART_FOUND)
    vssw_engine_plugin(dart dart/dart_engine.cpp dart/dart_plugin.cpp)
    set_target_properties(vssw_engine_dart PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
    target_include_directories(vssw_engine_dart SYSTEM PRIVATE ${DART_INCLUDE_DIRS})
    target_link_libraries(vssw_engine_dart PRIVATE dart dart-collision-ode)
  else()
    message(WARNING "DART (libdart-dev, libdart-collision-ode-dev) not found: the dart engine is not built "
                    "(bash scripts/setup.sh installs it)")
  endif()
endif()
