// Whether two medial meshes are the same file: every array equal, vertex for vertex and face for
// face (the output's order is part of what the engine promises).
#pragma once

#include <gtest/gtest.h>

#include "core/types.h"

namespace cadmedial::test {

inline void expect_same_mesh(const MedialMesh& a, const MedialMesh& b) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  ASSERT_EQ(a.num_faces(), b.num_faces());
  ASSERT_EQ(a.num_edges(), b.num_edges());
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.radius, b.radius);
  EXPECT_EQ(a.face_start, b.face_start);
  EXPECT_EQ(a.face_vertices, b.face_vertices);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.solid, b.solid);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_solid, b.edge_solid);
}

}  // namespace cadmedial::test
