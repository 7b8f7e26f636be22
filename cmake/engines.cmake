# Each engine's facts, declared once in its folder's multibody/<engine>/engine.cmake and written into one generated
# header, build/generated/vssw_engine_facts.hpp, that the registry, the contact schemes and the palette read
# (docs/architecture.md "Adding an engine"). Included by multibody/CMakeLists.txt.
#
# An engine.cmake opens with one call, then finds its library and builds its plugin when VSSW_WITH_<ENGINE> is on:
#
#   vssw_engine(NAME box2d DISPLAY "Box2D" ORDER 50 LIBRARY libbox2d
#     CONTACT_SCHEME "impulse stepping" COLOUR "#882255" MARKER 1 1
#     DEBIAN libbox2d-dev
#     HEADERS box2d/ b2_)
#
# NAME: the backend's name on the command line, its folder and its plugin (vssw_engine_<NAME>.so). DISPLAY: the name
# a report prints, the adapter's display_name(). ORDER: its place in every listing of engines (smallest first).
# LIBRARY: the start of its library's shared object's name, which a run of another engine must not map (a test).
# CONTACT_SCHEME: a key of multibody/host/contact_schemes.cpp's table. COLOUR and MARKER (gnuplot's filled and open point
# types): its plots' style (io/palette.hpp). DEFAULT_COMPARED OFF: left out of the engines a comparison runs when none
# is named. BENCH "LABEL: AXIS V V ..., AXIS V ...", which may repeat: its work-precision sweep, every combination of
# the axes' values ("dt", "iterations" or a knob) on its defaults (validation/bench_spec.hpp). DT_MEANING: what its dt
# is, in words for the report's findings ("step" unless said: Simbody's compliant route's is a reporting interval).
# CONTACT_SOFT and CONTACT_STIFF, knob=number words: its contact knobs at the soft and the stiff end of their range,
# which `vssw stress` runs (stress/cases.cpp; none: the engine has no contact stiffness knob). DEBIAN: the packages
# scripts/setup.sh installs for it, and HEADERS: the starts of its library's header names, which only its folder may
# include (tests/layering.py) -- both read from the engine.cmake files as lines of their own, "  DEBIAN pkg..." and
# "  HEADERS prefix..." (words up to a comment or the call's ")"), which may repeat. A plugin holding a second backend names it with vssw_engine_backend() (multibody/simbody/engine.cmake).

# The backends' facts, one line each in listing order, for the generated header.
set_property(GLOBAL PROPERTY VSSW_ENGINE_KEYS "")

