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
# add_mpi_tests(<name> <target> <rank counts...>): <name>_<n> runs <target> under mpirun -np <n>
# (oversubscribed beyond the cores; mpirun as root, as in CI and on these machines, needs the two
# variables: ../shared/docs/openfoam-mpi-hdf5-on-debian.md)
function(add_mpi_tests name target)
  foreach(np ${ARGN})
    add_test(NAME ${name}_${np}
             COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} --oversubscribe $<TARGET_FILE:${target}>)
    set_tests_properties(${name}_${np} PROPERTIES
                         ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1")
  endforeach()
endfunction()
# The spatial decomposition (dem/src/decompose.h): recursive bisection, serially and on 2 and 4
# ranks (4 oversubscribed on 2 cores), where every rank must get the serial tree bit for bit.
add_executable(test_decompose ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_decompose.c)
target_include_directories(test_decompose PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_decompose dem)
add_test(NAME decompose COMMAND test_decompose)
add_executable(test_decompose_mpi ${CMAKE_CURRENT_SOURCE_DIR}/mpi/test_decompose_mpi.c)
target_include_directories(test_decompose_mpi PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation
                           ${CMAKE_CURRENT_SOURCE_DIR}/unit)
target_link_libraries(test_decompose_mpi dem_mpi)
add_mpi_tests(decompose_mpi test_decompose_mpi 2 4)
# The DEM on 1, 2 and 4 ranks (halo, migration with contact history): the bed of the serial run to
# 1e-12 m after 100 steps, no particle lost or duplicated at any step.
add_executable(test_dem_parallel ${CMAKE_CURRENT_SOURCE_DIR}/mpi/test_dem_parallel.c)
target_include_directories(test_dem_parallel PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_dem_parallel dem_mpi)
add_mpi_tests(dem_parallel test_dem_parallel 1 2 4)
# Multisphere bodies on 1, 2 and 4 ranks (a body with its spheres on the rank of its centre): the
# serial bed's bodies and spheres to 1e-12 m after 100 steps, none lost, doubled or parted.
add_executable(test_bodies_parallel ${CMAKE_CURRENT_SOURCE_DIR}/mpi/test_bodies_parallel.c)
target_include_directories(test_bodies_parallel PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_bodies_parallel dem_mpi)
add_mpi_tests(bodies_parallel test_bodies_parallel 1 2 4)
# The coupling's copies on the fluid's ranks (issue 23): a mesh cut into slabs, one per rank, and
# particles owned by ranks unrelated to where they are; the void fraction (divided: spheres
# straddling the cuts; centre), the gather and the spreading equal the whole mesh's to 1e-12.
add_executable(test_coupling_parallel ${CMAKE_CURRENT_SOURCE_DIR}/mpi/test_coupling_parallel.c)
target_include_directories(test_coupling_parallel PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/validation)
target_link_libraries(test_coupling_parallel coupling dem_mpi)
add_mpi_tests(coupling_parallel test_coupling_parallel 1 2 4)
