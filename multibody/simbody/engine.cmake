# Simbody 3.7 (find_package(Simbody) CONFIG; its simbody.pc forces -std=c++11, so not pkg-config). Its headers do not
# compile as C++20 with GCC 12 and must never meet ODE's (dNaN): they stay inside simbody/ (its two .cpp files and
# simbody_wall.hpp, which only they include), compiled as C++17 (docs/contributing/engines.md "The libraries as Debian
# ships them"). One plugin for two routes (simbody_plugin.cpp): simbody, compliant contact, and simbody-rigid.
vssw_engine(NAME simbody DISPLAY "Simbody" ORDER 30 LIBRARY libSimTKsimbody
  CONTACT_SCHEME "compliant"
  COLOUR "#009E73"  # bluish green (Okabe-Ito)
  MARKER 11 10      # inverted triangle
  # The compliant route's error is set by its integrator's accuracy; dt is its reporting interval, which costs too (a
  # realization per report inside Simbody's stepTo) and sets the metrics' sampling.
  BENCH "accuracy={accuracy}: accuracy 1e-4 1e-5 1e-6 1e-7"
  BENCH "dt={dt}: dt 1e-3 4e-3"
  DT_MEANING "reporting interval (its integrator picks its own steps)"
  # Contact ends for `vssw stress`: the Hertz modulus [Pa], default 1e15, three decades either side.
  CONTACT_SOFT stiffness=1e12
  CONTACT_STIFF stiffness=1e18
  DEBIAN libsimbody-dev
  HEADERS Simbody SimTK simbody/)
# The rigid route (SemiExplicitEulerTimeStepper) steps with impulses as Bullet does; compared only when named.
vssw_engine_backend(NAME simbody-rigid PLUGIN simbody DISPLAY "simbody-rigid"
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#56B4E9"  # sky blue (Okabe-Ito)
  MARKER 15 14      # pentagon
  BENCH "dt={dt}: dt 2e-3 1e-3 5e-4 2.5e-4"  # the step
  DEFAULT_COMPARED OFF)

# Its own tests and its known differences, built into vssw_engine_tests whether or not Simbody is found (each test
# skips without it).
vssw_engine_tests(simbody tests/test_simbody.cpp tests/known_differences.cpp)

if(VSSW_WITH_SIMBODY)
  find_package(Simbody REQUIRED CONFIG)
  vssw_engine_plugin(simbody simbody/simbody_engine.cpp simbody/simbody_compliant.cpp simbody/simbody_plugin.cpp)
  set_target_properties(vssw_engine_simbody PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
  # Simbody's headers as system headers, so that our zero-warning rule holds.
  target_include_directories(vssw_engine_simbody SYSTEM PRIVATE ${Simbody_INCLUDE_DIR})
  target_link_libraries(vssw_engine_simbody PRIVATE ${Simbody_LIBRARIES})
endif()
