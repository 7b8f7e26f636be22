# MuJoCo 2.2.2 (Debian libmujoco-dev). Found by its header and library, not by its CMake package: Debian's
# mujoco-config.cmake lists /usr/include/libqhull_r among mujoco::mujoco's include directories, which only
# libqhull-dev installs (libmujoco-dev does not depend on it), and find_package stops with "includes non-existent
# path" without it (docs/contributing/engines.md "The libraries as Debian ships them"): setup.sh installs both.
# Optional: without it the build goes on.
vssw_engine(NAME mujoco DISPLAY "MuJoCo" ORDER 70 LIBRARY libmujoco
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#332288"  # indigo (Paul Tol's colour-blind safe "muted" set; Okabe-Ito has no hue left)
  MARKER 2 2        # cross (no filled form)
  # The step with semi-implicit Euler (the default; the contacts' time constant follows it, solref_steps), and RK4
  # at the default step (docs/contributing/engines.md "MuJoCo": the parapet's period to -0.002 %).
  BENCH "dt={dt}: dt 1e-3 5e-4 2e-4 1e-4"
  BENCH "dt={dt} integrator=rk4: integrator 1"
  DEBIAN libmujoco-dev libqhull-dev
  HEADERS mujoco/)

# Its own tests and its known differences, built into vssw_engine_tests whether or not MuJoCo is found (each test
# skips without it).
vssw_engine_tests(mujoco tests/test_mujoco.cpp tests/known_differences.cpp)

if(VSSW_WITH_MUJOCO)
  find_path(MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
  find_library(MUJOCO_LIBRARY mujoco)
  if(MUJOCO_INCLUDE_DIR AND MUJOCO_LIBRARY)
    vssw_engine_plugin(mujoco mujoco/mujoco_engine.cpp mujoco/mujoco_plugin.cpp)
    # MuJoCo's headers as system headers, so that our zero-warning rule holds.
    target_include_directories(vssw_engine_mujoco SYSTEM PRIVATE ${MUJOCO_INCLUDE_DIR})
    target_link_libraries(vssw_engine_mujoco PRIVATE ${MUJOCO_LIBRARY})
    # The scene file (vssw scene) loaded back by MuJoCo's own parser: a test program of its own, the one that links
    # MuJoCo beside the program's libraries (vssw_engine_tests links no engine library). Defined once the top
    # CMakeLists.txt has found GoogleTest (after this folder).
    if(VSSW_BUILD_TESTS)
      cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL vssw_mujoco_scene_tests)
    endif()
  else()
    message(WARNING "MuJoCo (libmujoco-dev) not found: the mujoco engine is not built "
                    "(bash scripts/setup.sh installs it)")
  endif()
endif()

function(vssw_mujoco_scene_tests)
  include(GoogleTest)
  add_executable(vssw_mujoco_scene_tests ${PROJECT_SOURCE_DIR}/multibody/mujoco/tests/test_mujoco_scene.cpp)
  target_compile_options(vssw_mujoco_scene_tests PRIVATE ${VSSW_WARNINGS})
  target_include_directories(vssw_mujoco_scene_tests SYSTEM PRIVATE ${MUJOCO_INCLUDE_DIR})
  target_link_libraries(vssw_mujoco_scene_tests PRIVATE vssw_compare ${MUJOCO_LIBRARY} GTest::gtest_main)
  gtest_discover_tests(vssw_mujoco_scene_tests DISCOVERY_TIMEOUT 60)
endfunction()
