# The response registry: every type documented and validated, bad types and groups refused with
# the allowed names; the upstream end of a wall.
flowform_unit_test(ResponsesTest unit/ResponsesTest.cpp)
