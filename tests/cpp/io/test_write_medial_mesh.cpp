#include "core/io/write_medial_mesh.h"

#include <gtest/gtest.h>

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
MedialMesh sample_mesh() {
  MedialMesh m;
  m.vertices = {{0.1, 1.0 / 3.0, M_PI},
                {-2.5e17, 1e-300, 2.0 / 7.0},
                {1.0, 0.0, -0.0},
                {std::sqrt(2.0), -1e-9, 123456.789012345678},
                {5e-324, 0.7, 0.30000000000000004}};
  m.radius = {0.5, 1.0 / 7.0, 1e-12, 3.0e5, std::exp(1.0)};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  m.add_face({0, 1, 3, 2}, FaceKind::Edge, 1);
  m.add_face({4, 3, 2, 1, 0}, FaceKind::Corner, 7);
  return m;
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
}

TEST(WritePly, HeaderDeclaresTheContractedProperties) {
  std::ostringstream out;
  write_ply(sample_mesh(), out);
  const std::string text = out.str();
  const std::string header = text.substr(0, text.find("end_header\n"));
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex 5\nproperty double x\nproperty double y\nproperty double z\nproperty double radius\n"),
            std::string::npos);
  EXPECT_NE(header.find("element face 3\nproperty list uchar int vertex_indices\nproperty uchar kind\nproperty int solid\n"),
            std::string::npos);
  // Body size: 5 vertices * 4 doubles + faces (1 count + 4n index + 1 kind + 4 solid bytes).
  const std::size_t body = text.size() - header.size() - std::string("end_header\n").size();
  EXPECT_EQ(body, 5u * 32u + (1 + 12 + 5) + (1 + 16 + 5) + (1 + 20 + 5));
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
  // OBJ has no place for kind and solid: documented as Voronoi / 0.
  EXPECT_EQ(r.kind, std::vector<FaceKind>(3, FaceKind::Voronoi));
  EXPECT_EQ(r.solid, std::vector<int>(3, 0));
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
