// The design's vectors as ROL sees them: ROL::StdVector over std::vector<double> (the design is a
// handful of numbers on one rank). The optimizer's classes read and write their entries here.
#pragma once

#include <vector>

#include <ROL_StdVector.hpp>

namespace flowform {

inline const std::vector<double>& entries(const ROL::Vector<double>& v) {
  return *dynamic_cast<const ROL::StdVector<double>&>(v).getVector();
}
inline std::vector<double>& entries(ROL::Vector<double>& v) {
  return *dynamic_cast<ROL::StdVector<double>&>(v).getVector();
}
inline ROL::Ptr<ROL::StdVector<double>> stdVector(const std::vector<double>& v) {
  return ROL::makePtr<ROL::StdVector<double>>(ROL::makePtr<std::vector<double>>(v));
}

}  // namespace flowform
