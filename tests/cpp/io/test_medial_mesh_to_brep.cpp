#include "core/io/medial_mesh_to_brep.h"

#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Iterator.hxx>

#include <sstream>

#include "core/errors.h"

namespace cadmedial {
namespace {

TopoDS_Shape parse(const std::string& text) {
  std::istringstream in(text);
  TopoDS_Shape shape;
  BRepTools::Read(shape, in, BRep_Builder());
  return shape;
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(s, type, map);
  return map.Extent();
}

double area(const TopoDS_Shape& s) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(s, props);
  return props.Mass();
}

TEST(MedialMeshToBrep, OneFacePerPolygonWithTheirArea) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, 1}};
  m.radius.assign(6, 1.0);
  m.add_face({0, 1, 2, 3}, FaceKind::Voronoi, 0);  // unit square, area 1
  m.add_face({0, 3, 5, 4}, FaceKind::Edge, 0);     // unit square in x = 0, area 1
  m.add_face({1, 2, 5}, FaceKind::Corner, 0);      // right triangle with legs 1 and sqrt(2): area sqrt(2)/2
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  ASSERT_FALSE(shape.IsNull());
  EXPECT_EQ(shape.ShapeType(), TopAbs_COMPOUND);
  EXPECT_EQ(count(shape, TopAbs_FACE), 3);
  EXPECT_NEAR(area(shape), 2.0 + std::sqrt(2.0) / 2.0, 1e-9);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

TEST(MedialMeshToBrep, FacesShareVerticesAndEdges) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.radius.assign(4, 1.0);
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  m.add_face({0, 2, 3}, FaceKind::Voronoi, 0);  // shares the edge {0, 2}, reversed
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(count(shape, TopAbs_FACE), 2);
  EXPECT_EQ(count(shape, TopAbs_EDGE), 5);
  EXPECT_EQ(count(shape, TopAbs_VERTEX), 4);
  EXPECT_NEAR(area(shape), 1.0, 1e-12);
}

TEST(MedialMeshToBrep, DegeneratePolygonsAreSkipped) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 0}};
  m.radius.assign(5, 1.0);
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);     // collinear: zero area
  m.add_face({0, 1, 1}, FaceKind::Voronoi, 0);     // repeated vertex: two distinct points
  m.add_face({0, 1, 4}, FaceKind::Voronoi, 0);     // vertex 4 sits on vertex 0
  m.add_face({0, 1, 3, 3}, FaceKind::Voronoi, 0);  // repeated vertex but still a triangle of area 1/2
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(count(shape, TopAbs_FACE), 1);
  EXPECT_NEAR(area(shape), 0.5, 1e-12);
}

TEST(MedialMeshToBrep, NonPlanarPolygonBecomesItsFanTriangles) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}};
  m.radius.assign(4, 1.0);
  m.add_face({0, 1, 2, 3}, FaceKind::Voronoi, 0);
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(count(shape, TopAbs_FACE), 2);
  // Triangles (0,1,2) and (0,2,3): each has area |(1,0,0) x (1,1,0.5)| / 2 = sqrt(1.25)/2 or the like.
  const gp_Vec a(1, 0, 0), b(1, 1, 0.5), c(0, 1, 0);
  EXPECT_NEAR(area(shape), a.Crossed(b).Magnitude() / 2 + b.Crossed(c).Magnitude() / 2, 1e-12);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

TEST(MedialMeshToBrep, GridSharesEveryVertexAndEdge) {
  const int n = 60;  // n x n quads
  MedialMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.vertices.push_back({double(i), double(j), 0.1 * i});
      m.radius.push_back(1.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      m.add_face({v, v + 1, v + n + 2, v + n + 1}, FaceKind::Voronoi, 0);
    }
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(count(shape, TopAbs_FACE), n * n);
  EXPECT_EQ(count(shape, TopAbs_VERTEX), (n + 1) * (n + 1));
  EXPECT_EQ(count(shape, TopAbs_EDGE), 2 * n * (n + 1));
  EXPECT_NEAR(area(shape), n * n * std::sqrt(1.01), 1e-6);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

double length(const TopoDS_Shape& s) {
  GProp_GProps props;
  BRepGProp::LinearProperties(s, props);
  return props.Mass();
}

// Shapes directly in the compound, by type.
int children(const TopoDS_Shape& s, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopoDS_Iterator it(s); it.More(); it.Next()) n += it.Value().ShapeType() == type;
  return n;
}

