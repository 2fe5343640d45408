// Mesh input through gmsh's C++ API, in the mesher process (GmshMesher.hpp).
#include "flowform/mesher/GmshMesher.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/mesher/GmshChecks.hpp"


namespace flowform {

namespace {

constexpr int kGmshLine2 = 1;  // gmsh element types: 2-node line,
constexpr int kGmshTri3 = 2;   // 3-node triangle,
constexpr int kGmshQuad4 = 3;  // 4-node quadrangle

// Rank 0: gmsh

/// gmsh::initialize ... gmsh::finalize, also on the error path.
class GmshSession {
 public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);  // no gmshrc: results must not depend on the user
    // gmsh's log goes to the mesher's output, which MesherProcess keeps: its last error is the
    // message when gmsh aborts, and Mesh/Verbose shows it all.
    gmsh::option::setNumber("General.Terminal", 1);
    // The onelab database outlives gmsh::finalize (seen in 4.8.4): without this, the Geo
    // Parameters of one read would silently apply to the next.
    gmsh::onelab::clear();
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// Runs `step`, turning gmsh's exceptions (4.8 throws a std::string on errors, an int when
/// not initialized) into InputError; C++ exceptions (our own InputError, or a bug) pass.
template <class Step>
void gmshStep(const std::string& path, const char* what, Step step) {
  std::string message;
  try {
    step();
    return;
  } catch (const std::exception&) {
    throw;
  } catch (const std::string& e) {
    message = e;
  } catch (...) {
  }
  std::string last;
  gmsh::logger::getLastError(last);
  if (message.empty()) message = last.empty() ? "unknown gmsh error" : last;
  throw InputError("mesh file '" + path + "': gmsh failed while " + what + ": " + message);
}

/// Opens (and for a .geo, meshes) the file, then refines. Leaves the model in gmsh. The
/// mesh's size is estimated before each step that makes cells, and refused above maxCells.
void loadModel(const ReadOptions& opt, const SizeField* sizeField) {
  const bool quads = opt.cellType == CellType::Quadrilateral4;
  if (opt.isGeo) {
    gmsh::option::setNumber("Mesh.MeshSizeFactor", opt.sizeFactor);
    gmsh::option::setNumber("Mesh.RecombineAll", quads ? 1 : 0);
    // Blossom (gmsh's default). The "full-quad" variants crashed gmsh 4.8.4 on a surface
    // with an odd number of boundary segments; Blossom leaves a triangle there instead,
    // which is reported below as a mixed mesh.
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
    // Set before parsing: DefineConstant[ NAME = {v, Name "Parameters/NAME"} ] takes an
    // existing onelab value in preference to its default.
    for (const auto& [name, value] : opt.geoParameters)
      gmsh::onelab::setNumber("Parameters/" + name, {value});
  }
  gmshStep(opt.path, "reading it", [&] { gmsh::open(opt.path); });
  double cells = 0.0;
  if (opt.isGeo) {
    checkGeoParameters(opt);
    if (sizeField && !sizeField->empty())
      gmshStep(opt.path, "setting the size field", [&] {
        // The field alone sets the sizes: the .geo's point sizes, its own Background Field,
        // curvature and the extension of boundary sizes inwards are all replaced by it.
        const int view = gmsh::view::add("flowform size field");
        gmsh::view::addListData(view, "ST", sizeField->numTriangles(), sizeField->triangles);
        const int field = gmsh::model::mesh::field::add("PostView");
        gmsh::model::mesh::field::setNumber(field, "ViewTag", view);
        gmsh::model::mesh::field::setAsBackgroundMesh(field);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
      });
    gmshStep(opt.path, "meshing its curves", [] { gmsh::model::mesh::generate(1); });
    const bool fromField = sizeField && !sizeField->empty();
    cells = fromField ? estimateCells(*sizeField, opt.cellType) : estimateCells(measureBoundary(), opt.cellType);
    const std::string source = fromField ? " (estimated from the size field)" : " (estimated from its 1-D mesh)";
    if (cells * std::pow(4.0, opt.refinements) > static_cast<double>(opt.maxCells))
      refuseTooMany(opt, cells * std::pow(4.0, opt.refinements),
                    opt.refinements > 0 ? "meshing and refining it " + std::to_string(opt.refinements) +
                                              " times would make" + source
                                        : "meshing it would make" + source);
    gmshStep(opt.path, "meshing it", [] { gmsh::model::mesh::generate(2); });
  }
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elemTags, nodeTags;
  gmsh::model::mesh::getElements(types, elemTags, nodeTags, 2, -1);
  cells = 0.0;
  for (const auto& t : elemTags) cells += static_cast<double>(t.size());
  if (cells * std::pow(4.0, opt.refinements) > static_cast<double>(opt.maxCells))
    refuseTooMany(opt, cells * std::pow(4.0, opt.refinements),
                  "refining its " + std::to_string(static_cast<long long>(cells)) + " cells " +
                      std::to_string(opt.refinements) + " times would make");
  for (int i = 0; i < opt.refinements; ++i)
    gmshStep(opt.path, "refining it", [] { gmsh::model::mesh::refine(); });
}

std::string elementName(int type) {
  std::string name;
  int dim, order, numNodes, numPrimary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, local, numPrimary);
  return name + " (gmsh type " + std::to_string(type) + ")";
}

std::string groupName(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  return name.empty() ? "group" + std::to_string(tag) : name;
}

/// The 2-D cells as gmsh has them, before renumbering and orientation checks.
struct RawCells {
  std::vector<std::size_t> nodeTags;     ///< nodesPerCell per cell
  std::vector<std::size_t> elementTags;  ///< gmsh element tag per cell
  std::map<int, std::vector<GO>> cellsOfEntity;
};

/// When the file has 2-D physical groups, only their cells are the mesh (what gmsh itself
/// would save); otherwise every surface is.
RawCells collectCells(const ReadOptions& opt) {
  gmsh::vectorpair groups, entities;
  gmsh::model::getPhysicalGroups(groups, 2);
  std::set<int> surfaces;
  if (groups.empty()) {
    gmsh::model::getEntities(entities, 2);
    for (const auto& dt : entities) surfaces.insert(dt.second);
  }
  for (const auto& g : groups) {
    std::vector<int> tags;
    gmsh::model::getEntitiesForPhysicalGroup(2, g.second, tags);
    surfaces.insert(tags.begin(), tags.end());
  }
  const int wanted = opt.cellType == CellType::Triangle3 ? kGmshTri3 : kGmshQuad4;
  std::map<int, std::size_t> typeCount;
  RawCells raw;
  for (int surface : surfaces) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elemTags, nodeTags;
    gmsh::model::mesh::getElements(types, elemTags, nodeTags, 2, surface);
    for (std::size_t k = 0; k < types.size(); ++k) {
      typeCount[types[k]] += elemTags[k].size();
      if (types[k] != wanted) continue;
      for (std::size_t e = 0; e < elemTags[k].size(); ++e) {
        raw.cellsOfEntity[surface].push_back(static_cast<GO>(raw.elementTags.size()));
        raw.elementTags.push_back(elemTags[k][e]);
      }
      raw.nodeTags.insert(raw.nodeTags.end(), nodeTags[k].begin(), nodeTags[k].end());
    }
  }
  std::string found;
  for (const auto& [type, count] : typeCount)
    found += (found.empty() ? "" : ", ") + std::to_string(count) + " x " + elementName(type);
  if (typeCount.empty())
    throw InputError("mesh file '" + opt.path + "' has no 2-D cells (triangles or quadrilaterals)");
  for (const auto& [type, count] : typeCount)
    if (type != kGmshTri3 && type != kGmshQuad4)
      throw InputError("mesh file '" + opt.path + "' has " + found +
                       "; flowform takes only first-order 3-node triangles or 4-node "
                       "quadrilaterals");
  if (typeCount.size() > 1)
    throw InputError("mesh file '" + opt.path + "' mixes cell types (" + found +
                     "); flowform takes one type per mesh" +
                     (opt.isGeo && opt.cellType == CellType::Quadrilateral4
                          ? std::string(" (gmsh could not recombine every triangle: make the "
                                        "number of boundary segments of each surface even, or "
                                        "put Mesh.SubdivisionAlgorithm = 1; in the .geo)")
                          : std::string()));
  if (typeCount.begin()->first != wanted)
    throw InputError("Mesh/Element Type is '" + std::string(cellTypeName(opt.cellType)) +
                     "' but mesh file '" + opt.path + "' has " + found);
  return raw;
}

