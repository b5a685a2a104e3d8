# The particle field table (dem/src/particles.h): allocation, zeroing, sorting, copying, packing,
# HDF5 snapshot, XDMF index and restart of every field, bit for bit. include()d from
# tests/CMakeLists.txt, so CMAKE_CURRENT_SOURCE_DIR is tests/.
add_executable(test_fields ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_fields.c)
# The test also opens the HDF5 file directly (to see what a snapshot holds).
target_link_libraries(test_fields dem)
if(TARGET PkgConfig::HDF5)
  target_link_libraries(test_fields PkgConfig::HDF5)
endif()
add_test(NAME particle_fields COMMAND test_fields ${CMAKE_CURRENT_BINARY_DIR})
