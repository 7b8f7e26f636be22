# Box2D 2.4.1 (Debian libbox2d-dev: single precision, 2D). Found by its CMake package (box2d::box2d), else by
# pkg-config (box2d.pc). Optional: without it the build goes on with the other engines and says so.
vssw_engine(NAME box2d DISPLAY "Box2D" ORDER 50 LIBRARY libbox2d
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#882255"  # wine (Paul Tol's colour-blind safe "muted" set: Okabe-Ito's spares stay free)
  MARKER 1 1        # plus (no filled form)
  # Box2D's sequential impulses: the step and the velocity iterations (docs/contributing/engines.md "Box2D").
  BENCH "dt={dt} it={iterations}: dt 1e-3 5e-4 2e-4 1e-4, iterations 4 8 16"
  DEBIAN libbox2d-dev
  HEADERS box2d/ b2_)

# Its own tests and its known differences, built into vssw_engine_tests whether or not Box2D is found (each test
# skips without it).
vssw_engine_tests(box2d tests/test_box2d.cpp tests/known_differences.cpp)

if(VSSW_WITH_BOX2D)
  find_package(box2d CONFIG QUIET)
  if(TARGET box2d::box2d)
    set(VSSW_BOX2D_TARGET box2d::box2d)
  else()
    pkg_check_modules(BOX2D QUIET IMPORTED_TARGET box2d)
    if(BOX2D_FOUND)
      set(VSSW_BOX2D_TARGET PkgConfig::BOX2D)
    endif()
  endif()
  if(VSSW_BOX2D_TARGET)
    vssw_engine_plugin(box2d box2d/box2d_engine.cpp box2d/box2d_plugin.cpp)
    # Box2D's headers as system headers, so that our zero-warning rule holds.
    get_target_property(VSSW_BOX2D_INCLUDES ${VSSW_BOX2D_TARGET} INTERFACE_INCLUDE_DIRECTORIES)
    if(VSSW_BOX2D_INCLUDES)
      target_include_directories(vssw_engine_box2d SYSTEM PRIVATE ${VSSW_BOX2D_INCLUDES})
    endif()
    target_link_libraries(vssw_engine_box2d PRIVATE ${VSSW_BOX2D_TARGET})
  else()
    message(WARNING "Box2D (libbox2d-dev) not found: the box2d engine is not built (bash scripts/setup.sh installs it)")
  endif()
endif()
