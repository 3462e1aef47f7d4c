// Writing the medial mesh as binary PLY, OBJ or .ma, atomically; and reading those files back.
//
// Text numbers are written with std::to_chars (the shortest text that parses back to the same
// double), so OBJ and .ma round-trip exactly, like PLY's raw doubles.
// What each format keeps:
// - PLY keeps everything: x y z radius per vertex, polygons, kind and solid per face, the 1-D edges
//   (`vertex1 vertex2 solid`) per edge. Faces are written as `list uchar int`; only a mesh with a
//   polygon of more than 255 vertices is written as `list uint int` (still standard PLY) since
//   uchar cannot count it. The edge element is written even when empty: the schema is then the
//   same for every file, so a script can read `edge` unconditionally, and viewers (MeshLab,
//   Open3D) skip elements they do not draw. Files without it (written before) read as no edges.
// - OBJ keeps positions, polygons and 1-D edges (`l i j`); the radius goes in a `vr r` line after
//   each `v` line (readers skip keywords they do not know). Kind and solid are lost: read back as
//   Voronoi / solid 0.
// - .ma (Q-MAT / MATFP) keeps positions, radius, triangles and 1-D edges: polygons are fanned from
//   their first vertex; the `e` lines are the unique sides of those triangles (diagonals included)
//   followed by the 1-D edges that are not such a side. Read back, faces are those triangles, kind
//   Voronoi, solid 0, and every `e` line that is no triangle's side is a 1-D edge, solid 0.
#include "write_medial_mesh.h"
#include "write_atomically.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <set>
#include <sstream>
#include <unistd.h>

#include "../errors.h"

namespace cadmedial {
namespace {

namespace fs = std::filesystem;

enum class Format { Ply, Obj, Ma };

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

Format format_of(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".ply") return Format::Ply;
  if (ext == ".obj") return Format::Obj;
  if (ext == ".ma") return Format::Ma;
  throw InvalidInput(path + ": unknown output type '" + ext + "' (expected .ply, .obj or .ma)");
}

// A mesh whose arrays disagree would write a corrupt file: refuse it with the reason.
void check_mesh(const MedialMesh& m) {
  const std::size_t nv = m.vertices.size(), nf = m.kind.size();
  auto fail = [](const std::string& why) { throw InvalidInput("medial mesh is inconsistent: " + why); };
  if (m.radius.size() != nv)
    fail("radius has " + std::to_string(m.radius.size()) + " values for " + std::to_string(nv) + " vertices");
  if (m.face_start.size() != nf + 1)
    fail("face_start has " + std::to_string(m.face_start.size()) + " offsets for " + std::to_string(nf) + " faces");
  if (m.solid.size() != nf)
    fail("solid has " + std::to_string(m.solid.size()) + " values for " + std::to_string(nf) + " faces");
  if (m.face_start.front() != 0 || m.face_start.back() != static_cast<int>(m.face_vertices.size()))
    fail("face_start does not span face_vertices");
  for (std::size_t f = 0; f < nf; ++f)
    if (m.face_start[f + 1] < m.face_start[f]) fail("face_start decreases at face " + std::to_string(f));
  for (int v : m.face_vertices)
    if (v < 0 || static_cast<std::size_t>(v) >= nv) fail("vertex index " + std::to_string(v) + " out of range");
  if (m.edge_solid.size() != m.edges.size())
    fail("edge_solid has " + std::to_string(m.edge_solid.size()) + " values for " + std::to_string(m.edges.size()) +
         " edges");
  for (std::size_t e = 0; e < m.edges.size(); ++e)
    for (int v : m.edges[e])
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        fail("edge " + std::to_string(e) + " has vertex index " + std::to_string(v) + " out of range");
}

// ---- small formatting helpers ---------------------------------------------------------------

void put_double(std::string& out, double x) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}
void put_int(std::string& out, long long x) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

// PLY is little-endian whatever the host; write bytes explicitly.
template <class U>
void put_le(std::string& out, U bits) {
  for (std::size_t i = 0; i < sizeof(U); ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
}
void put_le_double(std::string& out, double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  put_le(out, bits);
}

// Flushes `buf` into `out` once it is large, so huge meshes never sit twice in memory.
void drain(std::string& buf, std::ostream& out, bool force = false) {
  if (force || buf.size() > (1u << 20)) {
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    buf.clear();
  }
}

}  // namespace

