# ODE 0.16.2 (Debian's build is double precision; pkg-config ode). Its headers define a macro dNaN that breaks
# Simbody's: they stay inside ode/ode_engine.cpp (docs/contributing/engines.md "The libraries as Debian ships them").
vssw_engine(NAME ode DISPLAY "ODE" ORDER 20 LIBRARY libode.so
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#D55E00"  # vermillion (Okabe-Ito)
  MARKER 9 8        # triangle
  # The direct solver (the default) has no iterations; quickstep's SOR trades them for cost.
  BENCH "dt={dt} direct: dt 1e-3 5e-4 2e-4 1e-4"
  BENCH "dt={dt} quickstep it={iterations}: iterations 10 20 40, quickstep 1"
  # Contact ends for `vssw stress`: erp's upper end (full correction per step) and cfm 0 (hard constraints) when
  # stiff; the default erp and cfm 1e-5 (a spring 1e5 times softer than the default) when soft.
  CONTACT_SOFT erp=0.2 cfm=1e-5
  CONTACT_STIFF erp=1 cfm=0
  DEBIAN libode-dev
  HEADERS ode/)

# Its known differences (it has no tests of its own), built into vssw_engine_tests whether or not ODE is found.
vssw_engine_tests(ode tests/known_differences.cpp)

if(VSSW_WITH_ODE)
  pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
  vssw_engine_plugin(ode ode/ode_engine.cpp ode/ode_plugin.cpp)
  # ODE's headers as system headers, so that our zero-warning rule holds.
  target_include_directories(vssw_engine_ode SYSTEM PRIVATE ${ODE_INCLUDE_DIRS})
  target_compile_definitions(vssw_engine_ode PRIVATE ${ODE_CFLAGS_OTHER})
  target_link_libraries(vssw_engine_ode PRIVATE PkgConfig::ODE)
endif()