# vssw_engine_backend(NAME name PLUGIN plugin DISPLAY ... CONTACT_SCHEME ... COLOUR ... MARKER filled open
#                     [DEFAULT_COMPARED OFF] [BENCH ...] [DT_MEANING ...] [CONTACT_SOFT k=v...]
#                     [CONTACT_STIFF k=v...]): one backend's facts, listed after its plugin's earlier
# ones. A backend built into the program (the analytic model) has no PLUGIN and an ORDER of its own.
function(vssw_engine_backend)
  cmake_parse_arguments(PARSE_ARGV 0 B "" "NAME;PLUGIN;ORDER;DISPLAY;CONTACT_SCHEME;COLOUR;DEFAULT_COMPARED;DT_MEANING"
                        "MARKER;BENCH;CONTACT_SOFT;CONTACT_STIFF")
  set(order ${B_ORDER})
  if(B_PLUGIN)
    get_property(order GLOBAL PROPERTY VSSW_ENGINE_ORDER_${B_PLUGIN})
  endif()
  foreach(fact NAME DISPLAY CONTACT_SCHEME COLOUR MARKER)
    if(NOT DEFINED B_${fact})
      message(FATAL_ERROR "vssw_engine_backend(${B_NAME}): ${fact} is missing")
    endif()
  endforeach()
  list(LENGTH B_MARKER markers)
  if(NOT markers EQUAL 2 OR NOT B_COLOUR MATCHES "^#[0-9A-Fa-f]+$")
    message(FATAL_ERROR "vssw_engine_backend(${B_NAME}): MARKER takes two point types, COLOUR one #RRGGBB")
  endif()
  if(NOT DEFINED B_DEFAULT_COMPARED)
    set(B_DEFAULT_COMPARED ON)
  endif()
  # The sort key: the engine's ORDER, then the backends of one plugin in the order they are declared.
  get_property(count GLOBAL PROPERTY VSSW_ENGINE_BACKENDS_${B_PLUGIN})
  list(LENGTH count index)
  set_property(GLOBAL APPEND PROPERTY VSSW_ENGINE_BACKENDS_${B_PLUGIN} ${B_NAME})
  math(EXPR key "${order} * 10 + ${index} + 100000" OUTPUT_FORMAT DECIMAL)  # fixed width: sorts as text
  list(GET B_MARKER 0 filled)
  list(GET B_MARKER 1 open)
  set_property(GLOBAL APPEND PROPERTY VSSW_ENGINE_KEYS ${key})
  list(JOIN B_BENCH "|" bench)
  set_property(GLOBAL PROPERTY VSSW_ENGINE_BENCH_${key} "${bench}")
  if(NOT DEFINED B_DT_MEANING)
    set(B_DT_MEANING "step")
  endif()
  set_property(GLOBAL PROPERTY VSSW_ENGINE_DT_MEANING_${key} "${B_DT_MEANING}")
  foreach(end SOFT STIFF)
    foreach(setting ${B_CONTACT_${end}})
      if(NOT setting MATCHES "^[a-z_]+=[-+0-9.eE]+$")
        message(FATAL_ERROR "vssw_engine_backend(${B_NAME}): CONTACT_${end} takes knob=number words, got '${setting}'")
      endif()
    endforeach()
    list(JOIN B_CONTACT_${end} " " contact)
    set_property(GLOBAL PROPERTY VSSW_ENGINE_CONTACT_${end}_${key} "${contact}")
  endforeach()
  set_property(GLOBAL PROPERTY VSSW_ENGINE_ROW_${key}
               "${B_NAME}|${B_DISPLAY}|${B_PLUGIN}|${B_CONTACT_SCHEME}|${B_COLOUR}|${filled}|${open}|${B_DEFAULT_COMPARED}")
endfunction()

# vssw_engine(NAME ... DISPLAY ... ORDER n LIBRARY ... CONTACT_SCHEME ... COLOUR ... MARKER f o
#             [DEFAULT_COMPARED OFF] DEBIAN pkg... HEADERS prefix...): an engine folder's plugin and its first backend, and the option
# VSSW_WITH_<NAME> that builds it.
function(vssw_engine)
  cmake_parse_arguments(PARSE_ARGV 0 E "" "NAME;ORDER;DISPLAY;LIBRARY" "DEBIAN;HEADERS")
  if(NOT E_ORDER MATCHES "^[0-9]+$" OR E_ORDER GREATER 9999)
    message(FATAL_ERROR "vssw_engine(${E_NAME}): ORDER takes a whole number below 10000")
  endif()
  set_property(GLOBAL PROPERTY VSSW_ENGINE_ORDER_${E_NAME} ${E_ORDER})
  set_property(GLOBAL PROPERTY VSSW_ENGINE_LIBRARY_${E_NAME} "${E_LIBRARY}")
  string(TOUPPER ${E_NAME} upper)
  list(JOIN E_DEBIAN ", " packages)
  option(VSSW_WITH_${upper} "Build the ${E_DISPLAY} adapter (Debian ${packages})" ON)
  vssw_engine_backend(NAME ${E_NAME} PLUGIN ${E_NAME} DISPLAY ${E_DISPLAY} ${E_UNPARSED_ARGUMENTS})
endfunction()

