#pragma once
#include "flowform/core/Fine.hpp"          // earlier stage: allowed
#include "flowform/solvers/NonlinearSolver.hpp"  // later stage: a violation
