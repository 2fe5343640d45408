// XDMF 3 light data (XML) + HDF5 heavy data. Layout of <baseName>.h5:
//   /mesh/coordinates  float64 [nodes x 3]  (x, y, 0)
//   /mesh/topology     int64   [cells x nodesPerCell], counter-clockwise node ids
//   /fields/<name>     float64 [n] for scalars, [n x 3] (x, y, 0) for 2-D vectors,
//                      n = nodes for nodal fields, cells for cell fields
// Geometry is written as XYZ with z = 0 rather than XDMF's "XY": both XDMF readers in
// ParaView accept XYZ everywhere, and 3-component vectors then line up with the points
// for Glyph and Warp By Vector without a Calculator step.
#include "flowform/io/XdmfWriter.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace flowform {
namespace {

/// An HDF5 identifier closed on scope exit: an exception midway must not leave the file
/// open (HDF5 would keep it locked and unflushed until the process ends).
class H5Id {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Id(hid_t id, Closer close) : m_id(id), m_close(close) {}
  ~H5Id() { release(); }
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  hid_t get() const { return m_id; }
  bool valid() const { return m_id >= 0; }
  /// Closes now and reports whether HDF5 succeeded: closing the file is where it flushes.
  bool release() {
    const bool ok = m_id < 0 || m_close(m_id) >= 0;
    m_id = -1;
    return ok;
  }

 private:
  hid_t m_id;
  Closer m_close;
};

/// Turns off HDF5's automatic printing of its error stack while writing (we report errors
/// as exceptions) and restores the caller's setting afterwards, so the writer leaves no
/// global state behind.
class H5QuietErrors {
 public:
  H5QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &m_func, &m_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~H5QuietErrors() { H5Eset_auto2(H5E_DEFAULT, m_func, m_data); }
  H5QuietErrors(const H5QuietErrors&) = delete;
  H5QuietErrors& operator=(const H5QuietErrors&) = delete;

