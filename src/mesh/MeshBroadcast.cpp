#include "flowform/mesh/MeshBroadcast.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "flowform/core/InputError.hpp"

namespace flowform {

namespace {

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

Mesh broadcastMesh(const Teuchos::Comm<int>& comm, const std::function<Mesh()>& read, const std::string& context) {
  std::vector<char> bytes;
  if (comm.getRank() == 0) {
    Packer p;
    try {
      const Mesh mesh = read();
      p.put<int>(kOk);
      packMesh(p, mesh);
    } catch (const InputError& e) {
      p = Packer();
      p.put<int>(kInputError);
      p.putString(e.what());
    } catch (const std::exception& e) {
      p = Packer();
      p.put<int>(kOtherError);
      p.putString(context + ": " + e.what());
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
