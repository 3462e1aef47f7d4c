#include "core/io/write_medial_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "core/errors.h"
#include "io/io_test_files.h"

namespace cadmedial {
namespace {

using test::TempDir;

// Awkward doubles (no short decimal form, tiny, huge, negative) so that text precision shows.
// Three polygons, and a path of two 1-D edges 4 -> 5 -> 6 hanging off them (no face side).
MedialMesh sample_mesh() {
  MedialMesh m;
  m.vertices = {{0.1, 1.0 / 3.0, M_PI},
                {-2.5e17, 1e-300, 2.0 / 7.0},
                {1.0, 0.0, -0.0},
                {std::sqrt(2.0), -1e-9, 123456.789012345678},
                {5e-324, 0.7, 0.30000000000000004},
                {-1.0 / 3.0, 2.0, 1e100},
                {7.0, -0.1, 0.2}};
  m.radius = {0.5, 1.0 / 7.0, 1e-12, 3.0e5, std::exp(1.0), 0.1, 0.0};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  m.add_face({0, 1, 3, 2}, FaceKind::Edge, 1);
  m.add_face({4, 3, 2, 1, 0}, FaceKind::Corner, 7);
  m.edges = {{5, 4}, {5, 6}};
  m.edge_solid = {7, 3};
  return m;
}

// A closed loop of four 1-D edges and nothing else (a torus's core circle, coarsely).
MedialMesh edges_only_mesh() {
  MedialMesh m;
  m.vertices = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  m.radius = {0.25, 0.25, 0.25, 0.25};
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  m.edge_solid = {2, 2, 2, 2};
  return m;
}

std::size_t count_lines_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

void expect_close(double expected, double actual, const char* what) {
  EXPECT_LE(std::abs(expected - actual), 1e-15 * std::abs(expected)) << what << ": " << expected << " vs " << actual;
}

std::vector<std::vector<int>> polygons(const MedialMesh& m) {
  std::vector<std::vector<int>> out;
  for (std::size_t f = 0; f < m.num_faces(); ++f) out.emplace_back(m.face(f), m.face(f) + m.face_size(f));
  return out;
}

TEST(WritePly, RoundTripIsExact) {
  TempDir dir;
  const MedialMesh m = sample_mesh();
  write_medial_mesh(m, dir.file("m.ply"));
  const MedialMesh r = read_medial_mesh(dir.file("m.ply"));
  EXPECT_EQ(r.vertices, m.vertices);
  EXPECT_EQ(r.radius, m.radius);
  EXPECT_EQ(polygons(r), polygons(m));
  EXPECT_EQ(r.kind, m.kind);
  EXPECT_EQ(r.solid, m.solid);
  EXPECT_EQ(r.edges, m.edges);
  EXPECT_EQ(r.edge_solid, m.edge_solid);
}

TEST(WritePly, MeshOfEdgesOnlyRoundTrips) {
  TempDir dir;
  const MedialMesh m = edges_only_mesh();
  write_medial_mesh(m, dir.file("m.ply"));
  const MedialMesh r = read_medial_mesh(dir.file("m.ply"));
  EXPECT_EQ(r.vertices, m.vertices);
  EXPECT_EQ(r.radius, m.radius);
  EXPECT_EQ(r.num_faces(), 0u);
  EXPECT_EQ(r.edges, m.edges);
  EXPECT_EQ(r.edge_solid, m.edge_solid);
}

// Files written before the edge element existed have none: they read as a mesh without edges.
TEST(WritePly, FileWithoutEdgeElementReadsWithNoEdges) {
  TempDir dir;
  MedialMesh m = sample_mesh();
  m.edges.clear();
  m.edge_solid.clear();
  std::ostringstream out;
  write_ply(m, out);
  std::string text = out.str();
  const std::string edge_header = "element edge 0\nproperty int vertex1\nproperty int vertex2\nproperty int solid\n";
  const std::size_t at = text.find(edge_header);
  ASSERT_NE(at, std::string::npos);
  text.erase(at, edge_header.size());
  test::write_file(dir.file("old.ply"), text);
  const MedialMesh r = read_medial_mesh(dir.file("old.ply"));
  EXPECT_EQ(r.vertices, m.vertices);
  EXPECT_EQ(polygons(r), polygons(m));
  EXPECT_TRUE(r.edges.empty());
  EXPECT_TRUE(r.edge_solid.empty());
}

TEST(WritePly, EdgeWithVertexOutOfRangeIsRefusedOnReading) {
  TempDir dir;
  MedialMesh m = edges_only_mesh();
  std::ostringstream out;
  write_ply(m, out);
  std::string text = out.str();
  // The last edge's vertex2 is the 8 bytes before its solid: make it vertex 4 of 4.
  text[text.size() - 8] = 4;
  test::write_file(dir.file("bad.ply"), text);
  EXPECT_THROW(read_medial_mesh(dir.file("bad.ply")), InvalidInput);
}

TEST(WritePly, HeaderDeclaresTheContractedProperties) {
  std::ostringstream out;
  write_ply(sample_mesh(), out);
  const std::string text = out.str();
  const std::string header = text.substr(0, text.find("end_header\n"));
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex 7\nproperty double x\nproperty double y\nproperty double z\nproperty double radius\n"),
            std::string::npos);
  EXPECT_NE(header.find("element face 3\nproperty list uchar int vertex_indices\nproperty uchar kind\nproperty int solid\n"
                        "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty int solid\n"),
            std::string::npos);
  // Body size: 7 vertices * 4 doubles + faces (1 count + 4n index + 1 kind + 4 solid bytes)
  // + edges (3 ints).
  const std::size_t body = text.size() - header.size() - std::string("end_header\n").size();
  EXPECT_EQ(body, 7u * 32u + (1 + 12 + 5) + (1 + 16 + 5) + (1 + 20 + 5) + 2u * 12u);
}

// A fixed schema: a script may read the edge element of any file, even one without edges.
TEST(WritePly, EdgeElementIsWrittenEvenWhenEmpty) {
  MedialMesh m = sample_mesh();
  m.edges.clear();
  m.edge_solid.clear();
  std::ostringstream out;
  write_ply(m, out);
  EXPECT_NE(out.str().find("element edge 0\nproperty int vertex1\nproperty int vertex2\nproperty int solid\nend_header\n"),
            std::string::npos);
}

TEST(WritePly, PolygonWithMoreThan255VerticesRoundTrips) {
  TempDir dir;
  MedialMesh m;
  std::vector<int> big(300);
  for (int i = 0; i < 300; ++i) {
    m.vertices.push_back({std::cos(i * 2 * M_PI / 300), std::sin(i * 2 * M_PI / 300), 0.0});
    m.radius.push_back(i);
    big[i] = i;
  }
  m.add_face(big, FaceKind::Voronoi, 0);
  write_medial_mesh(m, dir.file("big.ply"));
  const MedialMesh r = read_medial_mesh(dir.file("big.ply"));
  ASSERT_EQ(r.num_faces(), 1u);
  EXPECT_EQ(r.face_size(0), 300);
  EXPECT_EQ(polygons(r), polygons(m));
}

TEST(WriteObj, RoundTripKeepsPositionsRadiusAndPolygons) {
  TempDir dir;
  const MedialMesh m = sample_mesh();
  write_medial_mesh(m, dir.file("m.obj"));
  const MedialMesh r = read_medial_mesh(dir.file("m.obj"));
  ASSERT_EQ(r.num_vertices(), m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) expect_close(m.vertices[v][k], r.vertices[v][k], "position");
    expect_close(m.radius[v], r.radius[v], "radius");
  }
  EXPECT_EQ(polygons(r), polygons(m));
  EXPECT_EQ(r.edges, m.edges);
  // OBJ has no place for kind and solid: documented as Voronoi / 0.
  EXPECT_EQ(r.kind, std::vector<FaceKind>(3, FaceKind::Voronoi));
  EXPECT_EQ(r.solid, std::vector<int>(3, 0));
  EXPECT_EQ(r.edge_solid, std::vector<int>(2, 0));
}

