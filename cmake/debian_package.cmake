# The Debian package (docs/guide/install.md, "The Debian package"): `cd build && cpack -G DEB` makes
# vssw_<version>_<arch>.deb of what `cmake --install` puts under /usr: the program, its plugins, data and studies, and
# the Python package in Debian's /usr/lib/python3/dist-packages (python/CMakeLists.txt picks that folder for the
# prefix /usr). Included by the top CMakeLists.txt after every install() rule.

set(CPACK_PACKAGE_NAME vssw)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # vssw_<version>_<arch>.deb, Debian's own naming
# Debian packages ship stripped binaries: the symbol tables are most of the plugins' size, and nothing reads them.
set(CPACK_STRIP_FILES ON)

# The maintainer and homepage are the distributor's to state: the repository names no address of its own.
set(VSSW_PACKAGE_MAINTAINER "The vssw developers" CACHE STRING "The Maintainer field of the Debian package")
set(VSSW_PACKAGE_HOMEPAGE "" CACHE STRING "The Homepage field of the Debian package (none when empty)")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${VSSW_PACKAGE_MAINTAINER}")
if(VSSW_PACKAGE_HOMEPAGE)
  set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${VSSW_PACKAGE_HOMEPAGE}")
endif()
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "rocking masonry walls: the analytic model against rigid-body engines")
# The long description, below the summary (CPack starts each of its lines with the space Debian's format wants).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "vssw cross-validates rigid-body engines (Bullet, ODE, Simbody, Siconos, Box2D, DART, MuJoCo) against the
analytic model of the vertical spanning strip wall of Sorrentino, Masiani & Griffith (2008): thresholds, free
rocking, earthquake response, studies and validation reports. The program vssw, its engine plugins, records and
studies, and the Python module (import vssw) for the system's python3.
Licence: Apache-2.0 (/usr/share/doc/vssw/copyright).")

# Depends: the shared libraries of the program, the engines' plugins and the Python module, as dpkg-shlibdeps finds
# their packages (it needs dpkg-dev and file), plus the Python the module was built for and NumPy, which the module
# imports. pandas (study results as a DataFrame) and gnuplot (the plots of reports and studies) are optional.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(VSSW_PYTHON_MODULE)
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")
  set(python "${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= ${python}), python3 (<< ${Python3_VERSION_MAJOR}.${next_minor}), python3-numpy")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-pandas, gnuplot-nox")
else()
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox")
endif()

# Debian's place for the licence: /usr/share/doc/vssw/copyright, in its machine-readable format.
configure_file(${PROJECT_SOURCE_DIR}/cmake/copyright.in ${PROJECT_BINARY_DIR}/generated/copyright @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/generated/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})

include(CPack)
