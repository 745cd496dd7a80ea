// Tests of the prism hull (convex_hull.hpp's prismHull, Polytope::prism): a static mesh's
// piece at the polygonal level (§6), a triangle and its copy moved off its plane, whose
// faces are known. Held to Qhull's hull of the same six points and to a linear scan.
#include <gjkx/support_mapping/polytope.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <random>
#include <set>
#include <vector>

using namespace gjkx;

namespace {

// A random triangle of a mesh about a metre across (sides from a millimetre to 30 cm, a
// quarter of them slivers a hundred times longer than wide) and its copy moved back by a
// millimetre (polygonPieces: a thousandth of the mesh's size) along its normal, or along a
// slanted direction.
template <typename S>
std::vector<Vector3<S>> randomPrism(std::mt19937& rng, bool slanted) {
  std::uniform_real_distribution<double> unit(-1, 1), scale(-3, -0.5), place(-0.5, 0.5);
  const Eigen::Vector3d a(place(rng), place(rng), place(rng));
  const double size = std::pow(10.0, scale(rng));
  const Eigen::Vector3d b = a + size * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  Eigen::Vector3d c = a + size * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  if (rng() % 4 == 0) c = a + 0.5 * (b - a) + 1e-2 * size * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  Eigen::Vector3d back = -1e-3 * (b - a).cross(c - a).normalized();
  if (slanted) back += 0.5e-3 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  std::vector<Vector3<S>> points;
  for (const Eigen::Vector3d& p : {a, b, c, Eigen::Vector3d(a + back), Eigen::Vector3d(b + back), Eigen::Vector3d(c + back)})
    points.push_back(p.cast<S>());
  return points;
}

}  // namespace

TEMPLATE_TEST_CASE("a prism's hull is Qhull's hull of its six points, with no Qhull call", "[polytope][hull][prism]",
                   float, double) {
  using S = TestType;
  std::mt19937 rng(7);
  int checked = 0, wrongVertices = 0, outside = 0, inwards = 0, badAdjacency = 0, wrongSupport = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto points = randomPrism<S>(rng, trial % 2 == 1);
    // Every such prism is one to within round-off: no Qhull call.
    std::vector<Eigen::Vector3d> exact;
    for (const auto& p : points) exact.push_back(p.template cast<double>());
    const std::optional<ConvexHull> known = prismHull(exact);
    REQUIRE(known.has_value());
    const Polytope<S> prism = Polytope<S>::prism(points);
    CHECK(prism.triangles() == known->triangles);
    const Polytope<S> qhull = Polytope<S>::hull(points);
    ++checked;
    // The same vertices (all six, in input order, unless Qhull welded a sliver's corners).
    if (qhull.vertexCount() == 6 && prism.vertices() != qhull.vertices()) ++wrongVertices;
    // Eight outward triangles, every corner on or below each (to the float rounding of its
    // corners), Euler's V - E + F = 2 through the adjacency.
    CHECK(prism.triangles().size() == 8);
    std::set<std::pair<int, int>> edges;
    for (const auto& t : prism.triangles()) {
      const Eigen::Vector3d a = prism.vertex(t[0]).template cast<double>();
      const Eigen::Vector3d n = (prism.vertex(t[1]).template cast<double>() - a)
                                    .cross(prism.vertex(t[2]).template cast<double>() - a)
                                    .normalized();
      if (!(n.dot(a - prism.center().template cast<double>()) > 0)) ++inwards;
      for (const auto& v : prism.vertices())
        if (n.dot(v.template cast<double>() - a) > 1e-12) ++outside;
      for (int e = 0; e < 3; ++e) edges.insert({std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])});
    }
    std::size_t entries = 0;
    for (int v = 0; v < prism.vertexCount(); ++v) entries += prism.neighbours(v).size();
    if (entries != 2 * edges.size() || 6 - int(edges.size()) + 8 != 2) ++badAdjacency;
    // Hill climbing on it finds the support of a linear scan, from every start.
    for (int k = 0; k < 20; ++k) {
      const Vector3<S> s(S(rng() % 201) - 100, S(rng() % 201) - 100, S(rng() % 201) - 100);
      if (s.norm() == 0) continue;
      for (SupportHint start = 0; start < 6; ++start) {
        SupportHint hint = start;
        if (s.dot(prism.support(s, hint)) != s.dot(prism.vertex(prism.supportIndexLinearScan(s)))) ++wrongSupport;
      }
    }
  }
  INFO(checked << " prisms");
  CHECK(wrongVertices == 0);
  CHECK(outside == 0);
  CHECK(inwards == 0);
  CHECK(badAdjacency == 0);
  CHECK(wrongSupport == 0);
}

TEST_CASE("a prism's hull refuses bad input by name", "[polytope][prism][input]") {
  std::vector<Vector3<double>> five(5, Vector3<double>::Zero());
  CHECK_THROWS_WITH(Polytope<double>::prism(five), Catch::Matchers::Contains("polytope.points") &&
                                                       Catch::Matchers::Contains("6 points"));
  std::vector<Vector3<double>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
  points[4].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(Polytope<double>::prism(points), Catch::Matchers::Contains("point 4 is not finite"));
  // A triangle with no area is no prism: Qhull's answer, a flat set.
  points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, -1}, {1, 0, -1}, {2, 0, -1}};
  CHECK_FALSE(prismHull(points).has_value());
  CHECK_THROWS_WITH(Polytope<double>::prism(points), Catch::Matchers::Contains("one plane"));
  // A copy moved within its triangle's plane is no prism either; Qhull finds its hull.
  points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {1.5, 0, 0}, {0.5, 1, 0}};
  CHECK_FALSE(prismHull(points).has_value());
}
