# Dictionary reader tests (dem/src/dict.c). include()d from tests/CMakeLists.txt, so
# CMAKE_CURRENT_SOURCE_DIR is tests/; the library target `dem` provides dict.c and error.c.
add_executable(test_dict ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_dict.c)
target_include_directories(test_dict PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/../dem/src)
target_link_libraries(test_dict dem m)
# Accessors on a dictionary written to a temporary directory.
add_test(NAME dict_unit COMMAND test_dict)
# Every file in unit/dict_cases/: exit status 1 and "<file>:<line>: error: key ..." on stderr.
add_test(NAME dict_errors
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/unit/dict_errors.sh $<TARGET_FILE:test_dict>
                 ${CMAKE_CURRENT_SOURCE_DIR}/unit/dict_cases)
