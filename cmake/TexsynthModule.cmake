# One static library per module (src/<name>/*.cpp, include/texsynth/<name>/*.h) and one
# GoogleTest executable per module (tests/<name>/*.cpp), so each builds and tests alone.

add_library(texsynth_warnings INTERFACE)
target_compile_options(texsynth_warnings INTERFACE -Wall -Wextra)
# No code reads errno after a math call, and without the errno path a square root is one
# instruction that loops can vectorize: the solver's distances take one per pixel. The same bits;
# bench/synthesis_comparison.sh at 512^2, 12 GIMP exemplars, one machine: optimize 0.685 ->
# 0.648 s (1.49x -> 1.56x G'MIC's speed).
target_compile_options(texsynth_warnings INTERFACE -fno-math-errno)
if(TEXSYNTH_WERROR)
  target_compile_options(texsynth_warnings INTERFACE -Werror)
endif()
if(TEXSYNTH_NATIVE)
  target_compile_options(texsynth_warnings INTERFACE -march=native)
endif()
if(TEXSYNTH_SANITIZE)
  target_compile_options(texsynth_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(texsynth_warnings INTERFACE -fsanitize=address,undefined)
endif()

function(texsynth_module name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp)
  if(NOT sources)
    message(STATUS "texsynth: module '${name}' has no sources yet; skipped")
    return()
  endif()
  add_library(texsynth_${name} STATIC ${sources})
  target_include_directories(texsynth_${name} PUBLIC ${CMAKE_SOURCE_DIR}/include)
  target_link_libraries(texsynth_${name} PUBLIC ${ARG_DEPS} PRIVATE texsynth_warnings)
  # Only the file that reads it sees the (clone-specific) path, so every other file compiles the
  # same in any checkout and a compiler cache can share it.
  if(name STREQUAL "core")
    set_source_files_properties(${CMAKE_SOURCE_DIR}/src/core/data_paths.cpp PROPERTIES COMPILE_DEFINITIONS
                                TEXSYNTH_DATA_DIR="${TEXSYNTH_DATA_DIR}")
  endif()
endfunction()

function(texsynth_tests name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/${name}/*.cpp)
  if(NOT sources OR NOT TARGET texsynth_${name})
    return()
  endif()
  add_executable(test_${name} ${sources})
  target_link_libraries(test_${name} PRIVATE texsynth_${name} ${ARG_DEPS} texsynth_test_support GTest::gtest_main texsynth_warnings)
  set_target_properties(test_${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  gtest_discover_tests(test_${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${name})
endfunction()