 private:
  H5E_auto2_t m_func = nullptr;
  void* m_data = nullptr;
};

/// The innermost description on HDF5's error stack: the one that says why (for example
/// "unable to open file: ... errno = 2, error message = 'No such file or directory'").
std::string hdf5ErrorDetail() {
  std::string detail;
  auto collect = [](unsigned, const H5E_error2_t* err, void* out) -> herr_t {
    if (err->desc && *err->desc) *static_cast<std::string*>(out) = err->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &detail);
  H5Eclear2(H5E_DEFAULT);
  return detail;
}

[[noreturn]] void throwHdf5(const std::string& file, const std::string& what) {
  const std::string detail = hdf5ErrorDetail();
  throw std::runtime_error("writeXdmf: cannot write '" + file + "': HDF5 failed to " + what +
                           (detail.empty() ? "" : " (" + detail + ")"));
}

/// Writes one contiguous dataset (data in C order, dims.size() <= 2).
void writeDataset(hid_t file, const std::string& fileName, const std::string& path,
                  const std::vector<hsize_t>& dims, hid_t fileType, hid_t memType,
                  const void* data) {
  H5Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (!space.valid()) throwHdf5(fileName, "create the dataspace of " + path);
  H5Id set(H5Dcreate2(file, path.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (!set.valid()) throwHdf5(fileName, "create dataset " + path);
  if (H5Dwrite(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throwHdf5(fileName, "write dataset " + path);
  if (!set.release()) throwHdf5(fileName, "close dataset " + path);
}

void createGroup(hid_t file, const std::string& fileName, const std::string& path) {
  H5Id group(H5Gcreate2(file, path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throwHdf5(fileName, "create group " + path);
}

/// Values as stored: scalars unchanged, 2-D vectors padded to (x, y, 0).
std::vector<double> paddedValues(const Field& field) {
  if (field.components == 1) return field.values;
  const std::size_t n = field.values.size() / 2;
  std::vector<double> out(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    out[3 * i] = field.values[2 * i];
    out[3 * i + 1] = field.values[2 * i + 1];
  }
  return out;
}

/// Checks everything before any file is touched, so bad input writes nothing.
void validate(const Mesh& mesh, const FieldSet& fields) {
  const std::size_t npc = static_cast<std::size_t>(nodesPerCell(mesh.cellType));
  if (mesh.cellNodes.empty() || mesh.cellNodes.size() % npc != 0)
    throw std::invalid_argument("writeXdmf: mesh '" + mesh.source + "' has " +
                                std::to_string(mesh.cellNodes.size()) +
                                " cell node ids; expected a positive multiple of " +
                                std::to_string(npc));
  for (GO id : mesh.cellNodes)
    if (id < 0 || id >= mesh.numNodes())
      throw std::invalid_argument("writeXdmf: mesh '" + mesh.source + "' has cell node id " +
                                  std::to_string(id) + " outside [0, " +
                                  std::to_string(mesh.numNodes()) + ")");

  std::set<std::string> names;
  auto check = [&](const Field& f, const char* where, GO count, const char* what) {
    if (f.name.empty() || f.name.find('/') != std::string::npos || f.name == "." ||
        f.name == "..")
      throw std::invalid_argument(std::string("writeXdmf: ") + where + " field name '" +
                                  f.name + "' is not usable as an HDF5 dataset name");
    // One namespace for nodal and cell fields: both live under /fields and ParaView
    // would show two arrays of one name.
    if (!names.insert(f.name).second)
      throw std::invalid_argument("writeXdmf: field '" + f.name + "' is given twice");
    if (f.components != 1 && f.components != 2)
      throw std::invalid_argument("writeXdmf: " + std::string(where) + " field '" + f.name +
                                  "' has " + std::to_string(f.components) +
                                  " components; expected 1 or 2");
    const std::size_t expected = static_cast<std::size_t>(count) * f.components;
    if (f.values.size() != expected)
      throw std::invalid_argument("writeXdmf: " + std::string(where) + " field '" + f.name +
                                  "' has " + std::to_string(f.values.size()) +
                                  " values; expected " + std::to_string(expected) + " (" +
                                  std::to_string(count) + " " + what + " x " +
                                  std::to_string(f.components) + " components)");
  };
  for (const Field& f : fields.nodal) check(f, "nodal", mesh.numNodes(), "nodes");
  for (const Field& f : fields.cell) check(f, "cell", mesh.numCells(), "cells");
}

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Writes the heavy data to `path`; messages name `fileName`, the file the user will look for.
void writeH5(const std::string& path, const std::string& fileName, const Mesh& mesh,
             const FieldSet& fields) {
  const H5QuietErrors quiet;
  // Default property lists: one rank writes, so no MPI-IO driver even though this is the
  // openmpi build of HDF5.
  H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throwHdf5(fileName, "create the file");

  const hsize_t nodes = static_cast<hsize_t>(mesh.numNodes());
  const hsize_t cells = static_cast<hsize_t>(mesh.numCells());
  createGroup(file.get(), fileName, "/mesh");
  std::vector<double> xyz(3 * nodes, 0.0);
  for (hsize_t i = 0; i < nodes; ++i) {
    xyz[3 * i] = mesh.coords[i][0];
    xyz[3 * i + 1] = mesh.coords[i][1];
  }
  writeDataset(file.get(), fileName, "/mesh/coordinates", {nodes, 3}, H5T_IEEE_F64LE,
               H5T_NATIVE_DOUBLE, xyz.data());
  static_assert(sizeof(GO) == 8, "topology is stored as int64");
  writeDataset(file.get(), fileName, "/mesh/topology",
               {cells, static_cast<hsize_t>(nodesPerCell(mesh.cellType))}, H5T_STD_I64LE,
               H5T_NATIVE_LLONG, mesh.cellNodes.data());

  createGroup(file.get(), fileName, "/fields");
  auto writeField = [&](const Field& f, hsize_t count) {
    const std::vector<double> values = paddedValues(f);
    std::vector<hsize_t> dims{count};
    if (f.components == 2) dims.push_back(3);
    writeDataset(file.get(), fileName, "/fields/" + f.name, dims, H5T_IEEE_F64LE,
                 H5T_NATIVE_DOUBLE, values.data());
  };
  for (const Field& f : fields.nodal) writeField(f, nodes);
  for (const Field& f : fields.cell) writeField(f, cells);
  if (!file.release()) throwHdf5(fileName, "close (flush) the file");
}

std::string xdmfText(const std::string& h5Name, const Mesh& mesh, const FieldSet& fields) {
  const std::string h5 = xmlEscape(h5Name);
  const std::string nodes = std::to_string(mesh.numNodes());
  const std::string cells = std::to_string(mesh.numCells());
  const std::string npc = std::to_string(nodesPerCell(mesh.cellType));
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"mesh\" GridType=\"Uniform\">\n"
    << "      <Topology TopologyType=\"" << cellTypeName(mesh.cellType)
    << "\" NumberOfElements=\"" << cells << "\" NodesPerElement=\"" << npc << "\">\n"
    << "        <DataItem Dimensions=\"" << cells << " " << npc
    << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5
    << ":/mesh/topology</DataItem>\n"
    << "      </Topology>\n"
    << "      <Geometry GeometryType=\"XYZ\">\n"
    << "        <DataItem Dimensions=\"" << nodes
    << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
    << ":/mesh/coordinates</DataItem>\n"
    << "      </Geometry>\n";
  auto attribute = [&](const Field& f, const char* center, const std::string& count) {
    const bool vector = f.components == 2;
    const std::string name = xmlEscape(f.name);
    x << "      <Attribute Name=\"" << name << "\" AttributeType=\""
      << (vector ? "Vector" : "Scalar") << "\" Center=\"" << center << "\">\n"
      << "        <DataItem Dimensions=\"" << count << (vector ? " 3" : "")
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/fields/"
      << name << "</DataItem>\n"
      << "      </Attribute>\n";
  };
  for (const Field& f : fields.nodal) attribute(f, "Node", nodes);
  for (const Field& f : fields.cell) attribute(f, "Cell", cells);
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x.str();
}

/// Replaces `target` by `tmp` in one step, so a reader (or a crash) never sees half a file.
void moveInto(const std::string& tmp, const std::string& target) {
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw std::runtime_error("writeXdmf: cannot rename '" + tmp + "' to '" + target +
                             "': " + std::strerror(err));
  }
}

}  // namespace

void writeXdmf(const std::string& outDir, const std::string& baseName, const Mesh& mesh,
               const FieldSet& fields) {
  if (baseName.empty() || baseName.find('/') != std::string::npos)
    throw std::invalid_argument("writeXdmf: base name '" + baseName +
                                "' must be a plain file name");
  validate(mesh, fields);
  const std::string prefix = (outDir.empty() ? std::string(".") : outDir) + "/" + baseName;
  const std::string h5Path = prefix + ".h5";
  const std::string xdmfPath = prefix + ".xdmf";

  // Both files go through a temporary name: an .xdmf must never point at a half-written
  // or stale .h5 of another run.
  try {
    writeH5(h5Path + ".tmp", h5Path, mesh, fields);
  } catch (...) {
    std::remove((h5Path + ".tmp").c_str());
    throw;
  }
  {
    std::ofstream out(xdmfPath + ".tmp", std::ios::binary | std::ios::trunc);
    if (!out) {
      const int err = errno;
      std::remove((h5Path + ".tmp").c_str());
      throw std::runtime_error("writeXdmf: cannot create '" + xdmfPath + ".tmp': " +
                               std::strerror(err));
    }
    // The XDMF names the .h5 relative to itself, so the pair can be moved together.
    // (ParaView 5.11's Xdmf3 readers resolve it wrongly when handed a bare "x.xdmf" with
    // no directory part, as in pvpython OpenDataFile("x.xdmf"); "./x.xdmf", relative
    // paths with a directory, absolute paths and the GUI all work.)
    out << xdmfText(baseName + ".h5", mesh, fields);
    out.close();
    if (!out) {
      std::remove((xdmfPath + ".tmp").c_str());
      std::remove((h5Path + ".tmp").c_str());
      throw std::runtime_error("writeXdmf: cannot write '" + xdmfPath + ".tmp'");
    }
  }
  moveInto(h5Path + ".tmp", h5Path);
  moveInto(xdmfPath + ".tmp", xdmfPath);
}

}  // namespace flowform