# vssw_engine_tests(NAME SOURCES...): an engine folder's own tests and its known differences (paths from its folder:
# tests/test_<name>.cpp, tests/known_differences.cpp), built into vssw_engine_tests by tests/CMakeLists.txt beside the
# tests every engine runs.
function(vssw_engine_tests name)
  list(TRANSFORM ARGN PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/${name}/)
  set_property(GLOBAL APPEND PROPERTY VSSW_ENGINE_TEST_SOURCES ${ARGN})
endfunction()

# The engine.cmake files in their ORDER (read from their "  ORDER n" line before any is included), so that each
# library is looked for in the order it always was: DART's package looks again for ODE and takes the ODE adapter's
# results when they exist (multibody/dart/engine.cmake).
function(vssw_engine_files out)
  file(GLOB files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*/engine.cmake)
  set(keyed "")
  foreach(file ${files})
    file(STRINGS ${file} line REGEX "^ *vssw_engine\\(.* ORDER [0-9]+" LIMIT_COUNT 1)
    string(REGEX MATCH "ORDER ([0-9]+)" ignored "${line}")
    if(NOT CMAKE_MATCH_1)
      message(FATAL_ERROR "${file}: its vssw_engine( line must hold its ORDER n")
    endif()
    math(EXPR key "${CMAKE_MATCH_1} + 10000" OUTPUT_FORMAT DECIMAL)
    list(APPEND keyed "${key}|${file}")
  endforeach()
  list(SORT keyed)
  list(TRANSFORM keyed REPLACE "^[0-9]+\\|" "")
  set(${out} ${keyed} PARENT_SCOPE)
endfunction()

# The generated header: one C++ row per backend, in listing order, and whether this build has its plugin (the
# plugins vssw_engine_plugin built). Rewritten only when its text changes (configure_file).
function(vssw_write_engine_facts)
  get_property(keys GLOBAL PROPERTY VSSW_ENGINE_KEYS)
  get_property(built GLOBAL PROPERTY VSSW_BUILT_PLUGINS)
  list(SORT keys)
  set(rows "")
  foreach(key ${keys})
    get_property(row GLOBAL PROPERTY VSSW_ENGINE_ROW_${key})
    string(REPLACE "|" ";" row "${row}")
    list(GET row 0 name)
    list(GET row 1 display)
    list(GET row 2 plugin)
    list(GET row 3 scheme)
    list(GET row 4 colour)
    list(GET row 5 filled)
    list(GET row 6 open)
    list(GET row 7 compared)
    get_property(bench GLOBAL PROPERTY VSSW_ENGINE_BENCH_${key})
    get_property(dt_meaning GLOBAL PROPERTY VSSW_ENGINE_DT_MEANING_${key})
    get_property(soft GLOBAL PROPERTY VSSW_ENGINE_CONTACT_SOFT_${key})
    get_property(stiff GLOBAL PROPERTY VSSW_ENGINE_CONTACT_STIFF_${key})
    get_property(library GLOBAL PROPERTY VSSW_ENGINE_LIBRARY_${plugin})
    set(has false)
    if(plugin STREQUAL "" OR plugin IN_LIST built)
      set(has true)
    endif()
    set(plugin_text "\"${plugin}\"")
    if(plugin STREQUAL "")
      set(plugin_text nullptr)
    endif()
    set(compared_text false)
    if(compared)
      set(compared_text true)
    endif()
    string(APPEND rows "    {\"${name}\", \"${display}\", ${plugin_text}, ${has}, \"${scheme}\", \"${colour}\", "
                       "${filled}, ${open}, ${compared_text}, \"${bench}\", \"${library}\", \"${dt_meaning}\", "
                       "\"${soft}\", \"${stiff}\"},\n")
  endforeach()
  set(VSSW_ENGINE_FACT_ROWS "${rows}")
  configure_file(${PROJECT_SOURCE_DIR}/cmake/vssw_engine_facts.hpp.in
                 ${PROJECT_BINARY_DIR}/generated/vssw_engine_facts.hpp @ONLY)
endfunction()
