# Read by ctest after the tests are added: the longest (longest_tests.txt) start
# first (COST), so that a cold run does not end on one of them running alone.
file(STRINGS "${CMAKE_CURRENT_LIST_DIR}/longest_tests.txt" entries REGEX "^[0-9]+ ")
foreach(entry IN LISTS entries)
  string(REGEX MATCH "^[0-9]+" cost "${entry}")
  string(REGEX REPLACE "^[0-9]+ " "" name "${entry}")
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
