// boundary_<name>.csv: one row per curve node, in curve order. Numbers are written in the
// shortest form that reads back to the same double (std::to_chars), so scripts comparing
// against the solver lose nothing and the files stay short; NaN and Inf appear as
// nan/inf, which Python's float() and pandas read.
#include "flowform/io/BoundaryCsvWriter.hpp"

#include "flowform/io/AtomicFile.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace flowform {
namespace {

void appendNumber(std::string& out, double v) {
  std::array<char, 32> buf;
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), res.ptr);
}

/// RFC 4180 quoting for header names that would otherwise split a column.
std::string csvName(const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
  std::string out = "\"";
  for (char c : name) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

const Field* findNodal(const FieldSet& fields, const std::string& name) {
  for (const Field& f : fields.nodal)
    if (f.name == name) return &f;
  return nullptr;
}

void checkSize(const Field& f, const Mesh& mesh, const std::string& curve) {
  if (f.components != 1 && f.components != 2)
    throw std::invalid_argument("writeBoundaryCsv(" + curve + "): nodal field '" + f.name +
                                "' has " + std::to_string(f.components) +
                                " components; expected 1 or 2");
  const std::size_t expected = static_cast<std::size_t>(mesh.numNodes()) * f.components;
  if (f.values.size() != expected)
    throw std::invalid_argument("writeBoundaryCsv(" + curve + "): nodal field '" + f.name +
                                "' has " + std::to_string(f.values.size()) +
                                " values; expected " + std::to_string(expected) + " (" +
                                std::to_string(mesh.numNodes()) + " nodes x " +
                                std::to_string(f.components) + " components)");
}

const Field& requireNodal(const FieldSet& fields, const std::string& name, int components,
                          const Mesh& mesh, const std::string& curve) {
  const Field* f = findNodal(fields, name);
  if (!f)
    throw std::invalid_argument("writeBoundaryCsv(" + curve + "): no nodal field '" + name +
                                "'");
  if (f->components != components)
    throw std::invalid_argument("writeBoundaryCsv(" + curve + "): nodal field '" + name +
                                "' has " + std::to_string(f->components) +
                                " components; expected " + std::to_string(components));
  checkSize(*f, mesh, curve);
  return *f;
}

void validateCurve(const BoundaryCurve& curve, const Mesh& mesh) {
  const std::string& c = curve.name;
  if (c.empty() || c.find('/') != std::string::npos)
    throw std::invalid_argument("writeBoundaryCsv: curve name '" + c +
                                "' is not usable in a file name");
  const std::size_t n = curve.nodes.size();
  if (curve.arcLength.size() != n || curve.normals.size() != n)
    throw std::invalid_argument("writeBoundaryCsv(" + c + "): " + std::to_string(n) +
                                " nodes but " + std::to_string(curve.arcLength.size()) +
                                " arc lengths and " + std::to_string(curve.normals.size()) +
                                " normals");
  for (GO id : curve.nodes)
    if (id < 0 || id >= mesh.numNodes())
      throw std::invalid_argument("writeBoundaryCsv(" + c + "): node id " + std::to_string(id) +
                                  " outside the mesh [0, " + std::to_string(mesh.numNodes()) +
                                  ")");
}

}  // namespace

void writeBoundaryCsv(const std::string& outDir, const Mesh& mesh, const BoundaryCurve& curve,
                      const FieldSet& fields) {
  // All checks before the file is opened: bad input writes nothing.
  validateCurve(curve, mesh);
  const Field& u = requireNodal(fields, "velocity", 2, mesh, curve.name);
  const Field& p = requireNodal(fields, "pressure", 1, mesh, curve.name);
  std::vector<const Field*> extra;
  for (const Field& f : fields.nodal) {
    if (f.name == "velocity" || f.name == "pressure") continue;
    checkSize(f, mesh, curve.name);
    extra.push_back(&f);
  }

  std::string text = "s,x,y,u_t,u_n,p";
  for (const Field* f : extra) {
    if (f->components == 1) {
      text += "," + csvName(f->name);
    } else if (!f->tangentialName.empty()) {
      text += "," + csvName(f->tangentialName) + "," + csvName(f->normalName);
    } else {
      text += "," + csvName(f->name + "_x") + "," + csvName(f->name + "_y");
    }
  }
  text += '\n';

  for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
    const GO node = curve.nodes[k];
    const double nx = curve.normals[k][0];
    const double ny = curve.normals[k][1];
    const double ux = u.values[2 * node];
    const double uy = u.values[2 * node + 1];
    // t = (-n_y, n_x): the material is on the left of the direction of travel.
    const double ut = -ux * ny + uy * nx;
    const double un = ux * nx + uy * ny;
    for (double v : {curve.arcLength[k], mesh.coords[node][0], mesh.coords[node][1], ut, un,
                     p.values[node]}) {
      appendNumber(text, v);
      text += ',';
    }
    for (const Field* f : extra) {
      if (f->components == 2 && !f->tangentialName.empty()) {
        const double vx = f->values[2 * node], vy = f->values[2 * node + 1];
        for (double v : {-vx * ny + vy * nx, vx * nx + vy * ny}) {
          appendNumber(text, v);
          text += ',';
        }
        continue;
      }
      for (int c = 0; c < f->components; ++c) {
        appendNumber(text, f->values[f->components * node + c]);
        text += ',';
      }
    }
    text.back() = '\n';
  }

  // Through a temporary name, so a reader never sees a half-written table.
  const std::string path =
      (outDir.empty() ? std::string(".") : outDir) + "/boundary_" + curve.name + ".csv";
  try {
    writeFileAtomically(path, text);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("writeBoundaryCsv: ") + e.what());
  }
}

}  // namespace flowform
