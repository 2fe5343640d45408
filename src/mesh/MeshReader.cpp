// Mesh input through gmsh's C++ API. Rank 0 alone talks to gmsh (gmsh keeps global state
// and is not MPI-aware); the finished Mesh, or the error text, is packed into one byte
// buffer and broadcast, so every rank returns the same mesh or throws the same error and
// no rank is left waiting in a collective when rank 0 fails.
#include "flowform/mesh/MeshReader.hpp"

#include <gmsh.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

constexpr int kGmshLine2 = 1;  // gmsh element types: 2-node line,
constexpr int kGmshTri3 = 2;   // 3-node triangle,
constexpr int kGmshQuad4 = 3;  // 4-node quadrangle
// |area| below this times (longest edge)^2 is a degenerate cell: far below any element a
// mesher produces on purpose, far above round-off of coordinates of order one.
constexpr double kDegenerateRatio = 1e-12;

struct ReadOptions {
  std::string path;  ///< File resolved against baseDir
  bool isGeo = false;
  CellType cellType = CellType::Triangle3;
  double sizeFactor = 1.0;
  int refinements = 0;
  bool verbose = false;
  std::vector<std::pair<std::string, double>> geoParameters;
};

/// Validation and defaults on every rank: they depend on the parameter list only, so all
/// ranks throw the same InputError here without talking to each other.
ReadOptions parseOptions(const Teuchos::ParameterList& given, const std::string& baseDir) {
  Teuchos::ParameterList params(given);
  try {
    params.validateParametersAndSetDefaults(*validMeshParameters());
  } catch (const std::exception& e) {
    throw InputError(std::string("invalid parameter in the Mesh list: ") + e.what());
  }
  ReadOptions opt;
  const std::string file = params.get<std::string>("File");
  if (file.empty()) throw InputError("Mesh/File is required: the .msh or .geo file to read");
  std::filesystem::path path(file);
  if (path.is_relative() && !baseDir.empty()) path = std::filesystem::path(baseDir) / path;
  opt.path = path.lexically_normal().string();
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  if (ext != ".msh" && ext != ".geo")
    throw InputError("mesh file '" + opt.path + "' (Mesh/File): unknown extension '" + ext +
                     "'; flowform reads gmsh .msh and .geo files");
  opt.isGeo = ext == ".geo";
  opt.cellType = Teuchos::getIntegralValue<CellType>(params, "Element Type");
  opt.sizeFactor = params.get<double>("Size Factor");
  opt.refinements = params.get<int>("Uniform Refinements");
  opt.verbose = params.get<bool>("Verbose");
  const Teuchos::ParameterList& geo = params.sublist("Geo Parameters");
  for (auto it = geo.begin(); it != geo.end(); ++it) {
    const std::string& name = geo.name(it);
    const Teuchos::ParameterEntry& entry = geo.entry(it);
    if (entry.isType<double>())
      opt.geoParameters.emplace_back(name, Teuchos::getValue<double>(entry));
    else if (entry.isType<int>())
      opt.geoParameters.emplace_back(name, Teuchos::getValue<int>(entry));
    else
      throw InputError("Mesh/Geo Parameters/" + name + " must be a number (type double)");
  }
  // Options that only shape meshing would be silently ignored for a ready-made .msh.
  if (!opt.isGeo && !opt.geoParameters.empty())
    throw InputError("Mesh/Geo Parameters is set but '" + opt.path +
                     "' is a .msh file; Geo Parameters only apply to .geo files");
  if (!opt.isGeo && opt.sizeFactor != 1.0)
    throw InputError("Mesh/Size Factor is set but '" + opt.path +
                     "' is a .msh file; Size Factor only applies to .geo files (use Uniform "
                     "Refinements)");
  return opt;
}

// ------------------------------------------------------------------------------------------
// Rank 0: gmsh