/// "cell 3 (gmsh element 104, centroid (0.5, 0.25))", the words every cell error uses.
std::string cellLabel(const Mesh& mesh, GO c, std::size_t gmshTag) {
  const int npc = nodesPerCell(mesh.cellType);
  double cx = 0, cy = 0;
  for (int i = 0; i < npc; ++i) {
    cx += mesh.coords[mesh.cell(c)[i]][0] / npc;
    cy += mesh.coords[mesh.cell(c)[i]][1] / npc;
  }
  std::ostringstream os;
  os << "cell " << c << " (gmsh element " << gmshTag << ", centroid (" << cx << ", " << cy << "))";
  return os.str();
}

/// +1 for a counter-clockwise cell, -1 for a clockwise one. Throws for a degenerate cell, and
/// for a quadrilateral whose corner Jacobians differ in sign (bow-tie or non-convex): its
/// bilinear map is not invertible, whichever way round the nodes are listed.
int cellOrientation(const Mesh& mesh, GO c, std::size_t gmshTag) {
  const int npc = nodesPerCell(mesh.cellType);
  std::array<double, 2> x[4];
  for (int i = 0; i < npc; ++i) x[i] = mesh.coords[mesh.cell(c)[i]];
  const CellOrientation o = cellOrientation(mesh.cellType, x);
  if (o.kind == CellOrientation::Kind::Degenerate)
    throw InputError("degenerate " + cellLabel(mesh, c, gmshTag) + " in mesh file '" + mesh.source + "': " +
                     (mesh.cellType == CellType::Triangle3
                          ? std::string("its area is zero")
                          : "corner " + std::to_string(o.corner) + " has a zero or 180 degree angle"));
  if (o.kind == CellOrientation::Kind::Mixed)
    throw InputError("inverted " + cellLabel(mesh, c, gmshTag) + " in mesh file '" + mesh.source +
                     "': its corner Jacobians differ in sign (bow-tie or non-convex quadrilateral)");
  return o.kind == CellOrientation::Kind::CounterClockwise ? 1 : -1;
}

