# Small helpers so that every core module and every test is declared the same way.

set(AUV_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)

# auv_module(NAME SOURCES a.cpp b.cpp DEPS other_module ...)
# One static library per core folder, named auv_<NAME>, includes rooted at core/.
function(auv_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(auv_${name} STATIC ${M_SOURCES})
  target_include_directories(auv_${name} PUBLIC ${PROJECT_SOURCE_DIR}/core)
  target_compile_options(auv_${name} PRIVATE ${AUV_WARNINGS})
  target_link_libraries(auv_${name} PUBLIC ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
  set_target_properties(auv_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# auv_test(NAME SOURCES x_test.cpp LIBS auv_seawater ...)
# A GoogleTest executable registered with CTest, one CTest entry per TEST.
function(auv_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  target_compile_options(${name} PRIVATE ${AUV_WARNINGS})
  target_compile_definitions(${name} PRIVATE
    AUV_RESOURCE_DIR="${AUV_RESOURCE_DIR}"
    AUV_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared"
    AUV_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data")
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