// ---- writers --------------------------------------------------------------------------------

void write_ply(const MedialMesh& mesh, std::ostream& out) {
  check_mesh(mesh);
  bool wide = false;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) wide = wide || mesh.face_size(f) > 255;
  std::string buf;
  buf += "ply\nformat binary_little_endian 1.0\ncomment cadmedial medial axis; kind 0 voronoi, 1 edge, 2 corner\n";
  buf += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  buf += "property double x\nproperty double y\nproperty double z\nproperty double radius\n";
  buf += "element face " + std::to_string(mesh.num_faces()) + "\n";
  buf += wide ? "property list uint int vertex_indices\n" : "property list uchar int vertex_indices\n";
  buf += "property uchar kind\nproperty int solid\n";
  buf += "element edge " + std::to_string(mesh.num_edges()) + "\n";
  buf += "property int vertex1\nproperty int vertex2\nproperty int solid\nend_header\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    for (double c : mesh.vertices[v]) put_le_double(buf, c);
    put_le_double(buf, mesh.radius[v]);
    drain(buf, out);
  }
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int n = mesh.face_size(f);
    if (wide) put_le(buf, static_cast<std::uint32_t>(n));
    else buf.push_back(static_cast<char>(n));
    for (int i = 0; i < n; ++i) put_le(buf, static_cast<std::uint32_t>(mesh.face(f)[i]));
    buf.push_back(static_cast<char>(mesh.kind[f]));
    put_le(buf, static_cast<std::uint32_t>(mesh.solid[f]));
    drain(buf, out);
  }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    put_le(buf, static_cast<std::uint32_t>(mesh.edges[e][0]));
    put_le(buf, static_cast<std::uint32_t>(mesh.edges[e][1]));
    put_le(buf, static_cast<std::uint32_t>(mesh.edge_solid[e]));
    drain(buf, out);
  }
  drain(buf, out, true);
}

void write_obj(const MedialMesh& mesh, std::ostream& out) {
  check_mesh(mesh);
  std::string buf;
  buf += "# cadmedial medial axis: " + std::to_string(mesh.num_vertices()) + " vertices, " +
         std::to_string(mesh.num_faces()) + " faces, " + std::to_string(mesh.num_edges()) + " edges\n";
  buf += "# each 'v x y z' is followed by 'vr r': the medial radius of that vertex (not standard OBJ; readers skip it)\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    buf += "v ";
    put_double(buf, mesh.vertices[v][0]);
    buf += ' ';
    put_double(buf, mesh.vertices[v][1]);
    buf += ' ';
    put_double(buf, mesh.vertices[v][2]);
    buf += "\nvr ";
    put_double(buf, mesh.radius[v]);
    buf += '\n';
    drain(buf, out);
  }
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    buf += 'f';
    for (int i = 0; i < mesh.face_size(f); ++i) {
      buf += ' ';
      put_int(buf, mesh.face(f)[i] + 1LL);
    }
    buf += '\n';
    drain(buf, out);
  }
  // The 1-D edges as polylines of one segment each.
  for (const auto& e : mesh.edges) {
    buf += "l ";
    put_int(buf, e[0] + 1LL);
    buf += ' ';
    put_int(buf, e[1] + 1LL);
    buf += '\n';
    drain(buf, out);
  }
  drain(buf, out, true);
}