/// gmsh orients cells by the surface normal, so a surface drawn clockwise gives clockwise
/// cells: those are turned round. A cell against the majority of its own surface is an
/// inverted cell (a fold, or a hand-written node list in the wrong order).
void orientCells(Mesh& mesh, const RawCells& raw) {
  auto orientationName = [](int sign) { return sign > 0 ? "counter-clockwise" : "clockwise"; };
  const int npc = nodesPerCell(mesh.cellType);
  std::vector<int> sign(raw.elementTags.size());
  for (GO c = 0; c < mesh.numCells(); ++c) sign[c] = cellOrientation(mesh, c, raw.elementTags[c]);
  for (const auto& [surface, cells] : raw.cellsOfEntity) {
    std::size_t ccw = 0;
    for (GO c : cells) ccw += sign[c] > 0;
    const int majority = 2 * ccw >= cells.size() ? 1 : -1;
    for (GO c : cells) {
      if (sign[c] != majority)
        throw InputError("inverted " + cellLabel(mesh, c, raw.elementTags[c]) + " in mesh file '" +
                         mesh.source + "': it is " + orientationName(sign[c]) + " while " +
                         std::to_string(majority > 0 ? ccw : cells.size() - ccw) + " of the " +
                         std::to_string(cells.size()) + " cells of gmsh surface " +
                         std::to_string(surface) + " are " + orientationName(majority));
      if (majority < 0)
        std::reverse(mesh.cellNodes.begin() + c * npc + 1, mesh.cellNodes.begin() + (c + 1) * npc);
    }
  }
}