TEST(WriteObj, MeshOfEdgesOnlyRoundTrips) {
  TempDir dir;
  const MedialMesh m = edges_only_mesh();
  write_medial_mesh(m, dir.file("m.obj"));
  const MedialMesh r = read_medial_mesh(dir.file("m.obj"));
  EXPECT_EQ(r.vertices, m.vertices);
  EXPECT_EQ(r.radius, m.radius);
  EXPECT_EQ(r.num_faces(), 0u);
  EXPECT_EQ(r.edges, m.edges);
}

TEST(WriteObj, EdgesAreOneBasedLines) {
  std::ostringstream out;
  write_obj(edges_only_mesh(), out);
  EXPECT_NE(out.str().find("l 1 2\nl 2 3\nl 3 4\nl 4 1\n"), std::string::npos) << out.str();
  EXPECT_EQ(count_lines_starting(out.str(), "l "), 4u);
}

// Other tools write polylines: `l a b c` is the two edges a-b and b-c.
TEST(ReadObj, PolylineGivesOneEdgePerSegment) {
  TempDir dir;
  test::write_file(dir.file("p.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 -1\n");
  const MedialMesh r = read_medial_mesh(dir.file("p.obj"));
  const std::vector<std::array<int, 2>> expected{{0, 1}, {1, 2}};
  EXPECT_EQ(r.edges, expected);
  EXPECT_EQ(r.edge_solid, std::vector<int>(2, 0));
}

TEST(WriteObj, FacesAreOneBasedAndRadiusFollowsEachVertex) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.radius = {0.25, 0.5, 0.75};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  std::ostringstream out;
  write_obj(m, out);
  EXPECT_NE(out.str().find("v 0 0 0\nvr 0.25\nv 1 0 0\nvr 0.5\nv 0 1 0\nvr 0.75\nf 1 2 3\n"), std::string::npos)
      << out.str();
}