void write_ma(const MedialMesh& mesh, std::ostream& out) {
  check_mesh(mesh);
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const int* p = mesh.face(f);
    for (int i = 1; i + 1 < mesh.face_size(f); ++i) triangles.push_back({p[0], p[i], p[i + 1]});
  }
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // Then the 1-D edges in the mesh's order (so that they read back in it), each once, and none
  // that is already a triangle's side: ne counts every segment of the axis exactly once.
  const std::size_t sides = edges.size();
  std::set<std::pair<int, int>> bare;
  for (const auto& e : mesh.edges) {
    const std::pair<int, int> key(std::min(e[0], e[1]), std::max(e[0], e[1]));
    if (std::binary_search(edges.begin(), edges.begin() + sides, key) || !bare.insert(key).second) continue;
    edges.emplace_back(e[0], e[1]);
  }

  std::string buf;
  buf += std::to_string(mesh.num_vertices()) + " " + std::to_string(edges.size()) + " " +
         std::to_string(triangles.size()) + "\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    buf += "v ";
    for (double c : mesh.vertices[v]) {
      put_double(buf, c);
      buf += ' ';
    }
    put_double(buf, mesh.radius[v]);
    buf += '\n';
    drain(buf, out);
  }
  for (const auto& [a, b] : edges) {
    buf += "e ";
    put_int(buf, a);
    buf += ' ';
    put_int(buf, b);
    buf += '\n';
    drain(buf, out);
  }
  for (const auto& t : triangles) {
    buf += "f ";
    put_int(buf, t[0]);
    buf += ' ';
    put_int(buf, t[1]);
    buf += ' ';
    put_int(buf, t[2]);
    buf += '\n';
    drain(buf, out);
  }
  drain(buf, out, true);
}

void write_medial_mesh(const MedialMesh& mesh, const std::string& path) {
  const Format format = format_of(path);  // refuse before touching the disk
  check_mesh(mesh);

  write_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case Format::Ply: write_ply(mesh, out); break;
      case Format::Obj: write_obj(mesh, out); break;
      case Format::Ma: write_ma(mesh, out); break;
    }
  });
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  // The temporary file lives beside the target, so that rename() stays on one file system and
  // is atomic: readers see the old file or the complete new one, never a partial one.
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  const fs::path temp = target.parent_path() /
                        ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter++));
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw InvalidInput(path + ": cannot write: " + why);
  };
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) fail(std::strerror(errno));
    try {
      write(out);
    } catch (const std::exception& e) {
      out.close();
      fail(e.what());
    }
    out.flush();
    if (!out) fail("write failed (disk full?)");
    out.close();
    if (out.fail()) fail("closing the file failed (disk full?)");
  }
  std::error_code ec;
  if (fs::is_directory(target, ec)) fail("is a directory");
  if (std::rename(temp.c_str(), target.c_str()) != 0) fail(std::strerror(errno));
}

// ---- readers --------------------------------------------------------------------------------

namespace {

[[noreturn]] void bad(const std::string& path, const std::string& why) {
  throw InvalidInput(path + ": " + why);
}

double parse_double(const std::string& path, std::size_t line, const std::string& token) {
  double x = 0;
  auto r = std::from_chars(token.data(), token.data() + token.size(), x);
  if (r.ec != std::errc() || r.ptr != token.data() + token.size())
    bad(path, "line " + std::to_string(line) + ": '" + token + "' is not a number");
  return x;
}

long long parse_int(const std::string& path, std::size_t line, const std::string& token) {
  long long x = 0;
  auto r = std::from_chars(token.data(), token.data() + token.size(), x);
  if (r.ec != std::errc() || r.ptr != token.data() + token.size())
    bad(path, "line " + std::to_string(line) + ": '" + token + "' is not an integer");
  return x;
}

int checked_index(const std::string& path, std::size_t line, long long i, std::size_t nv) {
  if (i < 0 || static_cast<std::size_t>(i) >= nv)
    bad(path, "line " + std::to_string(line) + ": vertex index " + std::to_string(i) + " out of range");
  return static_cast<int>(i);
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> tokens;
  std::istringstream in(s);
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

// ---- PLY: the binary little-endian PLY this file writes, and any with the same elements ------

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

PlyType ply_type(const std::string& path, const std::string& name) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::I8},    {"int8", PlyType::I8},     {"uchar", PlyType::U8},   {"uint8", PlyType::U8},
      {"short", PlyType::I16},  {"int16", PlyType::I16},   {"ushort", PlyType::U16}, {"uint16", PlyType::U16},
      {"int", PlyType::I32},    {"int32", PlyType::I32},   {"uint", PlyType::U32},   {"uint32", PlyType::U32},
      {"float", PlyType::F32},  {"float32", PlyType::F32}, {"double", PlyType::F64}, {"float64", PlyType::F64}};
  for (const auto& [n, t] : names)
    if (name == n) return t;
  bad(path, "PLY: unknown property type '" + name + "'");
}

