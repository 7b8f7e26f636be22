# The program's plugins: each engine adapter (multibody/) and the MPI module (study/) is a shared module opened only
# when a run needs it (docs/architecture.md, "Plugins"). Included by the top CMakeLists.txt.

# Where they are built (every program, test and the Python module of this build tree look there:
# multibody/host/plugin_loader.hpp) and installed (<prefix>/lib/vssw/plugins, found from <prefix>/bin).
set(VSSW_PLUGIN_OUTPUT_DIR ${PROJECT_BINARY_DIR}/plugins)
set(VSSW_PLUGIN_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/vssw/plugins)
# The installed plugins' folder relative to the installed program's, "../lib/vssw/plugins": relative, so that it holds
# for any prefix given at install time (cmake --install build --prefix P) and in a staged (DESTDIR) tree.
file(RELATIVE_PATH VSSW_PLUGIN_DIR_FROM_BINDIR /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${VSSW_PLUGIN_INSTALL_DIR})

# This build's identity, compiled into the program and into every plugin (build/generated/vssw_build_id.hpp): a
# plugin whose identity differs is refused (multibody/host/plugin_loader.hpp), since the C++ types it exchanges with the
# program (Engine, WallScene, std::string, ...) are only known to agree within one build. The token is drawn once per
# build tree and kept in the cache, so that a reconfigure does not rebuild the plugins; the rest says in words what
# differs when one is refused.
if(NOT VSSW_BUILD_TOKEN)
  string(RANDOM LENGTH 12 ALPHABET 0123456789abcdef token)
  set(VSSW_BUILD_TOKEN ${token} CACHE INTERNAL "This build tree's part of VSSW_BUILD_ID")
endif()
set(VSSW_BUILD_ID "vssw ${PROJECT_VERSION}, ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}, ${CMAKE_BUILD_TYPE}")
if(VSSW_SANITIZE)
  string(APPEND VSSW_BUILD_ID " with ASan and UBSan")
endif()
string(APPEND VSSW_BUILD_ID ", build ${VSSW_BUILD_TOKEN}")
# Rewritten only when its text changes (configure_file), so that a reconfigure rebuilds nothing.
configure_file(${PROJECT_SOURCE_DIR}/cmake/vssw_build_id.hpp.in ${PROJECT_BINARY_DIR}/generated/vssw_build_id.hpp @ONLY)

# vssw_add_plugin(TARGET SOURCES...): a plugin module, built as build/plugins/TARGET.so and installed beside the
# others. Its symbols are hidden but for its entry point (engine_plugin.hpp, study/mpi_module.hpp): nothing of our
# static libraries or of an engine library it links statically can bind to, or be bound by, another binary, and
# dlopen has fewer symbols to relocate.
function(vssw_add_plugin target)
  add_library(${target} MODULE ${ARGN})
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY ${VSSW_PLUGIN_OUTPUT_DIR}
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/generated)
  target_compile_options(${target} PRIVATE ${VSSW_WARNINGS})
  # --exclude-libs: the static libraries' symbols (vssw_engine_kit, vssw_analytic) hidden as well. --no-undefined: a
  # symbol the plugin needs and no library it links provides fails the link, not a user's run at dlopen. Not with the
  # sanitizers: clang leaves their runtime in the program, whose symbols the plugin finds at dlopen.
  # --build-id: the note that names the linked file (multibody/host/plugin_versions.hpp: the record of its engines'
  # versions is tied to it; most toolchains write it by default, this makes it sure).
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL -Wl,--build-id)
  if(NOT VSSW_SANITIZE)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${VSSW_PLUGIN_INSTALL_DIR})
endfunction()
