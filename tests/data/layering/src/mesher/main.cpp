#include "flowform/mesh/Mesh.hpp"          // the mesher may include mesh
#include "flowform/solvers/LinearSolver.hpp"  // but not the library's solvers: a violation
