// Output writers: the HDF5/XDMF pair read back through the HDF5 C API and the Teuchos XML
// parser, the boundary CSV against hand-computed u_t and u_n, and the JSON helpers.
#include <Teuchos_Array.hpp>
#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_TwoDArray.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Teuchos_XMLObject.hpp>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "flowform/io/BoundaryCsvWriter.hpp"
#include "flowform/io/JsonSummary.hpp"
#include "flowform/io/XdmfWriter.hpp"

namespace {

using namespace flowform;
namespace fs = std::filesystem;

/// A fresh directory per test, removed afterwards (ctest runs in the source tree).
struct TempDir {
  std::string path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "flowform-io-XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/// Unit square split along its diagonal: nodes 0..3 counter-clockwise from the origin.
Mesh twoTriangles() {
  Mesh mesh;
  mesh.source = "two-triangles";
  mesh.cellType = CellType::Triangle3;
  mesh.coords = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  mesh.cellNodes = {0, 1, 2, 0, 2, 3};
  return mesh;
}

FieldSet someFields() {
  FieldSet f;
  f.nodal.push_back({"velocity", 2, {1.0, 2.0, 3.0, -4.0, 0.1, 1e-300, -7.25, 1.0 / 3.0}});
  f.nodal.push_back({"pressure", 1, {10.0, 11.0, 12.5, -13.0}});
  f.nodal.push_back({"contact_status", 1, {1.0, 0.0, 2.0, 0.0}});
  f.nodal.push_back({"dU_dh", 2, {0.5, -0.5, 1.5, 2.5, 0.0, 0.0, 9.0, 8.0}});
  f.cell.push_back({"viscosity", 1, {1e6, 2.5e6}});
  f.cell.push_back({"cell_vec", 2, {1.0, 2.0, 3.0, 4.0}});
  return f;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// One dataset as read back: its shape and values converted to `memType`.
template <class T>
std::vector<T> readDataset(const std::string& file, const std::string& path, hid_t memType,
                           std::vector<hsize_t>& dims, bool& isInt64) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  const hid_t type = H5Dget_type(d);
  isInt64 = H5Tequal(type, H5T_STD_I64LE) > 0;
  const int rank = H5Sget_simple_extent_ndims(space);
  dims.assign(rank > 0 ? rank : 0, 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  std::vector<T> values(H5Sget_simple_extent_npoints(space));
  H5Dread(d, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return values;
}

std::vector<double> readDoubles(const std::string& file, const std::string& path,
                                std::vector<hsize_t>& dims) {
  bool isInt64 = false;
  return readDataset<double>(file, path, H5T_NATIVE_DOUBLE, dims, isInt64);
}

/// Attribute element of the grid by name, or nullptr.
const Teuchos::XMLObject* findAttribute(const Teuchos::XMLObject& grid, const std::string& name) {
  for (int i = 0; i < grid.numChildren(); ++i) {
    const Teuchos::XMLObject& c = grid.getChild(i);
    if (c.getTag() == "Attribute" && c.getAttribute("Name") == name) return &c;
  }
  return nullptr;
}

std::string dataItemText(const Teuchos::XMLObject& parent) {
  const Teuchos::XMLObject& item = parent.getChild(parent.findFirstChild("DataItem"));
  std::string text;
  for (int i = 0; i < item.numContentLines(); ++i) text += item.getContentLine(i);
  // The parser keeps surrounding whitespace; the writer puts none, but be lenient.
  const auto b = text.find_first_not_of(" \t\n");
  const auto e = text.find_last_not_of(" \t\n");
  return b == std::string::npos ? "" : text.substr(b, e - b + 1);
}

TEUCHOS_UNIT_TEST(Xdmf, TrianglesRoundTripThroughHdf5) {
  TempDir dir;
  const Mesh mesh = twoTriangles();
  const FieldSet fields = someFields();
  writeXdmf(dir.path, "solution", mesh, fields);
  const std::string h5 = dir.path + "/solution.h5";
  TEST_ASSERT(fs::exists(h5));
  TEST_ASSERT(!fs::exists(h5 + ".tmp"));

  std::vector<hsize_t> dims;
  const std::vector<double> xyz = readDoubles(h5, "/mesh/coordinates", dims);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({4, 3}));
  TEST_COMPARE_ARRAYS(xyz, std::vector<double>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));

  bool isInt64 = false;
  const std::vector<long long> topo =
      readDataset<long long>(h5, "/mesh/topology", H5T_NATIVE_LLONG, dims, isInt64);
  TEST_ASSERT(isInt64);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({2, 3}));
  TEST_COMPARE_ARRAYS(topo, mesh.cellNodes);