/// Two nodes at one point (a slit, or a duplicated node the file did not merge) make two
/// separate sides where the user drew one body: refused, with both named.
void checkCoincidentNodes(const Mesh& mesh, const std::string& path, const std::vector<std::size_t>& tagOfNode) {
  std::vector<GO> order(mesh.numNodes());
  for (GO i = 0; i < mesh.numNodes(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](GO a, GO b) { return mesh.coords[a] < mesh.coords[b]; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const auto& a = mesh.coords[order[k - 1]];
    const auto& b = mesh.coords[order[k]];
    if (a == b) {
      std::ostringstream os;
      os << "mesh file '" << path << "': nodes " << tagOfNode[order[k - 1]] << " and " << tagOfNode[order[k]]
         << " (gmsh tags) are both at (" << a[0] << ", " << a[1]
         << "): two nodes at one point (a slit or an unmerged duplicate) split the body; flowform "
            "needs a conforming mesh (in gmsh: Coherence Mesh; or remove the duplicate)";
      throw InputError(os.str());
    }
  }
}

Mesh extractMesh(const ReadOptions& opt) {
  Mesh mesh;
  mesh.source = opt.path;
  mesh.cellType = opt.cellType;
  const RawCells raw = collectCells(opt);

  // Nodes: only those used by 2-D cells, numbered 0.. in the order of their gmsh tags.
  std::vector<std::size_t> used(raw.nodeTags);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, GO> idOfTag;
  for (std::size_t i = 0; i < used.size(); ++i) idOfTag.emplace(used[i], static_cast<GO>(i));
  std::vector<std::size_t> allTags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(allTags, xyz, param, -1, -1, false, false);
  mesh.coords.resize(used.size());
  std::vector<char> placed(used.size(), 0);
  double zMin = std::numeric_limits<double>::max(), zMax = -zMin, extent = 0;
  for (std::size_t k = 0; k < allTags.size(); ++k) {
    auto it = idOfTag.find(allTags[k]);
    if (it == idOfTag.end()) continue;
    mesh.coords[it->second] = {xyz[3 * k], xyz[3 * k + 1]};
    placed[it->second] = 1;
    zMin = std::min(zMin, xyz[3 * k + 2]);
    zMax = std::max(zMax, xyz[3 * k + 2]);
    extent = std::max({extent, std::abs(xyz[3 * k]), std::abs(xyz[3 * k + 1])});
  }
  for (std::size_t i = 0; i < used.size(); ++i)
    if (!placed[i])
      throw InputError("mesh file '" + opt.path + "': a cell uses node " + std::to_string(used[i]) +
                       ", which the file does not define");
  if (zMax - zMin > 1e-10 * std::max(extent, 1.0))
    throw InputError("mesh file '" + opt.path + "' is not planar: node z ranges over [" +
                     std::to_string(zMin) + ", " + std::to_string(zMax) +
                     "]; flowform meshes lie in the x-y plane");
  mesh.cellNodes.reserve(raw.nodeTags.size());
  for (std::size_t tag : raw.nodeTags) mesh.cellNodes.push_back(idOfTag.at(tag));
  checkCoincidentNodes(mesh, opt.path, used);
  orientCells(mesh, raw);

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& g : groups) {
    RegionGroup region{groupName(2, g.second), {}};
    std::vector<int> surfaces;
    gmsh::model::getEntitiesForPhysicalGroup(2, g.second, surfaces);
    for (int s : surfaces) {
      auto it = raw.cellsOfEntity.find(s);
      if (it != raw.cellsOfEntity.end())
        region.cells.insert(region.cells.end(), it->second.begin(), it->second.end());
    }
    std::sort(region.cells.begin(), region.cells.end());
    for (const RegionGroup& r : mesh.regions)
      if (r.name == region.name)
        throw InputError("mesh file '" + opt.path + "' has two 2-D physical groups named '" +
                         r.name + "'");
    mesh.regions.push_back(std::move(region));
  }

  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& g : groups) {
    BoundaryGroup boundary{groupName(1, g.second), {}};
    if (mesh.hasBoundary(boundary.name))
      throw InputError("mesh file '" + opt.path + "' has two 1-D physical groups named '" +
                       boundary.name + "'");
    std::vector<int> curves;
    gmsh::model::getEntitiesForPhysicalGroup(1, g.second, curves);
    for (int curve : curves) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elemTags, nodeTags;
      gmsh::model::mesh::getElements(types, elemTags, nodeTags, 1, curve);
      for (std::size_t k = 0; k < types.size(); ++k) {
        if (types[k] != kGmshLine2)
          throw InputError("boundary group '" + boundary.name + "' in mesh file '" + opt.path +
                           "' has " + elementName(types[k]) +
                           " elements; flowform takes only 2-node lines");
        for (std::size_t e = 0; e < elemTags[k].size(); ++e) {
          std::array<GO, 2> edge{};
          for (int i = 0; i < 2; ++i) {
            auto it = idOfTag.find(nodeTags[k][2 * e + i]);
            if (it == idOfTag.end())
              throw InputError("boundary group '" + boundary.name + "' in mesh file '" + opt.path +
                               "': edge (gmsh element " + std::to_string(elemTags[k][e]) +
                               ") has node " + std::to_string(nodeTags[k][2 * e + i]) +
                               ", which is not a node of any 2-D cell");
            edge[i] = it->second;
          }
          boundary.edges.push_back(edge);
        }
      }
    }
    mesh.boundaries.push_back(std::move(boundary));
  }
  return mesh;
}

}  // namespace

Mesh meshWithGmsh(const ReadOptions& opt, const SizeField* sizeField) {
  GmshSession session;
  loadModel(opt, sizeField);
  Mesh mesh;
  gmshStep(opt.path, "extracting the mesh", [&] { mesh = extractMesh(opt); });
  return mesh;
}

}  // namespace flowform
