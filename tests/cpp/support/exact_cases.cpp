#include "support/exact_cases.h"

#include <cmath>
#include <memory>

#include "support/convex_polytope.h"
#include "support/polytope_medial_axis.h"
#include "support/revolved_medial_axis.h"
#include "support/solids.h"

namespace cadmedial::test {

namespace {

// Points along the segment ab, at most `step` apart, ends included.
void add_segment_points(const Vec3& a, const Vec3& b, double step, std::vector<Vec3>& out) {
  const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / step)));
  for (int k = 0; k <= n; ++k) out.push_back(a + (static_cast<double>(k) / n) * (b - a));
}

void add_circle_points(double R, double z, double step, std::vector<Vec3>& out) {
  const int n = static_cast<int>(std::ceil(2 * M_PI * R / step));
  for (int k = 0; k < n; ++k) out.push_back({R * std::cos(2 * M_PI * k / n), R * std::sin(2 * M_PI * k / n), z});
}

ExactCase polytope_case(const std::string& name, const ConvexPolytope& polytope,
                        std::function<TopoDS_Shape()> make_shape, double h) {
  auto poly = std::make_shared<ConvexPolytope>(polytope);
  auto axis = std::make_shared<PolytopeMedialAxis>(*poly);
  ExactCase c;
  c.name = name;
  c.make_shape = std::move(make_shape);
  c.spacing = h;
  c.axis_tolerance = h / (1.0 - poly->max_normal_cosine());
  c.axis_distance = [poly, axis](const Vec3& x) { return axis->distance(x); };
  c.axis_sample = [poly, axis](int n, std::uint32_t seed) { return axis->sample(n, seed); };
  c.boundary_distance = [poly](const Vec3& x) { return poly->boundary_distance(x); };
  for (const auto& e : poly->edges)
    add_segment_points(poly->vertices[e[0]], poly->vertices[e[1]], h / 2, c.convex_edge_points);
  c.corners = poly->vertices;
  c.euler = 1;
  c.bbox_diagonal = poly->bbox_diagonal();
  return c;
}

ExactCase revolved_case(const std::string& name, const RevolvedMedialAxis& reference,
                        std::function<TopoDS_Shape()> make_shape, double h, long euler, double diagonal) {
  auto axis = std::make_shared<RevolvedMedialAxis>(reference);
  ExactCase c;
  c.name = name;
  c.make_shape = std::move(make_shape);
  c.spacing = h;
  c.axis_tolerance = 2.2 * h;
  c.axis_distance = [axis](const Vec3& x) { return axis->distance(x); };
  c.axis_sample = [axis](int n, std::uint32_t seed) { return axis->sample(n, seed); };
  c.boundary_distance = [axis](const Vec3& x) { return axis->boundary_distance(x); };
  c.euler = euler;
  c.bbox_diagonal = diagonal;
  return c;
}

std::vector<ExactCase> build_cases() {
  std::vector<ExactCase> cases;
  // Sample counts at these spacings: roughly 1.15 * area / h^2, 3k to 15k per solid.
  cases.push_back(polytope_case("Box", box_polytope(10, 8, 6), [] { return make_box(10, 8, 6); }, 0.3));
  cases.push_back(polytope_case("ThinPlate", box_polytope(20, 10, 1), [] { return make_box(20, 10, 1); }, 0.2));
  const std::vector<std::array<double, 2>> triangle{{0, 0}, {6, 0}, {2, 5}};
  cases.push_back(polytope_case("Wedge", prism_polytope(triangle, 4), [triangle] { return make_prism(triangle, 4); },
                                0.2));
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    // Normals at least 50 degrees apart: dihedral angles at most 130 (Angle condition at 5 degrees
    // handles up to 170), tolerance h / (1 - cos 50) <= 2.8 h.
    const ConvexPolytope poly = random_polytope(seed, 10, 5.0, 50.0, 1.0);
    cases.push_back(polytope_case("RandomPolytope" + std::to_string(seed), poly,
                                  [poly] { return make_polytope_solid(poly); }, 0.25));
  }
  {
    const double R = 2, H = 8, h = 0.15;
    ExactCase c = revolved_case("Cylinder", RevolvedMedialAxis::cylinder(R, H), [=] { return make_cylinder(R, H); },
                                h, 1, std::sqrt(4 * R * R + 4 * R * R + H * H));
    add_circle_points(R, 0, h / 2, c.convex_edge_points);
    add_circle_points(R, H, h / 2, c.convex_edge_points);
    cases.push_back(c);
  }
  {
    const double R = 5, H = 2, h = 0.2;
    ExactCase c = revolved_case("Disc", RevolvedMedialAxis::cylinder(R, H), [=] { return make_cylinder(R, H); }, h, 1,
                                std::sqrt(8 * R * R + H * H));
    add_circle_points(R, 0, h / 2, c.convex_edge_points);
    add_circle_points(R, H, h / 2, c.convex_edge_points);
    cases.push_back(c);
  }
  cases.push_back(revolved_case("Sphere", RevolvedMedialAxis::sphere(3), [] { return make_sphere(3); }, 0.2, 1,
                                6 * std::sqrt(3.0)));
  cases.push_back(revolved_case("Torus", RevolvedMedialAxis::torus(5, 1.5), [] { return make_torus(5, 1.5); }, 0.2,
                                0, std::sqrt(2 * 13.0 * 13.0 + 9.0)));
  return cases;
}

}  // namespace

const std::vector<ExactCase>& exact_cases() {
  static const std::vector<ExactCase> cases = build_cases();
  return cases;
}

}  // namespace cadmedial::test
