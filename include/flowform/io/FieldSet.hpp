// Fields gathered for output: plain arrays on the writing rank, indexed by node or cell id
// of the (replicated) mesh, components interleaved (value[id * components + c]).
#pragma once

#include <string>
#include <vector>

namespace flowform {

struct Field {
  std::string name;    ///< as ParaView shows it, e.g. "velocity", "pressure"
  int components = 1;  ///< 1 (scalar) or 2 (2-D vector, written as 3-D with z = 0)
  std::vector<double> values;
  /// A 2-component nodal field with these names set is written to the boundary CSVs as its
  /// tangential and normal components (like u_t, u_n) under these names, not as x and y.
  std::string tangentialName{}, normalName{};
};

struct FieldSet {
  std::vector<Field> nodal;  ///< one value set per mesh node
  std::vector<Field> cell;   ///< one value set per mesh cell
};

}  // namespace flowform
