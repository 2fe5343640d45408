#include "flowform/mesh/MeshPacking.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

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
    const std::uint64_t n = get<std::uint64_t>();
    if (n > (m_bytes.size() - m_pos) / std::max<std::size_t>(sizeof(T), 1))
      throw std::runtime_error("mesh buffer too short");
    std::vector<T> v(n);
    getRaw(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string getString() {
    auto v = getVector<char>();
    return std::string(v.begin(), v.end());
  }

 private:
  void getRaw(void* p, std::size_t n) {
    if (m_pos + n > m_bytes.size()) throw std::runtime_error("mesh buffer too short");
    if (n > 0) std::memcpy(p, m_bytes.data() + m_pos, n);
    m_pos += n;
  }
  const std::vector<char>& m_bytes;
  std::size_t m_pos = 0;
};

enum Status : int { kOk = 0, kInputError = 1, kOtherError = 2 };

}  // namespace

std::vector<char> packMesh(const Mesh& mesh) {
  Packer p;
  p.put<int>(kOk);
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
  return std::move(p.bytes);
}

std::vector<char> packMeshError(bool inputError, const std::string& message) {
  Packer p;
  p.put<int>(inputError ? kInputError : kOtherError);
  p.putString(message);
  return std::move(p.bytes);
}

Mesh unpackMesh(const std::vector<char>& bytes) {
  Unpacker u(bytes);
  const int status = u.get<int>();
  if (status == kInputError) throw InputError(u.getString());
  if (status != kOk) throw std::runtime_error(u.getString());
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

}  // namespace flowform
