// libFuzzer target: the extrusion test (§3) of two moving bodies over an interval, in
// float or double, paper and certified variants, every kind of motion and per-vertex
// linear deforming simplices. Checks: no NaN; the distance at t0 against the brute
// force; CollidingAtStart only within the tolerance; NoCollision's separating vector
// really separating (brute-force supporting distance above the tolerance plus margin at
// both ends); and, where the test claims to be exact (linear motion, or the certified
// variant), NoCollision only if a dense static sampling of the interval (200 times,
// GJK in double, the brute force confirming anything close) never finds the bodies
// within half the tolerance.
#include "fuzz_common.hpp"

namespace gjkx::fuzz {
namespace {

constexpr int kSamples = 200;

/// The supporting distance of two clouds along a unit s, in long double.
inline Real cloudSd(const Cloud& a, const Cloud& b, const RVec& s) {
  Real maxA = -std::numeric_limits<Real>::infinity(), minB = std::numeric_limits<Real>::infinity();
  for (const auto& x : a.points) maxA = std::max(maxA, s.dot(x));
  for (const auto& y : b.points) minB = std::min(minB, s.dot(y));
  return minB - maxA - a.radius - b.radius;
}

template <typename S>
void run(Decoder& in) {
  const MovingPair<S> pair = decodeMovingPair<S>(in);
  const S t0 = pair.interval.t0, t1 = pair.interval.t1;
  const Body<S>& P = pair.P;
  const Body<S>& Q = pair.Q;
  ExtrusionSettings<S> settings;
  pair.configure(settings);
  const Real tol = Real(settings.collisionTolerance);

  const ExtrusionResult<S> r = std::visit(
      [&](const auto& p, const auto& q) { return extrusionTest(p, q, t0, t1, settings); }, P, Q);

  requireNotNan(r.separatingVector, "extrusion.separatingVector");
  requireNotNan(r.distanceAtStart, "extrusion.distanceAtStart");
  requireNotNan(r.witnessP, "extrusion.witnessP");
  requireNotNan(r.witnessQ, "extrusion.witnessQ");
  requireNotNan(r.maxSdEnd, "extrusion.maxSdEnd");
  requireNotNan(r.margin, "extrusion.margin");
  for (int k = 0; k < r.separating.count; ++k) {
    requireNotNan(r.separating.vectors[k], "extrusion.separating.vectors");
    requireNotNan(r.separating.sdStart[k], "extrusion.separating.sdStart");
    requireNotNan(r.separating.sdEnd[k], "extrusion.separating.sdEnd");
  }

  const Real extent = extentOver(P, Q, t0, t1, kSamples);
  const Real slack = slackFor<S>(extent);
  const Cloud a0 = cloudAt(P, t0), b0 = cloudAt(Q, t0);
  const Real ref0 = signedDistance(a0, b0);
  context() = std::string(sizeof(S) == 4 ? "float" : "double") + " at t0: P " + describe(a0) + " Q " + describe(b0);
  const bool rounded = a0.radius > 0 || b0.radius > 0;
  const Real relative = distanceAllowance(ref0, extent, rounded && !settings.gjk.roundedCores, settings.gjk.relativeTolerance) - slack;

  // GJK's distance at t0 is held to the reference at every scale (a flat box 2000 wide
  // against a sphere of 1e-7 once gave 1.9e-8 for an overlap of 5.9e-10; fixed by the
  // sliver-accurate sub-algorithm and GJK on the cores of rounded shapes).
  const bool gjkAccurate = checkAccuracy();
  switch (r.status) {
    case ExtrusionStatus::NumericalFailure: violation("extrusion: NumericalFailure on finite input");
    case ExtrusionStatus::IterationCap: return;  // undecided, said as such
    case ExtrusionStatus::CollidingAtStart:
      if (gjkAccurate && ref0 > tol + slack)
        violation("extrusion: CollidingAtStart, but the reference distance at t0 is %.12Lg (tol %.3Lg, slack %.3Lg)",
                  ref0, tol, slack);
      return;
    case ExtrusionStatus::Undecided:
      if (gjkAccurate && std::abs(Real(r.distanceAtStart) - std::max(Real(0), ref0)) > slack + relative)
        violation("extrusion: Undecided with distanceAtStart %.12Lg, reference %.12Lg (slack %.3Lg)",
                  Real(r.distanceAtStart), ref0, slack + relative);
      if (gjkAccurate && ref0 < tol - slack)
        violation("extrusion: Undecided, but the reference distance at t0 %.12Lg is within the tolerance %.3Lg", ref0,
                  tol);
      return;
    case ExtrusionStatus::NoCollision: break;
  }

  // NoCollision: the vector separates at both ends by the tolerance plus the margin.
  const RVec s = r.separatingVector.template cast<Real>();
  if (std::abs(s.norm() - 1) > Real(1e-3)) violation("extrusion: separatingVector not unit (|s| = %.9Lg)", s.norm());
  const RVec unit = s.normalized();
  const Real need = tol + Real(r.margin) - slack;
  const Real sd0 = cloudSd(a0, b0, unit), sd1 = cloudSd(cloudAt(P, t1), cloudAt(Q, t1), unit);
  if (sd0 < need || sd1 < need)
    violation("extrusion: NoCollision along s with SD(t0) = %.12Lg, SD(t1) = %.12Lg, needed %.12Lg", sd0, sd1, need);
  // Where the test claims exactness, a dense static sampling must agree.
  const bool exact =
      settings.variant == ExtrusionVariant::Certified || (accelerationBound(P) == S(0) && accelerationBound(Q) == S(0));
  if (!exact) return;
  const Real floor = tol / 2 - slack;
  for (int k = 0; k < kSamples; ++k) {
    const S t = sampleTime(t0, t1, k, kSamples);
    const Real d = signedDistanceAt(P, Q, t, floor);
    if (d < floor)
      violation("extrusion (%s): NoCollision on [%.9g, %.9g], but at t = %.9g the distance is %.12Lg < tol/2 - slack = %.12Lg",
                toString(settings.variant), double(t0), double(t1), double(t), d, floor);
  }
}

}  // namespace
}  // namespace gjkx::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using gjkx::fuzz::Decoder;
  return gjkx::fuzz::runOneInput(
      data, size, [](Decoder& in) { gjkx::fuzz::run<float>(in); }, [](Decoder& in) { gjkx::fuzz::run<double>(in); });
}
