# Particle output and restart (dem/src/io_hdf5.c): HDF5 round trip, killed runs, append, XDMF.
add_executable(test_io ${CMAKE_CURRENT_SOURCE_DIR}/unit/test_io.c)
# The test also opens the HDF5 file directly (to fake a half-written snapshot).
target_link_libraries(test_io dem)
if(TARGET PkgConfig::HDF5)
  target_link_libraries(test_io PkgConfig::HDF5)
endif()
add_test(NAME io_roundtrip COMMAND test_io ${CMAKE_CURRENT_BINARY_DIR})
