# The free-surface update without a flow solve: mesh motion (affine exactness), the spine
# update at a uniform velocity, input errors (docs/theory.md §3).
flowform_unit_test(FreeSurfaceTest unit/FreeSurfaceTest.cpp)
# Anderson acceleration of the free-surface loop on linear maps with a known fixed point.
flowform_unit_test(AndersonAccelerationTest unit/AndersonAccelerationTest.cpp)