  // Vectors gain z = 0; values must come back bit for bit.
  const std::vector<double> u = readDoubles(h5, "/fields/velocity", dims);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({4, 3}));
  TEST_COMPARE_ARRAYS(u, std::vector<double>({1.0, 2.0, 0.0, 3.0, -4.0, 0.0, 0.1, 1e-300, 0.0,
                                              -7.25, 1.0 / 3.0, 0.0}));
  const std::vector<double> p = readDoubles(h5, "/fields/pressure", dims);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({4}));
  TEST_COMPARE_ARRAYS(p, fields.nodal[1].values);
  const std::vector<double> mu = readDoubles(h5, "/fields/viscosity", dims);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({2}));
  TEST_COMPARE_ARRAYS(mu, fields.cell[0].values);
  const std::vector<double> cv = readDoubles(h5, "/fields/cell_vec", dims);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({2, 3}));
  TEST_COMPARE_ARRAYS(cv, std::vector<double>({1, 2, 0, 3, 4, 0}));
}

TEUCHOS_UNIT_TEST(Xdmf, XmlParsesAndPointsAtTheDatasets) {
  TempDir dir;
  const Mesh mesh = twoTriangles();
  writeXdmf(dir.path, "solution", mesh, someFields());
  const std::string xdmf = dir.path + "/solution.xdmf";

  Teuchos::FileInputSource source(xdmf);
  const Teuchos::XMLObject root = source.getObject();
  TEST_EQUALITY(root.getTag(), "Xdmf");
  TEST_EQUALITY(root.getAttribute("Version"), "3.0");
  const Teuchos::XMLObject& domain = root.getChild(root.findFirstChild("Domain"));
  const Teuchos::XMLObject& grid = domain.getChild(domain.findFirstChild("Grid"));

  const Teuchos::XMLObject& topo = grid.getChild(grid.findFirstChild("Topology"));
  TEST_EQUALITY(topo.getAttribute("TopologyType"), "Triangle");
  TEST_EQUALITY(topo.getAttribute("NumberOfElements"), "2");
  const Teuchos::XMLObject& topoItem = topo.getChild(0);
  TEST_EQUALITY(topoItem.getAttribute("Dimensions"), "2 3");
  TEST_EQUALITY(topoItem.getAttribute("Precision"), "8");
  TEST_EQUALITY(dataItemText(topo), "solution.h5:/mesh/topology");

  const Teuchos::XMLObject& geo = grid.getChild(grid.findFirstChild("Geometry"));
  TEST_EQUALITY(geo.getAttribute("GeometryType"), "XYZ");
  TEST_EQUALITY(geo.getChild(0).getAttribute("Dimensions"), "4 3");
  TEST_EQUALITY(dataItemText(geo), "solution.h5:/mesh/coordinates");

  struct Expect {
    const char *name, *type, *center, *dims;
  };
  for (const Expect& e : {Expect{"velocity", "Vector", "Node", "4 3"},
                          Expect{"pressure", "Scalar", "Node", "4"},
                          Expect{"contact_status", "Scalar", "Node", "4"},
                          Expect{"dU_dh", "Vector", "Node", "4 3"},
                          Expect{"viscosity", "Scalar", "Cell", "2"},
                          Expect{"cell_vec", "Vector", "Cell", "2 3"}}) {
    const Teuchos::XMLObject* a = findAttribute(grid, e.name);
    TEST_ASSERT(a != nullptr);
    if (!a) continue;
    TEST_EQUALITY(a->getAttribute("AttributeType"), e.type);
    TEST_EQUALITY(a->getAttribute("Center"), e.center);
    TEST_EQUALITY(a->getChild(0).getAttribute("Dimensions"), e.dims);
    TEST_EQUALITY(dataItemText(*a), std::string("solution.h5:/fields/") + e.name);
  }
}

