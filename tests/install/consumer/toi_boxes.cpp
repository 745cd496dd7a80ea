// The time of impact of two unit cubes, through the installed package (gjkx::brent).
//
// P is a box at rest at the origin; Q, the convex hull of a unit cube's eight corners
// (Qhull, in the static library gjkx::support_mapping), starts at x = 3 and moves at -4 along
// x. The faces facing each other are 3 - 4t - 1 = 2 - 4t apart, so the bodies come within
// the collision tolerance tol at t* = (2 - tol) / 4, just before 1/2. The solver must say
// Hit at t* within tol/4 + its time tolerance (as tests/brent/test_time_of_impact.cpp
// asks of the same case), with the normal along +x.
#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  using gjkx::Vector3;
  std::vector<Vector3<double>> corners;
  for (double x : {-0.5, 0.5})
    for (double y : {-0.5, 0.5})
      for (double z : {-0.5, 0.5}) corners.emplace_back(x, y, z);
  const auto P = gjkx::fixedAt(gjkx::Box<double>(Vector3<double>(0.5, 0.5, 0.5)), Vector3<double>(0, 0, 0));
  const auto Q = gjkx::translating(gjkx::Polytope<double>::hull(corners), Vector3<double>(3, 0, 0),
                                   Vector3<double>(-4, 0, 0));
  const gjkx::ToiSettings<double> settings;
  const auto r = gjkx::timeOfImpact(P, Q, 0.0, 1.0, settings);

  const double tol = settings.collisionTolerance;
  const double expected = (2 - tol) / 4;
  const double error = std::abs(r.time - expected);
  const double allowed = tol / 4 + settings.timeTolerance;
  std::printf("time of impact %.12f expected %.12f error %.3g allowed %.3g status %s normal %g %g %g\n", r.time,
              expected, error, allowed, gjkx::toString(r.status), r.normal.x(), r.normal.y(), r.normal.z());
  const bool ok = r.status == gjkx::ToiStatus::Hit && error <= allowed &&
                  r.normal.isApprox(Vector3<double>(1, 0, 0), 1e-6);
  std::printf("%s\n", ok ? "OK" : "WRONG");
  return ok ? 0 : 1;
}
