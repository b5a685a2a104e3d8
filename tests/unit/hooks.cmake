# The error and log hooks (dem/src/error.h). include()d from tests/CMakeLists.txt, so
# CMAKE_CURRENT_SOURCE_DIR is tests/.
# A logger and a fatal handler set by the program get the libraries' lines and errors.
add_executable(test_hooks ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_hooks.c)
target_include_directories(test_hooks PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_hooks coupling)
add_test(NAME error_hooks COMMAND test_hooks)
# Nothing in dem/src or coupling/src prints or exits except through those hooks (error.c).
add_test(NAME no_direct_output
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/unit/no_direct_output.sh ${CMAKE_SOURCE_DIR})
# The reduction hook (dem/src/reduce.h): the DEM's global decisions take the other ranks' values.
add_executable(test_reduce ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_reduce.c)
target_include_directories(test_reduce PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_reduce dem)
add_test(NAME reduce_hook COMMAND test_reduce)