TEUCHOS_UNIT_TEST(Xdmf, QuadrilateralsAndOverwrite) {
  TempDir dir;
  Mesh mesh = twoTriangles();
  mesh.cellType = CellType::Quadrilateral4;
  mesh.cellNodes = {0, 1, 2, 3};
  FieldSet fields;
  fields.nodal.push_back({"pressure", 1, {1, 2, 3, 4}});
  writeXdmf(dir.path, "q", mesh, fields);
  fields.nodal[0].values = {5, 6, 7, 8};
  writeXdmf(dir.path, "q", mesh, fields);  // existing files are replaced

  std::vector<hsize_t> dims;
  TEST_COMPARE_ARRAYS(readDoubles(dir.path + "/q.h5", "/fields/pressure", dims),
                      std::vector<double>({5, 6, 7, 8}));
  bool isInt64 = false;
  readDataset<long long>(dir.path + "/q.h5", "/mesh/topology", H5T_NATIVE_LLONG, dims, isInt64);
  TEST_COMPARE_ARRAYS(dims, std::vector<hsize_t>({1, 4}));
  const std::string xml = readText(dir.path + "/q.xdmf");
  TEST_ASSERT(xml.find("TopologyType=\"Quadrilateral\"") != std::string::npos);
  TEST_ASSERT(xml.find("NumberOfElements=\"1\"") != std::string::npos);
  TEST_ASSERT(xml.find("Dimensions=\"1 4\"") != std::string::npos);
}

/// True when `f` throws T whose message contains `needle`.
template <class T, class F>
bool throwsNaming(F f, const std::string& needle, std::ostream& out) {
  try {
    f();
  } catch (const T& e) {
    out << "  threw: " << e.what() << "\n";
    return std::string(e.what()).find(needle) != std::string::npos;
  } catch (const std::exception& e) {
    out << "  threw another type: " << e.what() << "\n";
    return false;
  }
  out << "  did not throw\n";
  return false;
}

TEUCHOS_UNIT_TEST(Xdmf, BadSizesThrowAndWriteNothing) {
  TempDir dir;
  const Mesh mesh = twoTriangles();
  auto attempt = [&](FieldSet f) { return [&, f] { writeXdmf(dir.path, "bad", mesh, f); }; };

  FieldSet f = someFields();
  f.nodal[0].values.pop_back();
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'velocity'", out));
  f = someFields();
  f.cell[0].values.push_back(1.0);
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'viscosity'", out));
  f = someFields();
  f.nodal[2].components = 3;
  f.nodal[2].values.resize(12);
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'contact_status'", out));
  f = someFields();
  f.cell.push_back(f.cell[0]);
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'viscosity'", out));
  f = someFields();
  f.nodal[1].name = "d/dh";
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'d/dh'", out));
  TEST_ASSERT(throwsNaming<std::invalid_argument>(
      [&] { writeXdmf(dir.path, "a/b", mesh, someFields()); }, "'a/b'", out));
  TEST_ASSERT(fs::is_empty(dir.path));

  // HDF5 failure (no such directory) is a runtime_error that names the file.
  TEST_ASSERT(throwsNaming<std::runtime_error>(
      [&] { writeXdmf(dir.path + "/missing", "solution", mesh, someFields()); },
      "missing/solution.h5", out));
}

