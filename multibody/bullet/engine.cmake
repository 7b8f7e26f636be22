# Bullet in double precision: the pkg-config module bullet-float64 carries -DBT_USE_DOUBLE_PRECISION and the *-float64
# libraries (find_package(Bullet) names a library Debian does not ship and drops the define;
# docs/contributing/engines.md "The libraries as Debian ships them").
vssw_engine(NAME bullet DISPLAY "Bullet" ORDER 10 LIBRARY libBulletDynamics
  CONTACT_SCHEME "impulse stepping"
  COLOUR "#0072B2"  # blue (Okabe-Ito)
  MARKER 5 4        # square
  # The step and the solver iterations.
  BENCH "dt={dt} it={iterations}: dt 1e-3 5e-4 2e-4 1e-4, iterations 10 20 40"
  # Contact ends for `vssw stress`: Bullet's contacts are rigid; erp (split impulse's position pass) is its knob.
  CONTACT_SOFT erp=0
  CONTACT_STIFF erp=1
  DEBIAN libbullet-dev
  HEADERS btBullet Bullet LinearMath BulletCollision BulletDynamics)

# Its own tests and its known differences, built into vssw_engine_tests whether or not Bullet is found (each test
# skips without it).
vssw_engine_tests(bullet tests/test_bullet.cpp tests/known_differences.cpp)

if(VSSW_WITH_BULLET)
  pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)
  vssw_engine_plugin(bullet bullet/bullet_engine.cpp bullet/bullet_plugin.cpp)
  # Bullet's own headers are not warning-clean: include them as system headers so our zero-warning rule holds.
  target_include_directories(vssw_engine_bullet SYSTEM PRIVATE ${BULLET_INCLUDE_DIRS})
  target_compile_definitions(vssw_engine_bullet PRIVATE ${BULLET_CFLAGS_OTHER})
  target_link_libraries(vssw_engine_bullet PRIVATE PkgConfig::BULLET)
endif()
