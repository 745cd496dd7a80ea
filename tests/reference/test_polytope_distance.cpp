// Brute-force distances of gjkx::reference (polytope_distance.hpp): boxes and rounded
// shapes by hand, the slivers of the fuzz findings against closed forms, and the two
// independent brute forces (directions for clouds, feature pairs and separating axes for
// polytopes) against each other on random tetrahedra.
#include <gjkx/reference/polytope_distance.hpp>

#include <catch2/catch.hpp>

#include <random>

using namespace gjkx::reference;

namespace {

std::vector<Vec> boxCorners(const Vec& centre, const Vec& h) {
  std::vector<Vec> out;
  for (int k = 0; k < 8; ++k)
    out.push_back(centre + Vec((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z()));
  return out;
}

// The box's 12 boundary triangles (corner k has bit 0: +x, bit 1: +y, bit 2: +z).
WorldPolytope box(const Vec& centre, const Vec& h) {
  const std::vector<std::array<int, 3>> t{{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                          {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}};
  return WorldPolytope::fromTriangles(boxCorners(centre, h), t);
}

WorldPolytope tetrahedron(const std::vector<Vec>& v) {
  return WorldPolytope::fromTriangles(v, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
}

}  // namespace

TEST_CASE("reference: two unit boxes by hand", "[reference]") {
  const Vec h(0.5, 0.5, 0.5);
  // 2 apart: distance 1 (face to face).
  CHECK(signedDistance({boxCorners(Vec(0, 0, 0), h), 0}, {boxCorners(Vec(2, 0, 0), h), 0}) == Approx(1.0));
  CHECK(distance(box(Vec(0, 0, 0), h), box(Vec(2, 0, 0), h)) == Approx(1.0));
  CHECK(boundaryDistance(box(Vec(0, 0, 0), h), box(Vec(2, 0, 0), h)).distance == Approx(1.0));
  CHECK(separatingAxisGap(box(Vec(0, 0, 0), h), box(Vec(2, 0, 0), h)) == Approx(1.0));
  // Corner to corner: (2, 2, 2) apart, distance sqrt(3).
  const FeatureDistance corner = boundaryDistance(box(Vec(0, 0, 0), h), box(Vec(2, 2, 2), h));
  CHECK(corner.distance == Approx(std::sqrt(3.0)));
  CHECK((corner.p - Vec(0.5, 0.5, 0.5)).norm() < 1e-15);
  CHECK((corner.q - Vec(1.5, 1.5, 1.5)).norm() < 1e-15);
  // Overlapping by 0.25: signed distance -0.25, distance 0.
  CHECK(signedDistance({boxCorners(Vec(0, 0, 0), h), 0}, {boxCorners(Vec(0.75, 0, 0), h), 0}) == Approx(-0.25));
  CHECK(separatingAxisGap(box(Vec(0, 0, 0), h), box(Vec(0.75, 0, 0), h)) == Approx(-0.25));
  CHECK(distance(box(Vec(0, 0, 0), h), box(Vec(0.75, 0, 0), h)) == 0);
  // Crossed bars, no vertex inside the other: overlap found by an edge through a face.
  CHECK(distance(box(Vec(0, 0, 0), Vec(3, 0.1, 0.1)), box(Vec(0, 0, 0), Vec(0.1, 3, 0.1))) == 0);
  CHECK(box(Vec(0, 0, 0), h).contains(Vec(0.25, 0.25, -0.5)));
  CHECK(!box(Vec(0, 0, 0), h).contains(Vec(0.25, 0.25, -0.51L)));
}

TEST_CASE("reference: spheres and capsules as clouds", "[reference]") {
  // Spheres of radius 1 and 2, centres 5 apart: 2.
  CHECK(signedDistance({{Vec(0, 0, 0)}, 1}, {{Vec(3, 4, 0)}, 2}) == Approx(2.0));
  // Overlapping by 0.5.
  CHECK(signedDistance({{Vec(0, 0, 0)}, 1}, {{Vec(2.5L, 0, 0)}, 2}) == Approx(-0.5));
  // Crossed capsules of radius 0.25, axes 3 apart: 2.5.
  CHECK(signedDistance({{Vec(-1, 0, 0), Vec(1, 0, 0)}, 0.25L}, {{Vec(0, -1, 3), Vec(0, 1, 3)}, 0.25L}) == Approx(2.5));
}

TEST_CASE("reference: the findings' slivers as clouds", "[reference][sliver]") {
  // A point 2.1e-8 above a sliver triangle 47000 x 1e-7 (reference_sliver_triangle) and
  // 4e-8 from its long edge (reference_point_near_long_edge); all exact in this frame.
  const Cloud sliver{{Vec(0, 0, 0), Vec(47000, 0, 0), Vec(23500, Real(1e-7), 0)}, 0};
  CHECK(std::abs(signedDistance({{Vec(20000, Real(5e-8), Real(2.1e-8))}, 0}, sliver) - Real(2.1e-8)) < Real(1e-15));
  CHECK(std::abs(signedDistance(sliver, {{Vec(20000, Real(-3e-8), Real(4e-8))}, 0}) - Real(5e-8)) < Real(1e-15));
  // Two nearly parallel edges 2.7e5 long, h = 1e-6 apart where their projections cross.
  const Cloud e1{{Vec(0, 0, 0), Vec(270000, 0, 0)}, 0}, e2{{Vec(-1000, Real(-1e-3), Real(1e-6)), Vec(271000, Real(1e-3), Real(1e-6))}, 0};
  CHECK(std::abs(signedDistance(e1, e2) - Real(1e-6)) < Real(1e-15));
  // A needle tetrahedron (edges 2.7e5 and 1e-4) above a unit square's plane by 1e-5.
  const std::vector<Vec> needle{Vec(0, 0, Real(1e-5)), Vec(Real(1e-4), 0, Real(1e-5)), Vec(0, 270000, Real(1e-5)),
                                Vec(Real(5e-5), 270000, Real(1e-5) + Real(1e-4))};
  const Cloud floor{{Vec(-1, -1, 0), Vec(1, -1, 0), Vec(-1, 1, 0), Vec(1, 1, 0)}, 0};
  CHECK(std::abs(signedDistance(floor, {needle, 0}) - Real(1e-5)) < Real(1e-15));
  CHECK(std::abs(distance(tetrahedron(needle), box(Vec(0, 0, -0.5L), Vec(1, 1, 0.5L))) - Real(1e-5)) < Real(1e-15));
}

TEST_CASE("reference: random tetrahedra, the brute forces agree", "[reference]") {
  // signedDistance (max SD over candidate directions, min over closest pairs) and the
  // polytope forms (feature pairs, separating axes) share only closest_points.hpp; on
  // random tetrahedra near and far, apart and overlapping, they agree within round-off.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  auto point = [&](const Vec& c) { return Vec(c + Vec(Real(u(rng)), Real(u(rng)), Real(u(rng)))); };
  int apart = 0, overlapping = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec c(Real(1.5 * u(rng)), Real(1.5 * u(rng)), Real(1.5 * u(rng)));
    std::vector<Vec> a, b;
    for (int k = 0; k < 4; ++k) a.push_back(point(Vec::Zero()));
    for (int k = 0; k < 4; ++k) b.push_back(point(c));
    const Vec na = (a[1] - a[0]).cross(a[2] - a[0]), nb = (b[1] - b[0]).cross(b[2] - b[0]);
    if (std::abs(na.dot(a[3] - a[0])) < 1e-3 || std::abs(nb.dot(b[3] - b[0])) < 1e-3) continue;  // flat
    const WorldPolytope P = tetrahedron(a), Q = tetrahedron(b);
    const Real sd = signedDistance({a, 0}, {b, 0});
    const Real gap = separatingAxisGap(P, Q);
    INFO("trial " << trial << ": signed distance " << double(sd) << ", SAT gap " << double(gap));
    if (gap > 0) {
      ++apart;
      CHECK(std::abs(boundaryDistance(P, Q).distance - sd) < Real(1e-15));
      CHECK(std::abs(distance(P, Q) - sd) < Real(1e-15));
      CHECK(gap <= sd + Real(1e-15));  // an axis's gap is a lower bound
    } else {
      ++overlapping;
      CHECK(std::abs(gap - sd) < Real(1e-15));  // both the best separating axis
      if (gap < -1e-12) CHECK(distance(P, Q) == 0);
    }
  }
  CHECK(apart > 50);
  CHECK(overlapping > 20);
}