/// CSV rows as numbers, header separately.
std::vector<std::vector<double>> readCsv(const std::string& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEUCHOS_UNIT_TEST(BoundaryCsv, TangentialAndNormalVelocity) {
  TempDir dir;
  const Mesh mesh = twoTriangles();
  const FieldSet fields = someFields();

  // Bottom edge y = 0, outward normal (0,-1), so t = (1,0): the curve runs 0 -> 1.
  BoundaryCurve bottom;
  bottom.name = "bottom";
  bottom.nodes = {0, 1};
  bottom.arcLength = {0.0, 1.0};
  bottom.normals = {{0.0, -1.0}, {0.0, -1.0}};
  writeBoundaryCsv(dir.path, mesh, bottom, fields);
  std::string header;
  auto rows = readCsv(dir.path + "/boundary_bottom.csv", header);
  TEST_EQUALITY(header, "s,x,y,u_t,u_n,p,contact_status,dU_dh_x,dU_dh_y");
  TEST_EQUALITY(rows.size(), 2u);
  // node 0: u = (1,2) -> u_t = 1, u_n = -2; node 1: u = (3,-4) -> u_t = 3, u_n = 4.
  TEST_COMPARE_ARRAYS(rows[0], std::vector<double>({0, 0, 0, 1, -2, 10, 1, 0.5, -0.5}));
  TEST_COMPARE_ARRAYS(rows[1], std::vector<double>({1, 1, 0, 3, 4, 11, 0, 1.5, 2.5}));

  // Right edge x = 1, n = (1,0), t = (0,1): runs 1 -> 2. Node 2 has u = (0.1, 1e-300).
  BoundaryCurve right;
  right.name = "right";
  right.nodes = {1, 2};
  right.arcLength = {0.0, 1.0};
  right.normals = {{1.0, 0.0}, {1.0, 0.0}};
  writeBoundaryCsv(dir.path, mesh, right, fields);
  rows = readCsv(dir.path + "/boundary_right.csv", header);
  TEST_COMPARE_ARRAYS(rows[0], std::vector<double>({0, 1, 0, -4, 3, 11, 0, 1.5, 2.5}));
  TEST_COMPARE_ARRAYS(rows[1], std::vector<double>({1, 1, 1, 1e-300, 0.1, 12.5, 2, 0, 0}));

  // Diagonal normal at a corner: n = (1,-1)/sqrt2 at node 1, u = (3,-4).
  BoundaryCurve corner = bottom;
  corner.name = "corner";
  const double r = 1.0 / std::sqrt(2.0);
  corner.normals = {{r, -r}, {r, -r}};
  writeBoundaryCsv(dir.path, mesh, corner, fields);
  rows = readCsv(dir.path + "/boundary_corner.csv", header);
  // t = (r, r): u_t = (3 - 4) r, u_n = (3 + 4) r.
  TEST_FLOATING_EQUALITY(rows[1][3], -r, 1e-15);
  TEST_FLOATING_EQUALITY(rows[1][4], 7.0 * r, 1e-15);
  TEST_ASSERT(!fs::exists(dir.path + "/boundary_corner.csv.tmp"));
}

TEUCHOS_UNIT_TEST(BoundaryCsv, VectorFieldsNamingTheirComponentsGoAsTangentialAndNormal) {
  // A sensitivity field du/dh names its CSV columns: written like u_t, u_n, not as x, y.
  TempDir dir;
  const Mesh mesh = twoTriangles();
  FieldSet fields = someFields();
  fields.nodal.back().tangentialName = "du_t_dh";
  fields.nodal.back().normalName = "du_n_dh";
  BoundaryCurve right;
  right.name = "right";
  right.nodes = {1, 2};
  right.arcLength = {0.0, 1.0};
  right.normals = {{1.0, 0.0}, {1.0, 0.0}};  // t = (0, 1)
  writeBoundaryCsv(dir.path, mesh, right, fields);
  std::string header;
  const auto rows = readCsv(dir.path + "/boundary_right.csv", header);
  TEST_EQUALITY(header, "s,x,y,u_t,u_n,p,contact_status,du_t_dh,du_n_dh");
  // node 1: dU/dh = (1.5, 2.5) -> t 2.5, n 1.5; node 2: (0, 0).
  TEST_COMPARE_ARRAYS(rows[0], std::vector<double>({0, 1, 0, -4, 3, 11, 0, 2.5, 1.5}));
  TEST_COMPARE_ARRAYS(rows[1], std::vector<double>({1, 1, 1, 1e-300, 0.1, 12.5, 2, 0, 0}));
}

TEUCHOS_UNIT_TEST(BoundaryCsv, MissingOrBadFieldsThrow) {
  TempDir dir;
  const Mesh mesh = twoTriangles();
  BoundaryCurve bottom;
  bottom.name = "bottom";
  bottom.nodes = {0, 1};
  bottom.arcLength = {0.0, 1.0};
  bottom.normals = {{0.0, -1.0}, {0.0, -1.0}};
  auto attempt = [&](FieldSet f) {
    return [&, f] { writeBoundaryCsv(dir.path, mesh, bottom, f); };
  };

  FieldSet f = someFields();
  f.nodal.erase(f.nodal.begin());  // no velocity
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'velocity'", out));
  f = someFields();
  f.nodal.erase(f.nodal.begin() + 1);  // no pressure
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'pressure'", out));
  f = someFields();
  f.nodal[3].values.pop_back();
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(f), "'dU_dh'", out));
  bottom.nodes = {0, 4};
  TEST_ASSERT(throwsNaming<std::invalid_argument>(attempt(someFields()), "node id 4", out));
  TEST_ASSERT(fs::is_empty(dir.path));
}