TEST(WriteMa, OneQuadGivesTwoTrianglesAndFiveEdges) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.radius = {1, 2, 3, 4};
  m.add_face({0, 1, 2, 3}, FaceKind::Voronoi, 0);
  std::ostringstream out;
  write_ma(m, out);
  std::istringstream in(out.str());
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "4 5 2");
  int v = 0, e = 0, f = 0;
  for (std::string line; std::getline(in, line);) {
    v += line.rfind("v ", 0) == 0;
    e += line.rfind("e ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, 4);
  EXPECT_EQ(e, 5);
  EXPECT_EQ(f, 2);
  EXPECT_NE(out.str().find("f 0 1 2\nf 0 2 3\n"), std::string::npos);
}

// A 1-D edge is one more `e` line; one that is also a triangle's side is not written twice.
TEST(WriteMa, OneDimensionalEdgesCountOnceInNe) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 2, 2}};
  m.radius = {1, 2, 3, 4, 5};
  m.add_face({0, 1, 2, 3}, FaceKind::Voronoi, 0);  // sides 01 12 23 30, diagonal 02
  m.edges = {{4, 2}, {1, 0}, {2, 4}};  // a new segment, a side of the quad, the new one reversed
  m.edge_solid = {0, 0, 0};
  std::ostringstream out;
  write_ma(m, out);
  const std::string text = out.str();
  EXPECT_EQ(text.substr(0, text.find('\n')), "5 6 2");
  EXPECT_EQ(count_lines_starting(text, "e "), 6u);
  EXPECT_NE(text.find("e 4 2\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("e 2 4\n"), std::string::npos) << text;
}

TEST(WriteMa, RoundTripKeepsOneDimensionalEdges) {
  TempDir dir;
  const MedialMesh m = sample_mesh();
  write_medial_mesh(m, dir.file("m.ma"));
  const MedialMesh r = read_medial_mesh(dir.file("m.ma"));
  EXPECT_EQ(r.edges, m.edges);  // in order and orientation: no edge of sample_mesh is a face side
  EXPECT_EQ(r.edge_solid, std::vector<int>(2, 0));
}

TEST(WriteMa, MeshOfEdgesOnlyRoundTrips) {
  TempDir dir;
  const MedialMesh m = edges_only_mesh();
  write_medial_mesh(m, dir.file("m.ma"));
  EXPECT_EQ(test::read_file(dir.file("m.ma")).substr(0, 6), "4 4 0\n");
  const MedialMesh r = read_medial_mesh(dir.file("m.ma"));
  EXPECT_EQ(r.vertices, m.vertices);
  EXPECT_EQ(r.radius, m.radius);
  EXPECT_EQ(r.num_faces(), 0u);
  EXPECT_EQ(r.edges, m.edges);
}

TEST(WriteMa, RoundTripGivesTheFanTriangles) {
  TempDir dir;
  const MedialMesh m = sample_mesh();  // a triangle, a quad and a pentagon: 1 + 2 + 3 triangles
  write_medial_mesh(m, dir.file("m.ma"));
  const MedialMesh r = read_medial_mesh(dir.file("m.ma"));
  ASSERT_EQ(r.num_vertices(), m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) expect_close(m.vertices[v][k], r.vertices[v][k], "position");
    expect_close(m.radius[v], r.radius[v], "radius");
  }
  const std::vector<std::vector<int>> expected{{0, 1, 2}, {0, 1, 3}, {0, 3, 2}, {4, 3, 2}, {4, 2, 1}, {4, 1, 0}};
  EXPECT_EQ(polygons(r), expected);
  EXPECT_EQ(r.solid, std::vector<int>(6, 0));
}