struct PlyProperty {
  std::string name;
  PlyType type;
  bool list = false;
  PlyType count_type = PlyType::U8;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

double read_ply_value(std::istream& in, PlyType type, const std::string& path) {
  static const int size_of[] = {1, 1, 2, 2, 4, 4, 4, 8};
  unsigned char b[8];
  const int n = size_of[static_cast<int>(type)];
  if (!in.read(reinterpret_cast<char*>(b), n)) bad(path, "PLY: the file ends early");
  std::uint64_t bits = 0;
  for (int i = 0; i < n; ++i) bits |= static_cast<std::uint64_t>(b[i]) << (8 * i);
  switch (type) {
    case PlyType::I8: return static_cast<std::int8_t>(bits);
    case PlyType::U8: return static_cast<std::uint8_t>(bits);
    case PlyType::I16: return static_cast<std::int16_t>(bits);
    case PlyType::U16: return static_cast<std::uint16_t>(bits);
    case PlyType::I32: return static_cast<std::int32_t>(bits);
    case PlyType::U32: return static_cast<std::uint32_t>(bits);
    case PlyType::F32: {
      std::uint32_t b32 = static_cast<std::uint32_t>(bits);
      float f;
      std::memcpy(&f, &b32, 4);
      return f;
    }
    case PlyType::F64: {
      double d;
      std::memcpy(&d, &bits, 8);
      return d;
    }
  }
  return 0;
}

MedialMesh read_ply(const std::string& path, std::istream& in) {
  std::string line;
  std::getline(in, line);
  if (line != "ply") bad(path, "not a PLY file (no 'ply' on the first line)");
  std::vector<PlyElement> elements;
  bool format_ok = false;
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    const auto t = split(line);
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() < 2 || t[1] != "binary_little_endian")
        bad(path, "PLY: only binary_little_endian is read, not '" + (t.size() > 1 ? t[1] : "") + "'");
      format_ok = true;
    } else if (t[0] == "element" && t.size() == 3) {
      elements.push_back({t[1], static_cast<std::size_t>(parse_int(path, n, t[2])), {}});
    } else if (t[0] == "property" && !elements.empty()) {
      if (t.size() == 5 && t[1] == "list")
        elements.back().properties.push_back({t[4], ply_type(path, t[3]), true, ply_type(path, t[2])});
      else if (t.size() == 3)
        elements.back().properties.push_back({t[2], ply_type(path, t[1])});
      else
        bad(path, "line " + std::to_string(n) + ": bad property line");
    } else {
      bad(path, "line " + std::to_string(n) + ": unexpected header line '" + line + "'");
    }
  }
  if (!format_ok) bad(path, "PLY: no format line");

  MedialMesh mesh;
  for (const PlyElement& e : elements) {
    if (e.name == "vertex") {
      mesh.vertices.resize(e.count);
      mesh.radius.assign(e.count, 0.0);
      for (std::size_t v = 0; v < e.count; ++v)
        for (const PlyProperty& p : e.properties) {
          if (p.list) bad(path, "PLY: list property '" + p.name + "' on vertices");
          const double x = read_ply_value(in, p.type, path);
          if (p.name == "x") mesh.vertices[v][0] = x;
          else if (p.name == "y") mesh.vertices[v][1] = x;
          else if (p.name == "z") mesh.vertices[v][2] = x;
          else if (p.name == "radius") mesh.radius[v] = x;
        }
    } else if (e.name == "face") {
      std::vector<int> polygon;
      for (std::size_t f = 0; f < e.count; ++f) {
        FaceKind kind = FaceKind::Voronoi;
        int solid = 0;
        polygon.clear();
        for (const PlyProperty& p : e.properties) {
          if (p.list) {
            const double n = read_ply_value(in, p.count_type, path);
            if (n < 0) bad(path, "PLY: face " + std::to_string(f) + " has a negative vertex count");
            std::vector<int> values(static_cast<std::size_t>(n));
            for (int& v : values) v = static_cast<int>(read_ply_value(in, p.type, path));
            if (p.name == "vertex_indices" || p.name == "vertex_index") polygon = values;
          } else {
            const double x = read_ply_value(in, p.type, path);
            if (p.name == "kind") {
              if (x < 0 || x > 2) bad(path, "PLY: face " + std::to_string(f) + " has unknown kind " + std::to_string(x));
              kind = static_cast<FaceKind>(static_cast<int>(x));
            } else if (p.name == "solid") {
              solid = static_cast<int>(x);
            }
          }
        }
        for (int v : polygon)
          if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size())
            bad(path, "PLY: face " + std::to_string(f) + " has vertex index " + std::to_string(v) + " out of range");
        mesh.add_face(polygon, kind, solid);
      }
    } else if (e.name == "edge") {
      mesh.edges.reserve(e.count);
      for (std::size_t k = 0; k < e.count; ++k) {
        long long ends[2] = {-1, -1};
        int solid = 0;
        for (const PlyProperty& p : e.properties) {
          if (p.list) bad(path, "PLY: list property '" + p.name + "' on edges");
          const double x = read_ply_value(in, p.type, path);
          if (p.name == "vertex1") ends[0] = static_cast<long long>(x);
          else if (p.name == "vertex2") ends[1] = static_cast<long long>(x);
          else if (p.name == "solid") solid = static_cast<int>(x);
        }
        for (long long v : ends)
          if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size())
            bad(path, "PLY: edge " + std::to_string(k) + " has vertex index " + std::to_string(v) +
                          " out of range (or no vertex1 / vertex2)");
        mesh.edges.push_back({static_cast<int>(ends[0]), static_cast<int>(ends[1])});
        mesh.edge_solid.push_back(solid);
      }
    } else {
      bad(path, "PLY: unexpected element '" + e.name + "'");
    }
  }
  return mesh;
}

