# Read by ctest when it starts (a TEST_INCLUDE_FILES script): asks the
# QtTest program for its test functions and adds one ctest test for each, so
# a new function runs without being listed anywhere. Set by the caller:
# VIEWER_TEST_PROGRAM, VIEWER_TEST_CMAKE (cmake, for `cmake -E env`).
execute_process(
  COMMAND "${VIEWER_TEST_CMAKE}" -E env QT_QPA_PLATFORM=offscreen "${VIEWER_TEST_PROGRAM}" -functions
  OUTPUT_VARIABLE listing
  ERROR_VARIABLE errors
  RESULT_VARIABLE status)
string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*\\(\\)" functions "${listing}")
if(NOT status EQUAL 0 OR NOT functions)
  # Never silently fewer tests: a failed listing is a failing test.
  add_test(viewer.listFunctions "${VIEWER_TEST_CMAKE}" -E echo_append "")
  set_tests_properties(viewer.listFunctions PROPERTIES WILL_FAIL ON LABELS "viewer")
  message(WARNING "could not list the viewer's test functions (${status}): ${errors}")
  return()
endif()
foreach(function IN LISTS functions)
  string(REPLACE "()" "" name "${function}")
  add_test(viewer.${name} "${VIEWER_TEST_PROGRAM}" ${name})
  set_tests_properties(viewer.${name} PROPERTIES
    LABELS "viewer;rendering" TIMEOUT 120 ENVIRONMENT "QT_QPA_PLATFORM=xcb")
endforeach()