TEST(WriteMedialMesh, UnknownExtensionIsRefusedBeforeWriting) {
  TempDir dir;
  try {
    write_medial_mesh(sample_mesh(), dir.file("m.stl"));
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("unknown output type '.stl'"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteMedialMesh, MissingDirectoryIsRefusedNamingThePath) {
  TempDir dir;
  const std::string path = dir.file("no/such/dir/m.ply");
  try {
    write_medial_mesh(sample_mesh(), path);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot write", 0), 0u) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(WriteMedialMesh, DirectoryAsTargetIsRefusedAndLeavesNoTempFile) {
  TempDir dir;
  std::filesystem::create_directory(dir.file("out.ply"));
  EXPECT_THROW(write_medial_mesh(sample_mesh(), dir.file("out.ply")), InvalidInput);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.ply"});
  EXPECT_TRUE(std::filesystem::is_directory(dir.file("out.ply")));
}

TEST(WriteMedialMesh, ReplacesAnExistingFileAndLeavesOnlyIt) {
  TempDir dir;
  test::write_file(dir.file("m.obj"), "old content\n");
  write_medial_mesh(sample_mesh(), dir.file("m.obj"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"m.obj"});
  EXPECT_EQ(read_medial_mesh(dir.file("m.obj")).num_faces(), 3u);
}

TEST(WriteMedialMesh, InconsistentMeshIsRefusedAndNothingWritten) {
  TempDir dir;
  MedialMesh m = sample_mesh();
  m.radius.pop_back();
  EXPECT_THROW(write_medial_mesh(m, dir.file("m.ply")), InvalidInput);
  m = sample_mesh();
  m.face_vertices[0] = 99;  // out of range
  EXPECT_THROW(write_medial_mesh(m, dir.file("m.ply")), InvalidInput);
  m = sample_mesh();
  m.edges[1][1] = 7;  // one past the last vertex
  EXPECT_THROW(write_medial_mesh(m, dir.file("m.ply")), InvalidInput);
  m = sample_mesh();
  m.edge_solid.pop_back();
  EXPECT_THROW(write_medial_mesh(m, dir.file("m.ply")), InvalidInput);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ReadMedialMesh, TruncatedPlyIsRefused) {
  TempDir dir;
  write_medial_mesh(sample_mesh(), dir.file("m.ply"));
  const std::string text = test::read_file(dir.file("m.ply"));
  test::write_file(dir.file("cut.ply"), text.substr(0, text.size() - 7));
  EXPECT_THROW(read_medial_mesh(dir.file("cut.ply")), InvalidInput);
}

TEST(ReadMedialMesh, MaWithWrongCountsIsRefused) {
  TempDir dir;
  test::write_file(dir.file("bad.ma"), "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nf 0 1 2\n");
  EXPECT_THROW(read_medial_mesh(dir.file("bad.ma")), InvalidInput);
}

TEST(ReadMedialMesh, ObjWithIndexOutOfRangeIsRefused) {
  TempDir dir;
  test::write_file(dir.file("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  EXPECT_THROW(read_medial_mesh(dir.file("bad.obj")), InvalidInput);
}

}  // namespace
}  // namespace cadmedial