MedialMesh read_obj(const std::string& path, std::istream& in) {
  MedialMesh mesh;
  std::string line;
  std::vector<std::vector<int>> faces;
  std::vector<std::size_t> face_line;
  std::vector<std::array<long long, 2>> segments;
  std::vector<std::size_t> segment_line;
  // "f 1/2/3" or "l 1/2": only the vertex index matters; negative indices count from the end so far.
  auto vertex_index = [&](std::size_t n, const std::string& token) {
    const long long idx = parse_int(path, n, token.substr(0, token.find('/')));
    return idx < 0 ? static_cast<long long>(mesh.vertices.size()) + idx : idx - 1;
  };
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const auto t = split(line);
    if (t.empty() || t[0][0] == '#') continue;
    if (t[0] == "v") {
      if (t.size() < 4) bad(path, "line " + std::to_string(n) + ": 'v' needs three coordinates");
      mesh.vertices.push_back({parse_double(path, n, t[1]), parse_double(path, n, t[2]), parse_double(path, n, t[3])});
      mesh.radius.push_back(0.0);
    } else if (t[0] == "vr") {
      if (t.size() != 2 || mesh.vertices.empty()) bad(path, "line " + std::to_string(n) + ": 'vr' must follow a 'v'");
      mesh.radius.back() = parse_double(path, n, t[1]);
    } else if (t[0] == "f") {
      std::vector<int> polygon;
      for (std::size_t i = 1; i < t.size(); ++i) polygon.push_back(static_cast<int>(vertex_index(n, t[i])));
      faces.push_back(std::move(polygon));
      face_line.push_back(n);
    } else if (t[0] == "l") {
      // A polyline: one edge per consecutive pair (this file's writer puts one segment per line).
      if (t.size() < 3) bad(path, "line " + std::to_string(n) + ": 'l' needs at least two indices");
      for (std::size_t i = 1; i + 1 < t.size(); ++i) {
        segments.push_back({vertex_index(n, t[i]), vertex_index(n, t[i + 1])});
        segment_line.push_back(n);
      }
    }
  }
  // Without vr lines (an OBJ from another tool) every radius stays 0.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int& v : faces[f]) v = checked_index(path, face_line[f], v, mesh.vertices.size());
    mesh.add_face(faces[f], FaceKind::Voronoi, 0);
  }
  for (std::size_t e = 0; e < segments.size(); ++e) {
    const std::size_t nv = mesh.vertices.size();
    mesh.edges.push_back({checked_index(path, segment_line[e], segments[e][0], nv),
                          checked_index(path, segment_line[e], segments[e][1], nv)});
    mesh.edge_solid.push_back(0);
  }
  return mesh;
}