/// gmsh::initialize ... gmsh::finalize, also on the error path.
class GmshSession {
 public:
  explicit GmshSession(bool verbose) {
    gmsh::initialize(0, nullptr, false);  // no gmshrc: results must not depend on the user
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
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

/// Opens (and for a .geo, meshes) the file, then refines. Leaves the model in gmsh.
void loadModel(const ReadOptions& opt) {
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
  if (opt.isGeo) {
    // A parameter the .geo defined has gmsh as a onelab client; one we created alone has none.
    std::vector<std::string> names;
    gmsh::onelab::getNames(names);
    std::string defined;
    for (const std::string& n : names) {
      if (n.rfind("Parameters/", 0) != 0) continue;
      std::string json;
      gmsh::onelab::get(json, n);
      if (json.find("\"clients\"") != std::string::npos)
        defined += (defined.empty() ? "" : ", ") + n.substr(11);
    }
    for (const auto& [name, value] : opt.geoParameters) {
      std::string json;
      gmsh::onelab::get(json, "Parameters/" + name);
      if (json.find("\"clients\"") == std::string::npos)
        throw InputError("Mesh/Geo Parameters/" + name + ": '" + opt.path +
                         "' defines no DefineConstant named \"Parameters/" + name +
                         "\"; it defines: " + (defined.empty() ? "none" : defined));
    }
    gmshStep(opt.path, "meshing it", [] { gmsh::model::mesh::generate(2); });
  }
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
  std::array<std::array<double, 2>, 4> x{};
  for (int i = 0; i < npc; ++i) x[i] = mesh.coords[mesh.cell(c)[i]];
  auto cross = [](const std::array<double, 2>& a, const std::array<double, 2>& b,
                  const std::array<double, 2>& o) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  double longest2 = 0;
  for (int i = 0; i < npc; ++i) {
    const double dx = x[(i + 1) % npc][0] - x[i][0], dy = x[(i + 1) % npc][1] - x[i][1];
    longest2 = std::max(longest2, dx * dx + dy * dy);
  }
  const double tiny = 2.0 * kDegenerateRatio * longest2;  // on twice the area
  auto degenerate = [&](const std::string& why) {
    return InputError("degenerate " + cellLabel(mesh, c, gmshTag) + " in mesh file '" +
                      mesh.source + "': " + why);
  };
  if (mesh.cellType == CellType::Triangle3) {
    const double twiceArea = cross(x[1], x[2], x[0]);
    if (std::abs(twiceArea) <= tiny) throw degenerate("its area is zero");
    return twiceArea > 0 ? 1 : -1;
  }
  // Quadrilateral: the corners decide. Same-signed nonzero corner Jacobians also bound the
  // area away from zero, while a bow-tie can have zero net area and is reported as inverted.
  int positive = 0, negative = 0;
  for (int i = 0; i < 4; ++i) {
    // Jacobian determinant of the bilinear map at corner i (times 4): twice the area of
    // the triangle the corner and its two neighbours span.
    const double j = cross(x[(i + 1) % 4], x[(i + 3) % 4], x[i]);
    if (std::abs(j) <= tiny)
      throw degenerate("corner " + std::to_string(i) + " has a zero or 180 degree angle");
    (j > 0 ? positive : negative)++;
  }
  if (positive == 4) return 1;
  if (negative == 4) return -1;
  throw InputError("inverted " + cellLabel(mesh, c, gmshTag) + " in mesh file '" + mesh.source +
                   "': its corner Jacobians differ in sign (bow-tie or non-convex quadrilateral)");
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

Mesh readOnRoot(const ReadOptions& opt) {
  if (!std::filesystem::is_regular_file(opt.path))
    throw InputError("mesh file '" + opt.path + "' (Mesh/File) does not exist");
  GmshSession session(opt.verbose);
  loadModel(opt);
  Mesh mesh;
  gmshStep(opt.path, "extracting the mesh", [&] { mesh = extractMesh(opt); });
  return mesh;
}

// ------------------------------------------------------------------------------------------
// Broadcast: the mesh as one byte buffer (plain copies of trivially copyable data).

class Packer {
 public:
  template <class T>
  void put(const T& value) {
    putRaw(&value, sizeof(T));
  }
  template <class T>
  void putVector(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    putRaw(v.data(), v.size() * sizeof(T));
  }
  void putString(const std::string& s) { putVector(std::vector<char>(s.begin(), s.end())); }
  std::vector<char> bytes;

 private:
  void putRaw(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    bytes.insert(bytes.end(), c, c + n);
  }
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : m_bytes(bytes) {}
  template <class T>
  T get() {
    T value;
    getRaw(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getVector() {
    std::vector<T> v(get<std::uint64_t>());
    getRaw(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string getString() {
    auto v = getVector<char>();
    return std::string(v.begin(), v.end());
  }

 private:
  void getRaw(void* p, std::size_t n) {
    if (m_pos + n > m_bytes.size()) throw std::logic_error("readMesh: broadcast buffer too short");
    if (n > 0) std::memcpy(p, m_bytes.data() + m_pos, n);
    m_pos += n;
  }
  const std::vector<char>& m_bytes;
  std::size_t m_pos = 0;
};

enum Status : int { kOk = 0, kInputError = 1, kOtherError = 2 };

void packMesh(Packer& p, const Mesh& mesh) {
  p.putString(mesh.source);
  p.put<int>(static_cast<int>(mesh.cellType));
  p.putVector(mesh.coords);
  p.putVector(mesh.cellNodes);
  p.put<std::uint64_t>(mesh.boundaries.size());
  for (const BoundaryGroup& g : mesh.boundaries) {
    p.putString(g.name);
    p.putVector(g.edges);
  }
  p.put<std::uint64_t>(mesh.regions.size());
  for (const RegionGroup& g : mesh.regions) {
    p.putString(g.name);
    p.putVector(g.cells);
  }
}

Mesh unpackMesh(Unpacker& u) {
  Mesh mesh;
  mesh.source = u.getString();
  mesh.cellType = static_cast<CellType>(u.get<int>());
  mesh.coords = u.getVector<std::array<double, 2>>();
  mesh.cellNodes = u.getVector<GO>();
  mesh.boundaries.resize(u.get<std::uint64_t>());
  for (BoundaryGroup& g : mesh.boundaries) {
    g.name = u.getString();
    g.edges = u.getVector<std::array<GO, 2>>();
  }
  mesh.regions.resize(u.get<std::uint64_t>());
  for (RegionGroup& g : mesh.regions) {
    g.name = u.getString();
    g.cells = u.getVector<GO>();
  }
  return mesh;
}

void broadcastBytes(const Teuchos::Comm<int>& comm, std::vector<char>& bytes) {
  long long size = static_cast<long long>(bytes.size());
  Teuchos::broadcast<int, long long>(comm, 0, 1, &size);
  bytes.resize(static_cast<std::size_t>(size));
  const long long chunk = 1 << 30;  // MPI counts are int
  for (long long offset = 0; offset < size; offset += chunk)
    Teuchos::broadcast<int, char>(comm, 0, static_cast<int>(std::min(chunk, size - offset)),
                                  bytes.data() + offset);
}

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> validMeshParameters() {
  using Teuchos::tuple;
  auto pl = Teuchos::rcp(new Teuchos::ParameterList("Mesh"));
  pl->set("File", std::string(),
          "Mesh file, required: a gmsh .msh (format 4; 2.2 is read as well) or a .geo meshed "
          "on the fly. A relative path is taken relative to the directory of the case XML.");
  Teuchos::setStringToIntegralParameter<CellType>(
      "Element Type", "Triangle", "Cell type of the mesh (P1/P1 or Q1/Q1 elements).",
      tuple<std::string>("Triangle", "Quadrilateral"),
      tuple<std::string>("3-node triangles (gmsh type 2)",
                         "4-node quadrilaterals (gmsh type 3); a .geo is meshed with "
                         "Mesh.RecombineAll = 1"),
      tuple<CellType>(CellType::Triangle3, CellType::Quadrilateral4), pl.get());
  pl->set("Size Factor", 1.0,
          "Multiplies every mesh size of a .geo (gmsh option Mesh.MeshSizeFactor); no effect on "
          "transfinite curves. Must stay 1 for a .msh.",
          Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(
              std::numeric_limits<double>::min(), std::numeric_limits<double>::max())));
  pl->set(
      "Uniform Refinements", 0,
      "Times every cell is split into 4 (gmsh::model::mesh::refine) after reading or meshing.",
      Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, std::numeric_limits<int>::max())));
  pl->set("Verbose", false, "Let gmsh print its log on rank 0.");
  Teuchos::ParameterList& geo = pl->sublist(
      "Geo Parameters", false,
      "Numbers handed to a .geo before it is parsed: an entry NAME = v sets the onelab number "
      "\"Parameters/NAME\", which the .geo reads with "
      "DefineConstant[ NAME = {default, Name \"Parameters/NAME\"} ];. A NAME the .geo does not "
      "define that way is an error.");
  geo.disableRecursiveValidation();  // its entries are the .geo's names, checked in readMesh
  return pl;
}

Mesh readMesh(const Teuchos::ParameterList& meshParams, const std::string& baseDir,
              const Teuchos::Comm<int>& comm) {
  const ReadOptions opt = parseOptions(meshParams, baseDir);
  std::vector<char> bytes;
  if (comm.getRank() == 0) {
    Packer p;
    try {
      const Mesh mesh = readOnRoot(opt);
      p.put<int>(kOk);
      packMesh(p, mesh);
    } catch (const InputError& e) {
      p = Packer();
      p.put<int>(kInputError);
      p.putString(e.what());
    } catch (const std::exception& e) {
      p = Packer();
      p.put<int>(kOtherError);
      p.putString(std::string("reading mesh file '") + opt.path + "': " + e.what());
    }
    bytes = std::move(p.bytes);
  }
  broadcastBytes(comm, bytes);
  Unpacker u(bytes);
  const int status = u.get<int>();
  if (status == kInputError) throw InputError(u.getString());
  if (status != kOk) throw std::runtime_error(u.getString());
  return unpackMesh(u);
}

}  // namespace flowform
