# Mesh input, partition and boundary curves, on 1 and 2 ranks (the reader broadcasts).
flowform_unit_test(MeshTest unit/MeshTest.cpp)
flowform_unit_test(MeshTest unit/MeshTest.cpp NP 2)
target_compile_definitions(MeshTest PRIVATE
  FLOWFORM_TEST_DATA="${FLOWFORM_TEST_DATA}"
  FLOWFORM_MESH_DIR="${FLOWFORM_SOURCE_DIR}/meshes")
# Moving a state between meshes (point location, interpolation, wall statuses), 1 and 2 ranks.
flowform_unit_test(TransferTest unit/TransferTest.cpp)
flowform_unit_test(TransferTest unit/TransferTest.cpp NP 2)
# What a .geo may do (mesh/GeoScript): the command filter before gmsh parses a file.
flowform_unit_test(GeoScriptTest unit/GeoScriptTest.cpp)
