# DART 6.12 (Debian libdart-dev with libdart-collision-ode-dev). Found by its CMake package, which gives cxx_std_17 and
# /usr/include; not by dart.pc, which forces -std=c++11, puts /usr/include/dart on the include path and lacks libraries.
# DART's Bullet detector is never linked: it is Debian's single-precision Bullet, which aborted beside the Bullet
# adapter's double precision in one process. Its headers stay inside dart/ (dart_engine.cpp takes about a minute to
# compile), as system headers, compiled as C++17 (docs/contributing/engines.md "DART"). Optional: without it the build
# goes on and says so. Its packages: DART, its ODE collision detector, its URDF loader (a run loads its blocks from
# the URDF `vssw scene` writes, dart/dart_urdf.hpp; with urdfdom about 1 MB more), and ikfast, which dart/dart.hpp
# needs though libdart-dev does not depend on it. Heavy: libdart-dev pulls libboost-all-dev, about 108 packages and
# 224 MB installed.
vssw_engine(NAME dart DISPLAY "DART" ORDER 60 LIBRARY libdart.so
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#E69F00"  # orange (Okabe-Ito)
  MARKER 3 3        # star (no filled form)
  # The step with the ODE detector (the default), and DART's own detector at the default step.
  BENCH "dt={dt}: dt 1e-3 5e-4 2e-4 1e-4"
  BENCH "dt={dt} detector=dart: detector 0"
  DEBIAN libdart-dev libdart-collision-ode-dev libdart-external-ikfast-dev libdart-utils-urdf-dev
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
  find_package(DART 6.12 QUIET CONFIG COMPONENTS collision-ode utils-urdf)
  set(DART_FOUND ${DART_FOUND} PARENT_SCOPE)
endfunction()
if(VSSW_WITH_DART)
  vssw_find_dart()
  if(DART_FOUND)
    vssw_engine_plugin(dart dart/dart_engine.cpp dart/dart_urdf.cpp dart/dart_plugin.cpp)
    set_target_properties(vssw_engine_dart PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
    target_include_directories(vssw_engine_dart SYSTEM PRIVATE ${DART_INCLUDE_DIRS})
    target_link_libraries(vssw_engine_dart PRIVATE dart dart-collision-ode dart-utils-urdf)
    # The scene file (vssw scene) loaded back by DART's own URDF loader: a test program of its own, the one that links
    # DART beside the program's libraries (vssw_engine_tests links no engine library). Defined once the top
    # CMakeLists.txt has found GoogleTest (after this folder), where DART is looked for again: its targets are this
    # folder's.
    if(VSSW_BUILD_TESTS)
      cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL vssw_dart_scene_tests)
    endif()
  else()
    message(WARNING "DART (libdart-dev, libdart-collision-ode-dev) not found: the dart engine is not built "
                    "(bash scripts/setup.sh installs it)")
  endif()
endif()

function(vssw_dart_scene_tests)
  include(GoogleTest)
  vssw_find_dart()
  add_executable(vssw_dart_scene_tests ${PROJECT_SOURCE_DIR}/multibody/dart/tests/test_dart_scene.cpp)
  # DART's headers as the plugin takes them: C++17, system headers (zero warnings of ours).
  set_target_properties(vssw_dart_scene_tests PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
  target_compile_options(vssw_dart_scene_tests PRIVATE ${VSSW_WARNINGS})
  target_include_directories(vssw_dart_scene_tests SYSTEM PRIVATE ${DART_INCLUDE_DIRS})
  target_link_libraries(vssw_dart_scene_tests PRIVATE vssw_compare dart dart-utils-urdf GTest::gtest_main)
  gtest_discover_tests(vssw_dart_scene_tests DISCOVERY_TIMEOUT 60)
endfunction()