TEUCHOS_UNIT_TEST(JsonSummary, ParameterListRoundTrip) {
  TempDir dir;
  Teuchos::ParameterList list("Case");
  list.set("Verbose", true);
  list.set("Max Iterations", 25);
  list.set("Tolerance", 1e-10);
  list.set("Mesh File", std::string("meshes/extrusion.geo"));
  list.set("Heights", Teuchos::Array<double>(Teuchos::tuple<double>(0.5, 1.25)));
  list.set("Steps", Teuchos::Array<int>(Teuchos::tuple<int>(1, 2, 3)));
  list.set("Groups", Teuchos::Array<std::string>(Teuchos::tuple<std::string>("die", "ram")));
  Teuchos::TwoDArray<int> table(1, 2, 7);
  list.set("Table", table);
  Teuchos::ParameterList& material = list.sublist("Material");
  material.set("Flow Stress", 120.0e6);
  material.sublist("Hardening").set("Law", std::string("Voce"));

  const nlohmann::json j = parameterListToJson(list);
  TEST_EQUALITY(j["Verbose"], true);
  TEST_EQUALITY(j["Max Iterations"], 25);
  TEST_ASSERT(j["Max Iterations"].is_number_integer());
  TEST_EQUALITY(j["Tolerance"].get<double>(), 1e-10);
  TEST_EQUALITY(j["Mesh File"], "meshes/extrusion.geo");
  TEST_EQUALITY(j["Heights"], nlohmann::json({0.5, 1.25}));
  TEST_EQUALITY(j["Steps"], nlohmann::json({1, 2, 3}));
  TEST_EQUALITY(j["Groups"], nlohmann::json({"die", "ram"}));
  TEST_ASSERT(j["Table"].is_string());
  TEST_EQUALITY(j["Material"]["Flow Stress"].get<double>(), 120.0e6);
  TEST_EQUALITY(j["Material"]["Hardening"]["Law"], "Voce");
  TEST_ASSERT(!list.getEntry("Tolerance").isUsed());  // conversion is a silent read

  const std::string path = dir.path + "/summary.json";
  writeJsonFile(path, j);
  TEST_ASSERT(!fs::exists(path + ".tmp"));
  const std::string text = readText(path);
  TEST_EQUALITY(nlohmann::json::parse(text), j);
  TEST_ASSERT(text.find("\n  \"Groups\": [") != std::string::npos);  // 2-space indent
}

TEUCHOS_UNIT_TEST(JsonSummary, NonFiniteIsNullAndErrorsNameThePath) {
  TempDir dir;
  Teuchos::ParameterList list;
  const double inf = std::numeric_limits<double>::infinity();
  list.set("nan", std::numeric_limits<double>::quiet_NaN());
  list.set("inf", inf);
  list.set("arr", Teuchos::Array<double>(Teuchos::tuple<double>(1.0, -inf)));
  nlohmann::json j = parameterListToJson(list);
  j["converged"] = false;
  const std::string path = dir.path + "/summary.json";
  writeJsonFile(path, j);
  const nlohmann::json back = nlohmann::json::parse(readText(path));  // throws if invalid
  TEST_ASSERT(back["nan"].is_null());
  TEST_ASSERT(back["inf"].is_null());
  TEST_EQUALITY(back["arr"], nlohmann::json({1.0, nullptr}));
  TEST_EQUALITY(back["converged"], false);

  // Invalid UTF-8 does not abort the summary.
  TEST_NOTHROW(writeJsonFile(path, nlohmann::json{{"s", std::string("bad \xff byte")}}));

  TEST_ASSERT(throwsNaming<std::runtime_error>(
      [&] { writeJsonFile(dir.path + "/no/such/summary.json", j); }, "no/such/summary.json",
      out));
}

}  // namespace
