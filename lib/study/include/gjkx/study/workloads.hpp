/// @file
/// @brief The time-of-impact workloads of the study (chapters/09_study): the generator of
/// its sets of queries, each query with its reference (`gen`, `makeWorkloads`).
///
/// The header to include for the study's time-of-impact queries. It includes the query
/// (toi_query.hpp: `MotionSpec`, `ToiQuery`, `ToiWorkload`, `relativeSpeedBound`) and its
/// long-double reference (toi_reference.hpp: `ref`, `computeReference`), each with its
/// own file comment. Shapes are the study's one description, shape_description.hpp.
#pragma once

// The includes of this header before its parts moved out, in their order: with them the
// split compiles to the same code (GCC's code for a few functions of the study depends on
// the order in which it meets the headers).
#include <gjkx/study/shape_description.hpp>

#include <gjkx/motion/motion.hpp>
#include <gjkx/support_mapping/polytope.hpp>
#include <gjkx/support_mapping/primitives.hpp>
#include <gjkx/reference/polytope_distance.hpp>
#include <gjkx/reference/time_of_impact.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <gjkx/study/toi_query.hpp>
#include <gjkx/study/toi_reference.hpp>

namespace gjkx::study {

// ---------------------------------------------------------------------------------------
// The workloads

/// Options of the generator.
struct WorkloadOptions {
  /// Queries in each workload.
  int queriesPerWorkload = 48;
  /// Seed of the generator.
  std::uint64_t seed = 4;
};

/// The generator of the workloads.
namespace gen {

/// A small deterministic generator (the same numbers on every platform).
struct Random {
  /// The engine.
  std::mt19937_64 engine;
  /// A generator from a seed.
  explicit Random(std::uint64_t seed) : engine(seed) {}
  /// Uniform in [lo, hi), from the engine's top 53 bits.
  double uniform(double lo = 0, double hi = 1) { return lo + (hi - lo) * double(engine() >> 11) * 0x1.0p-53; }
  /// Uniform in {0, ..., n - 1}.
  int integer(int n) { return int(engine() % std::uint64_t(n)); }
  /// A random unit vector (rejection sampling in the unit ball).
  Eigen::Vector3d unit() {
    for (;;) {
      const Eigen::Vector3d x(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n = x.norm();
      if (n > 0.1 && n <= 1) return x / n;
    }
  }
  /// A random rotation (a uniform angle about a random axis).
  Eigen::Matrix3d rotation() { return Eigen::AngleAxisd(uniform(0, 2 * M_PI), unit()).toRotationMatrix(); }
};

/// n points on an ellipsoid of semi-axes `axes` (all on the hull).
inline ShapeDescription randomPolytope(Random& rng, int n, const Eigen::Vector3d& axes) {
  std::vector<Vector3<double>> points;
  for (int k = 0; k < n; ++k) points.push_back(rng.unit().cwiseProduct(axes));
  return polytopeDescription(points);
}

/// A convex polygon of n vertices in z = 0, one in each of n equal angular sectors, at
/// radius r (squeezed in y by a random 0.6 to 1).
inline ShapeDescription randomPolygon(Random& rng, int n, double r) {
  std::vector<Vector3<double>> points;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + rng.uniform(0.1, 0.9)) / n;
    points.emplace_back(r * std::cos(a), r * rng.uniform(0.6, 1.0) * std::sin(a), 0);
  }
  return polygonDescription(points);
}

/// A shape of medium size (about 0.3 to 0.8): box, capsule or polytope of 12, 100 or 1000 vertices.
inline ShapeDescription mediumShape(Random& rng, int which) {
  switch (which) {
    case 0: return boxDescription(Eigen::Vector3d(rng.uniform(0.2, 0.6), rng.uniform(0.2, 0.6), rng.uniform(0.1, 0.5)));
    case 1: return capsuleDescription(rng.uniform(0.2, 0.5), rng.uniform(0.1, 0.3));
    case 2: return randomPolytope(rng, 12, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
    case 3: return randomPolytope(rng, 100, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
    default: return randomPolytope(rng, 1000, Eigen::Vector3d(rng.uniform(0.3, 0.6), rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.5)));
  }
}

/// P's velocity (and acceleration) to reach `target` at time `arrive` from p0.
inline Eigen::Vector3d aim(const Eigen::Vector3d& p0, const Eigen::Vector3d& target, const Eigen::Vector3d& a, double arrive) {
  return (target - p0 - 0.5 * a * arrive * arrive) / arrive;
}

/// A random offset perpendicular to `dir` of length `length`.
inline Eigen::Vector3d sideways(Random& rng, const Eigen::Vector3d& dir, double length) {
  Eigen::Vector3d x = rng.unit();
  x -= dir * dir.dot(x);
  if (x.norm() < 1e-6) x = dir.unitOrthogonal();
  return x.normalized() * length;
}

/// Two bodies flying at each other (hit: aimed within a fraction of the smaller size) or
/// past each other (miss: the bounding spheres pass a clear margin apart), with the given
/// acceleration and angular speed.
inline ToiQuery encounter(Random& rng, ShapeDescription P, ShapeDescription Q, bool hit, double accel, double spin, double speed = 4) {
  ToiQuery q;
  q.P = std::move(P);
  q.Q = std::move(Q);
  const double rP = q.P.boundingRadius(), rQ = q.Q.boundingRadius();
  q.motionQ.R0 = rng.rotation();
  q.motionQ.v = rng.unit() * rng.uniform(0, 0.3);
  const Eigen::Vector3d dir = rng.unit();
  q.motionP.R0 = rng.rotation();
  q.motionP.p0 = -dir * (rP + rQ + 0.1 + speed * rng.uniform(0.2, 0.5));
  q.motionP.a = accel > 0 ? Eigen::Vector3d(rng.unit() * accel) : Eigen::Vector3d::Zero();
  if (spin > 0) q.motionP.w = rng.unit() * spin;
  if (spin > 0 && rng.uniform() < 0.5) q.motionQ.w = rng.unit() * spin * 0.5;
  const double arrive = rng.uniform(0.35, 1.1);
  // Q's centre at `arrive`, and an offset: small for a hit, beyond both bounding radii for a miss.
  const Eigen::Vector3d qAt = q.motionQ.v * arrive;
  const Eigen::Vector3d offset = hit ? sideways(rng, dir, rng.uniform(0, 0.3) * std::min(rP, rQ))
                                     : sideways(rng, dir, rP + rQ + rng.uniform(0.05, 0.5));
  q.motionP.v = aim(q.motionP.p0, qAt + offset, q.motionP.a, arrive);
  return q;
}

}  // namespace gen

/// The 3D workloads and the 2D set; each query with its reference.
inline std::vector<ToiWorkload> makeWorkloads(const WorkloadOptions& o) {
  using gen::Random;
  std::vector<ToiWorkload> out;
  const int n = o.queriesPerWorkload;
  Random rng(o.seed);
  // Shape pairs: P from box, capsule, poly12, poly100, poly1000 (1 in 8); Q never poly1000.
  auto shapeP = [&](int k) { return gen::mediumShape(rng, k % 8 == 7 ? 4 : k % 4); };
  auto shapeQ = [&](int k) { return gen::mediumShape(rng, (k / 4) % 4); };

  auto encounters = [&](const std::string& name, const std::string& description, double accel, double spin) {
    ToiWorkload w{name, description, false, {}};
    for (int k = 0; k < n; ++k) {
      ShapeDescription P = shapeP(k), Q = shapeQ(k);
      w.queries.push_back(gen::encounter(rng, std::move(P), std::move(Q), k % 3 != 2, accel, spin));
    }
    out.push_back(std::move(w));
  };
  encounters("linear", "constant velocity, boxes/capsules/polytopes of 12-1000 vertices, 2/3 aimed to hit", 0, 0);
  encounters("ballistic", "constant acceleration |a| = 6 (curved paths), aimed along the parabola", 6, 0);
  encounters("screw_w0.5", "screw motion, 0.5 rad per interval", 0, 0.5);
  encounters("screw_w1.5", "screw motion, 1.5 rad per interval", 0, 1.5);
  encounters("screw_w3.0", "screw motion, 3.0 rad per interval (almost half a turn)", 0, 3.0);

  {  // The paper's tunnelling case: a small fast box through a thin plate.
    ToiWorkload w{"thin_plate", "small box (0.01-0.05) at speed 2-6 through a plate 0.005 thick; 1/4 pass beside it", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.Q = boxDescription(Eigen::Vector3d(1, 1, 0.0025));
      q.motionQ.R0 = Eigen::Matrix3d::Identity();
      const double h = rng.uniform(0.01, 0.05);
      q.P = k % 2 ? boxDescription(Eigen::Vector3d(h, h, h)) : gen::randomPolytope(rng, 12, Eigen::Vector3d(h, h, h));
      q.motionP.R0 = rng.rotation();
      const double speed = rng.uniform(2, 6);
      const bool beside = k % 4 == 3;
      q.motionP.p0 = Eigen::Vector3d(rng.uniform(-0.8, 0.8) + (beside ? 2.2 : 0), rng.uniform(-0.8, 0.8), speed * rng.uniform(0.2, 0.8));
      q.motionP.v = Eigen::Vector3d(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), -speed);
      if (k % 3 == 0) q.motionP.w = rng.unit() * 2.0;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // Small fast objects against medium ones.
    ToiWorkload w{"small_fast", "small sphere/box/poly12 (0.01-0.04) at speed 10-20 at a medium body; 1/3 aimed to miss", false, {}};
    for (int k = 0; k < n; ++k) {
      const double h = rng.uniform(0.01, 0.04);
      ShapeDescription P = k % 3 == 0 ? sphereDescription(h) : (k % 3 == 1 ? boxDescription(Eigen::Vector3d(h, h, h)) : gen::randomPolytope(rng, 12, Eigen::Vector3d(h, h, h)));
      ShapeDescription Q = gen::mediumShape(rng, k % 8 == 5 ? 4 : k % 4);
      w.queries.push_back(gen::encounter(rng, std::move(P), std::move(Q), k % 3 != 1, 0, k % 2 ? 0 : 4.0, rng.uniform(10, 20)));
    }
    out.push_back(std::move(w));
  }
  {  // Near misses: P slides over Q, its lowest point a gap above Q's highest; half are shallow grazes (negative gap).
    ToiWorkload w{"near_miss", "P's lowest point slides over Q's highest at a gap of 0.025-0.1 (clear misses) or -0.05 to -0.005 (grazes)", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.P = shapeP(k);
      q.Q = shapeQ(k + 1);
      q.motionP.R0 = rng.rotation();
      q.motionQ.R0 = rng.rotation();
      // P's lowest point passes straight over Q's highest point, `gap` above it (negative: a graze).
      // The z extents come from the reference's own vertices (cores, plus the skins).
      auto extreme = [](const ShapeDescription& s, const Eigen::Matrix3d& R, double sign) {
        const ref::Body b = ref::body(s);
        Eigen::Vector3d best = Eigen::Vector3d::Zero();
        double value = -1e300;
        for (const auto& x : b.v) {
          const Eigen::Vector3d y = (R * x.cast<double>());
          if (sign * y.z() > value) {
            value = sign * y.z();
            best = y;
          }
        }
        return Eigen::Vector3d(best + Eigen::Vector3d(0, 0, sign * double(b.skin)));
      };
      const double gap = k % 2 ? rng.uniform(0.025, 0.1) : -rng.uniform(0.005, 0.05);
      const Eigen::Vector3d top = extreme(q.Q, q.motionQ.R0, 1), low = extreme(q.P, q.motionP.R0, -1);
      const double speed = rng.uniform(2, 5);
      const double span = q.P.boundingRadius() + q.Q.boundingRadius() + 0.1;
      const Eigen::Vector3d across(std::cos(k * 1.3), std::sin(k * 1.3), 0);
      const Eigen::Vector3d over(top.x() - low.x(), top.y() - low.y(), top.z() + gap - low.z());  // P's origin when low is over top
      const double when = rng.uniform(0.3, 0.8);
      q.motionP.p0 = over - across * (speed * when);
      (void)span;
      q.motionP.v = across * speed;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // Crossing paths (the paper's Fig. 1B): both bodies fast, their paths cross; at the same time (hit) or not (miss).
    ToiWorkload w{"crossing", "P and Q both fast (speed 3-6), paths crossing; they reach the crossing together (hit) or apart (miss)", false, {}};
    for (int k = 0; k < n; ++k) {
      ToiQuery q;
      q.P = shapeP(k);
      q.Q = shapeQ(k + 2);
      q.motionP.R0 = rng.rotation();
      q.motionQ.R0 = rng.rotation();
      const Eigen::Vector3d dP = rng.unit(), dQ0 = rng.unit();
      const Eigen::Vector3d dQ = (dQ0 - dP * dP.dot(dQ0)).normalized();  // perpendicular paths
      const double sP = rng.uniform(3, 6), sQ = rng.uniform(3, 6);
      const double tP = rng.uniform(0.3, 0.7);
      const double rSum = q.P.boundingRadius() + q.Q.boundingRadius();
      const bool hit = k % 2 == 0;
      // Miss: Q reaches the crossing when P is already rSum + 0.1 to 0.5 past it (or before it).
      const double lag = hit ? rng.uniform(-0.2, 0.2) * rSum / sQ : (rSum + rng.uniform(0.1, 0.5)) * (1 / sP + 1 / sQ) * (k % 4 == 1 ? 1 : -1);
      const double tQ = tP + lag;
      q.motionP.p0 = -dP * (sP * tP);
      q.motionP.v = dP * sP;
      q.motionQ.p0 = -dQ * (sQ * tQ);
      q.motionQ.v = dQ * sQ;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  {  // 2D: polygons of 3-8 vertices and disks in the plane z = 0 (Box2D's set).
    ToiWorkload w{"planar_2d", "polygons of 3-8 vertices and disks in z = 0, linear + spin up to 3 rad; 2/3 aimed to hit", true, {}};
    for (int k = 0; k < n; ++k) {
      auto planarShape = [&](int j) {
        return j % 4 == 3 ? diskDescription(rng.uniform(0.2, 0.5)) : gen::randomPolygon(rng, 3 + rng.integer(6), rng.uniform(0.3, 0.8));
      };
      ToiQuery q;
      q.planar = true;
      q.P = planarShape(k);
      q.Q = planarShape(k / 2 + 1);
      auto planarRotation = [&] { return Eigen::AngleAxisd(rng.uniform(0, 2 * M_PI), Eigen::Vector3d::UnitZ()).toRotationMatrix(); };
      q.motionP.R0 = planarRotation();
      q.motionQ.R0 = planarRotation();
      const double rP = q.P.boundingRadius(), rQ = q.Q.boundingRadius();
      const double ang = rng.uniform(0, 2 * M_PI);
      const Eigen::Vector3d dir(std::cos(ang), std::sin(ang), 0);
      q.motionP.p0 = -dir * (rP + rQ + 0.1 + rng.uniform(0.5, 2));
      q.motionP.w = Eigen::Vector3d(0, 0, rng.uniform(-3, 3));
      q.motionQ.w = Eigen::Vector3d(0, 0, rng.uniform(-1, 1));
      const double arrive = rng.uniform(0.35, 1.1);
      const bool hit = k % 3 != 2;
      const Eigen::Vector3d side(-dir.y(), dir.x(), 0);
      const Eigen::Vector3d target = side * (hit ? rng.uniform(-0.3, 0.3) * std::min(rP, rQ) : (rP + rQ + rng.uniform(0.05, 0.5)));
      q.motionP.v = (target - q.motionP.p0) / arrive;
      w.queries.push_back(q);
    }
    out.push_back(std::move(w));
  }
  for (auto& w : out)
    for (auto& q : w.queries) computeReference(q);
  return out;
}

}  // namespace gjkx::study
