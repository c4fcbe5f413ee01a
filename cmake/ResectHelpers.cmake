# Small helpers shared by every folder's CMakeLists.txt.

# resect_set_warnings(target): the project's warning set, applied per target.
function(resect_set_warnings target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endfunction()

# resect_add_test(NAME name SOURCES ... LIBS ... LABELS ... [ENV ...] [TIMEOUT s])
# One Qt Test binary per unit, registered with CTest under the given labels.
function(resect_add_test)
  cmake_parse_arguments(T "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS;ENV" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  set_target_properties(${T_NAME} PROPERTIES AUTOMOC ON)
  resect_set_warnings(${T_NAME})
  target_link_libraries(${T_NAME} PRIVATE Qt6::Test ${T_LIBS})
  target_compile_definitions(${T_NAME} PRIVATE
    RESECT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    RESECT_BINARY_DIR="${PROJECT_BINARY_DIR}")
  add_test(NAME ${T_NAME} COMMAND ${T_NAME})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    ENVIRONMENT "${T_ENV}")
endfunction()