MedialMesh read_ma(const std::string& path, std::istream& in) {
  std::string line;
  std::size_t n = 1;
  while (std::getline(in, line) && split(line).empty()) ++n;
  const auto head = split(line);
  if (head.size() != 3) bad(path, "line " + std::to_string(n) + ": .ma must start with 'nv ne nf'");
  const long long nv = parse_int(path, n, head[0]), ne = parse_int(path, n, head[1]), nf = parse_int(path, n, head[2]);
  if (nv < 0 || ne < 0 || nf < 0) bad(path, "line " + std::to_string(n) + ": negative count");
  MedialMesh mesh;
  long long seen_e = 0;
  std::vector<std::array<int, 2>> e_lines;
  while (std::getline(in, line)) {
    ++n;
    const auto t = split(line);
    if (t.empty() || t[0][0] == '#') continue;
    if (t[0] == "v") {
      if (t.size() != 5) bad(path, "line " + std::to_string(n) + ": 'v' needs x y z r");
      mesh.vertices.push_back({parse_double(path, n, t[1]), parse_double(path, n, t[2]), parse_double(path, n, t[3])});
      mesh.radius.push_back(parse_double(path, n, t[4]));
    } else if (t[0] == "e") {
      if (t.size() != 3) bad(path, "line " + std::to_string(n) + ": 'e' needs two indices");
      std::array<int, 2> e;
      for (int i = 0; i < 2; ++i) e[i] = checked_index(path, n, parse_int(path, n, t[i + 1]), static_cast<std::size_t>(nv));
      e_lines.push_back(e);
      ++seen_e;
    } else if (t[0] == "f") {
      if (t.size() != 4) bad(path, "line " + std::to_string(n) + ": 'f' needs three indices");
      std::vector<int> tri;
      for (int i = 1; i <= 3; ++i) tri.push_back(checked_index(path, n, parse_int(path, n, t[i]), static_cast<std::size_t>(nv)));
      mesh.add_face(tri, FaceKind::Voronoi, 0);
    } else {
      bad(path, "line " + std::to_string(n) + ": unknown record '" + t[0] + "'");
    }
  }
  if (static_cast<long long>(mesh.vertices.size()) != nv || seen_e != ne ||
      static_cast<long long>(mesh.num_faces()) != nf)
    bad(path, "the header says " + std::to_string(nv) + " " + std::to_string(ne) + " " + std::to_string(nf) +
                  " but the file holds " + std::to_string(mesh.vertices.size()) + " " + std::to_string(seen_e) + " " +
                  std::to_string(mesh.num_faces()));
  // The format lists every edge, triangle sides included: those that bound no triangle are the
  // axis's 1-D edges.
  std::set<std::pair<int, int>> sides;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (int i = 0; i < 3; ++i) {
      const int a = mesh.face(f)[i], b = mesh.face(f)[(i + 1) % 3];
      sides.emplace(std::min(a, b), std::max(a, b));
    }
  for (const auto& e : e_lines)
    if (!sides.count({std::min(e[0], e[1]), std::max(e[0], e[1])})) {
      mesh.edges.push_back(e);
      mesh.edge_solid.push_back(0);
    }
  return mesh;
}

}  // namespace

MedialMesh read_medial_mesh(const std::string& path) {
  const Format format = format_of(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path, std::string("cannot open for reading: ") + std::strerror(errno));
  try {
    switch (format) {
      case Format::Ply: return read_ply(path, in);
      case Format::Obj: return read_obj(path, in);
      case Format::Ma: return read_ma(path, in);
    }
  } catch (const std::length_error&) {
    bad(path, "a count in the file is absurdly large");
  } catch (const std::bad_alloc&) {
    bad(path, "a count in the file is absurdly large (out of memory)");
  }
  bad(path, "unknown format");
}

}  // namespace cadmedial