// Points closer than OpenCASCADE's tolerance (1e-7) count as one: no edge can join them. This
// hexagon is a polygon of axom's boxed_sphere (sampled finer for its topology), whose last three
// vertices lie within 6e-14 of each other; a 1-D edge between two such points is dropped too.
TEST(MedialMeshToBrep, PointsWithinTheToleranceAreOnePoint) {
  MedialMesh m;
  m.vertices = {{-4.72147748, -3.75383745, -3.25429773}, {-4.72045503, -3.76055521, -3.25519351},
                {-4.71477353, -3.77789515, -3.24257625}, {-4.71, -3.79, -3.2298065},
                {-4.71, -3.79, -3.2298065 + 5e-14},      {-4.71 + 4e-14, -3.79, -3.2298065}};
  m.radius.assign(6, 1.0);
  m.add_face({0, 1, 2, 3, 4, 5}, FaceKind::Voronoi, 0);
  m.edges = {{3, 4}};
  m.edge_solid = {0};
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(count(shape, TopAbs_FACE), 1);
  EXPECT_EQ(count(shape, TopAbs_EDGE), 4);  // the quadrilateral 0 1 2 3
  EXPECT_EQ(count(shape, TopAbs_VERTEX), 4);
  EXPECT_EQ(children(shape, TopAbs_EDGE), 0);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

TEST(MedialMeshToBrep, EdgesBecomeFreeEdgesSharingTheFacesVertices) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {0, 0, 0}};
  m.radius.assign(5, 1.0);
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  m.edges = {{0, 3}, {1, 0}, {4, 0}};  // dangling, of length 2; a side of the triangle; zero length
  m.edge_solid = {0, 0, 0};
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  EXPECT_EQ(children(shape, TopAbs_FACE), 1);
  EXPECT_EQ(children(shape, TopAbs_EDGE), 1);  // the side is in the face already; no zero-length edge
  EXPECT_EQ(count(shape, TopAbs_EDGE), 4);
  EXPECT_EQ(count(shape, TopAbs_VERTEX), 4);  // vertex 0 is shared by the face and the edge
  // The three sides of the triangle and the dangling edge.
  EXPECT_NEAR(length(shape), 2.0 + std::sqrt(2.0) + 2.0, 1e-12);
  EXPECT_NEAR(area(shape), 0.5, 1e-12);
  EXPECT_TRUE(BRepCheck_Analyzer(shape).IsValid());
}

TEST(MedialMeshToBrep, MeshOfEdgesOnlyIsAClosedPolygonOfEdges) {
  MedialMesh m;
  m.vertices = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  m.radius.assign(4, 1.0);
  m.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  m.edge_solid.assign(4, 0);
  const TopoDS_Shape shape = parse(medial_mesh_to_brep(m));
  ASSERT_FALSE(shape.IsNull());
  EXPECT_EQ(shape.ShapeType(), TopAbs_COMPOUND);
  EXPECT_EQ(count(shape, TopAbs_FACE), 0);
  EXPECT_EQ(children(shape, TopAbs_EDGE), 4);
  EXPECT_EQ(count(shape, TopAbs_VERTEX), 4);
  EXPECT_NEAR(length(shape), 4 * std::sqrt(2.0), 1e-12);
}

TEST(MedialMeshToBrep, EdgeIndexOutOfRangeIsRefused) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}};
  m.radius = {1, 1};
  m.edges = {{0, 2}};
  m.edge_solid = {0};
  EXPECT_THROW(medial_mesh_to_brep(m), InvalidInput);
}

TEST(MedialMeshToBrep, IndexOutOfRangeIsRefused) {
  MedialMesh m;
  m.vertices = {{0, 0, 0}};
  m.radius = {1};
  m.add_face({0, 1, 2}, FaceKind::Voronoi, 0);
  EXPECT_THROW(medial_mesh_to_brep(m), InvalidInput);
}

}  // namespace
}  // namespace cadmedial
