#include "flowform/mesh/MeshOptions.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/mesh/MeshReader.hpp"

namespace flowform {

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
          "transfinite curves. Must stay 1 for a .msh. Between 1e-3 and 1e3 (a smaller factor "
          "asks gmsh for its curves' points by the billion before anything can be counted).",
          inRange(1e-3, 1e3));
  pl->set(
      "Uniform Refinements", 0,
      "Times every cell is split into 4 (gmsh::model::mesh::refine) after reading or meshing.",
      intAtLeast(0));
  pl->set("Verbose", false, "Let gmsh print its log on rank 0.");
  pl->set("Maximum Cells", 1000000,
          "The largest mesh flowform makes: a .geo's cell count is estimated from its 1-D mesh "
          "before the surfaces are meshed, a refinement's exactly, and a larger mesh is refused "
          "(exit 2, with the estimate). Raise it for a larger mesh the machine can hold (about "
          "6 kB of memory per cell to solve on, more for the finest meshes).",
          intAtLeast(1));
  pl->set("Time Limit", 120.0,
          "Seconds gmsh may take to read, mesh and refine the file (it runs in a process of its "
          "own); past that it is stopped and the run ends with exit 2 naming the file.",
          positive());
  Teuchos::ParameterList& geo = pl->sublist(
      "Geo Parameters", false,
      "Numbers handed to a .geo before it is parsed: an entry NAME = v sets the onelab number "
      "\"Parameters/NAME\", which the .geo reads with "
      "DefineConstant[ NAME = {default, Name \"Parameters/NAME\"} ];. A NAME the .geo does not "
      "define that way is an error.");
  geo.disableRecursiveValidation();  // its entries are the .geo's names, checked in readMesh
  Teuchos::ParameterList& reference = pl->sublist(
      "Reference Geo Parameters", false,
      "Geo Parameters whose mesh gives the topology (docs/optimization.md §2): the .geo is meshed with these "
      "values (over Geo Parameters), then its nodes are moved to the shape at Geo Parameters, each boundary group's "
      "nodes by arc length between its corners, the interior by the harmonic extension. Empty: the mesh at Geo "
      "Parameters itself. The optimizer sets it to keep one topology across the designs of a shape parameter");
  reference.disableRecursiveValidation();
  return pl;
}

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
  opt.maxCells = params.get<int>("Maximum Cells");
  opt.timeLimit = params.get<double>("Time Limit");
  const Teuchos::ParameterList& geo = params.sublist("Geo Parameters");
  for (auto it = geo.begin(); it != geo.end(); ++it) {
    const std::string& name = geo.name(it);
    const Teuchos::ParameterEntry& entry = geo.entry(it);
    if (entry.isType<double>() && !std::isfinite(Teuchos::getValue<double>(entry)))
      throw InputError("Mesh/Geo Parameters/" + name + " = " + Teuchos::toString(Teuchos::getValue<double>(entry)) +
                       " is not a finite number");
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

}  // namespace flowform
