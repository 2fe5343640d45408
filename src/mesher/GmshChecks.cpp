// The mesher's checks of its input before it meshes (GmshChecks.hpp).
#include "flowform/mesher/GmshChecks.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

constexpr int kGmshLine2 = 1;  // gmsh element type: 2-node line

/// The Geo Parameters the .geo defines (a DefineConstant named "Parameters/NAME" has gmsh as
/// a onelab client; one we created alone has none), each with its onelab description.
std::map<std::string, nlohmann::json> definedGeoParameters() {
  std::map<std::string, nlohmann::json> defined;
  std::vector<std::string> names;
  gmsh::onelab::getNames(names);
  for (const std::string& n : names) {
    if (n.rfind("Parameters/", 0) != 0) continue;
    std::string text;
    gmsh::onelab::get(text, n);
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) continue;
    if (j.is_object() && j.contains("clients")) defined[n.substr(11)] = j;
  }
  return defined;
}

std::string formatNumber(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string cellCountText(double n) {
  std::ostringstream os;
  os.precision(2);
  os << n;
  return os.str();
}

}  // namespace

/// Every Geo Parameter given must be one the .geo defines, inside the range it declares:
/// DefineConstant's Min and Max (gmsh stores ±1e200 when none is given) and Choices are
/// input validation too.
void checkGeoParameters(const ReadOptions& opt) {
  const auto defined = definedGeoParameters();
  std::string names;
  for (const auto& [name, j] : defined) names += (names.empty() ? "" : ", ") + name;
  for (const auto& [name, value] : opt.geoParameters) {
    auto it = defined.find(name);
    if (it == defined.end())
      throw InputError("Mesh/Geo Parameters/" + name + ": '" + opt.path + "' defines no DefineConstant named \"Parameters/" +
                       name + "\"; it defines: " + (names.empty() ? "none" : names));
    const nlohmann::json& j = it->second;
    const std::string where = "Mesh/Geo Parameters/" + name + " = " + formatNumber(value) + ": '" + opt.path + "'";
    const double min = j.value("min", -1e200), max = j.value("max", 1e200);
    const bool hasMin = min > -1e199, hasMax = max < 1e199;
    if ((hasMin && value < min) || (hasMax && value > max))
      throw InputError(where + " declares the range [" + (hasMin ? formatNumber(min) : "-inf") + ", " +
                       (hasMax ? formatNumber(max) : "inf") + "] for it");
    if (j.contains("choices") && j["choices"].is_array() && !j["choices"].empty()) {
      bool found = false;
      std::string list;
      for (const auto& c : j["choices"]) {
        found = found || c.get<double>() == value;
        list += (list.empty() ? "" : ", ") + formatNumber(c.get<double>());
      }
      if (!found) throw InputError(where + " allows only the values {" + list + "}");
    }
  }
}

BoundaryMeasure measureBoundary() {
  BoundaryMeasure m;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, true, false);
  std::unordered_map<std::size_t, std::array<double, 2>> at;
  for (std::size_t k = 0; k < tags.size(); ++k) at[tags[k]] = {xyz[3 * k], xyz[3 * k + 1]};
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::set<int> curvesSeen;
  for (const auto& surface : surfaces) {
    gmsh::vectorpair boundary;
    gmsh::model::getBoundary({surface}, boundary, false, true, false);
    double twiceArea = 0.0;
    for (const auto& curve : boundary) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elemTags, nodeTags;
      gmsh::model::mesh::getElements(types, elemTags, nodeTags, 1, std::abs(curve.second));
      const double sign = curve.second < 0 ? -1.0 : 1.0;
      const bool first = curvesSeen.insert(std::abs(curve.second)).second;
      for (std::size_t k = 0; k < types.size(); ++k) {
        if (types[k] != kGmshLine2) continue;
        for (std::size_t e = 0; e < elemTags[k].size(); ++e) {
          const auto& a = at[nodeTags[k][2 * e]];
          const auto& b = at[nodeTags[k][2 * e + 1]];
          twiceArea += sign * (a[0] * b[1] - b[0] * a[1]);
          if (first) m.lengths.push_back(std::hypot(b[0] - a[0], b[1] - a[1]));
        }
      }
    }
    m.area += 0.5 * std::abs(twiceArea);
  }
  return m;
}

/// The number of cells the 2-D mesh will have, estimated from the 1-D mesh before meshing:
/// the surfaces' area over the area of a cell of the boundary edges' size. Each edge weighs
/// as its length (the sizes gmsh spreads inwards are the boundary's), and a cell of edge l is
/// √3/4 l² (an equilateral triangle) or l² (a square).
double estimateCells(const BoundaryMeasure& m, CellType type) {
  double length = 0.0, weighted = 0.0;
  for (double l : m.lengths)
    if (l > 0.0) {
      length += l;
      weighted += l / (l * l);
    }
  if (length <= 0.0) return 0.0;
  const double meanInverseSquare = weighted / length;  // mean of 1/l² along the boundary
  const double cellShape = type == CellType::Triangle3 ? std::sqrt(3.0) / 4.0 : 1.0;
  return m.area * meanInverseSquare / cellShape;
}

double estimateCells(const SizeField& field, CellType type) {
  const double cellShape = type == CellType::Triangle3 ? std::sqrt(3.0) / 4.0 : 1.0;
  double cells = 0.0;
  for (int t = 0; t < field.numTriangles(); ++t) {
    const double* v = &field.triangles[12 * t];  // x1 x2 x3 y1 y2 y3 z1 z2 z3 s1 s2 s3
    const double area = 0.5 * std::abs((v[1] - v[0]) * (v[5] - v[3]) - (v[2] - v[0]) * (v[4] - v[3]));
    double inverseSquare = 0.0;
    for (int a = 0; a < 3; ++a) inverseSquare += 1.0 / (3.0 * std::max(v[9 + a] * v[9 + a], 1e-300));
    cells += area * inverseSquare / cellShape;
  }
  return cells;
}

void refuseTooMany(const ReadOptions& opt, double cells, const std::string& how) {
  throw InputError("mesh file '" + opt.path + "': " + how + " about " + cellCountText(cells) +
                   " cells, more than Mesh/Maximum Cells = " + std::to_string(opt.maxCells) +
                   " (about " + cellCountText(cells * kBytesPerCellEstimate / 1e9) +
                   " GB to solve on); coarsen the mesh (Geo Parameters, Size Factor, Uniform "
                   "Refinements) or raise Mesh/Maximum Cells");
}

}  // namespace flowform
