// The time-of-impact solver of §5 on random workloads, against an independent reference
// (toi_test_support.hpp):
//  - random linear motions (both bodies at constant velocity; boxes, spheres, capsules
//    and random polytopes; float and double): zero misses, and every reported time is
//    early enough and free of interpenetration;
//  - random screw motions (up to a half turn per interval), where the certified variant
//    must not miss and the paper's variant's misses are counted;
//  - temporal coherence: warm queries give the cold verdicts for less work.
// The hand-checked and hard cases are in test_time_of_impact.cpp.
#include "toi_test_support.hpp"

#include <gjkx/brent/time_of_impact.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/support_mapping/shape.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace gjkx;
using namespace gjkx::toi_test;

// =======================================================================================
// Random linear motions against the reference.

// Constant velocities (no rotation, arbitrary fixed orientations), both bodies moving; the
// shapes boxes, spheres, capsules and random polytopes. 400 aimed pairs plus 1200 grazing
// pairs, whose closest approach is moved to between 0.05 and 3 tolerances (shifting Q's
// whole path along the closest direction at the time of closest approach). No miss is
// allowed; every hit must come no later than the reference's first time within tol/2
// (plus the time tolerance), at a time where the bodies do not interpenetrate and are
// within the tolerance plus what they can move in one time tolerance.
TEMPLATE_TEST_CASE("random linear motions: no misses against the reference", "[toi][random][linear]", float,
                   double) {
  using S = TestType;
  std::mt19937 rng(sizeof(S) == sizeof(float) ? 20240611u : 20240612u);
  std::uniform_real_distribution<double> u(0, 1);
  const ToiSettings<S> settings;
  const double tol = settings.collisionTolerance, timeTol = settings.timeTolerance;
  Stats aimedStats, grazingStats;
  aimedStats.workload = std::string("linear-") + scalarName<S>();
  grazingStats.workload = std::string("linear-grazing-") + scalarName<S>();
  int grazingMade = 0, aimed = 0;
  double worstLate = -1, worstHitDistance = 0;

  const int kAimed = 400, kGrazing = 1200;
  while (aimed + grazingMade < kAimed + kGrazing) {
    PairSpec pair = randomPair(rng, 0.0);
    const Bounds bounds = boundsOf(pair);
    const double hi = 2 * tol + 2 * bounds.V * timeTol;
    const double lo = tol / 2, gap = tol / 16;
    Body refP = referenceBody(pair.P), refQ = referenceBody(pair.Q);
    const bool wantGrazing = aimed >= kAimed;
    if (wantGrazing) {
      // Move the closest approach to `target`: find it, then shift Q's path along the
      // closest direction (which changes the distance at that time by exactly the shift).
      const Sample closest = closestApproach(refP, refQ);
      if (!(closest.upper > 0) || closest.t < 0.05 || closest.t > 0.95) continue;
      // Two thirds pass within half the tolerance (must be reported), a third between
      // half and three tolerances (mostly the band where either answer will do).
      const double target = grazingMade % 3 != 2 ? tol * (0.05 + 0.5 * u(rng)) : tol * (0.55 + 2.45 * u(rng));
      pair.Q.start.translation += (target - closest.upper) * closest.closest;
      refQ = referenceBody(pair.Q);
    }
    // Queries start apart (starting inside the tolerance is a hard case of its own).
    if (sampleAt(refP, refQ, 0).lower <= 4 * hi) continue;
    (wantGrazing ? grazingMade : aimed) += 1;

    const Reference ref = classify(refP, refQ, 0, 1, bounds, lo, hi, gap);
    const auto P = makeBody<S>(pair.P);
    const auto Q = makeBody<S>(pair.Q);
    const ToiResult<S> r = timeOfImpact(P, Q, S(0), S(1), settings);
    Stats& stats = wantGrazing ? grazingStats : aimedStats;
    stats.add(r);
    INFO(stats.workload << " pair " << stats.queries << " (" << kindName(pair.P.kind) << ", "
                        << kindName(pair.Q.kind) << (wantGrazing ? ", grazing" : "") << "): reference "
                        << toString(ref.verdict) << " min distance in [" << ref.minLower << ", " << ref.minUpper
                        << "] at t = " << ref.tMin << "; solver " << toString(r.status) << " at " << r.time
                        << ", distance " << r.distance << ", brent " << r.brentIterations);
    switch (ref.verdict) {
      case Verdict::Contact: ++stats.contact; break;
      case Verdict::Clear: ++stats.clear; break;
      case Verdict::Grazing: ++stats.grazing; break;
    }
    CHECK(r.status != ToiStatus::NumericalFailure);
    CHECK(r.status != ToiStatus::StartsPenetrating);  // they start apart
    if (ref.verdict == Verdict::Contact && saysNoCollision(r.status)) ++stats.misses;
    if (ref.verdict == Verdict::Clear && reportsCollision(r.status)) ++stats.falseAlarms;
    CHECK_FALSE((ref.verdict == Verdict::Contact && saysNoCollision(r.status)));  // a miss
    CHECK_FALSE((ref.verdict == Verdict::Clear && r.status == ToiStatus::Hit));   // a false alarm

    if (r.status == ToiStatus::Hit) {
      const double T = double(r.time);
      worstHitDistance = std::max(worstHitDistance, checkHit(r, P, Q, refP, refQ, bounds, tol, timeTol));
      if (ref.verdict == Verdict::Contact) {
        const double tFirst = firstTimeWithin(refP, refQ, 0, ref.tMin, lo);
        INFO("first time within tol/2: " << tFirst);
        CHECK(T <= tFirst + timeTol);
        worstLate = std::max(worstLate, (T - tFirst) / timeTol);
      }
    }
  }
  aimedStats.print();
  grazingStats.print();
  std::cout << "TOI linear-" << scalarName<S>() << ": worst (T - t_first(tol/2))/timeTol = " << worstLate
            << ", worst distance at a hit / tol = " << worstHitDistance << "\n";
  CHECK(aimedStats.misses + grazingStats.misses == 0);
  CHECK(aimedStats.contact > 100);                      // the workload does collide...
  CHECK(aimedStats.clear > 100);                        // ...and does miss
  CHECK(grazingStats.grazing + aimedStats.grazing > 20);  // and grazes
}

// =======================================================================================
// Random screw motions: the certified variant must not miss; the paper's variant's
// misses are counted (§3: "these errors are the result of second order motion").
// 300 aimed pairs (as in the linear test, each body also turning at up to π per unit
// interval) and 200 spinning neighbours (see spinningPair), against the same reference,
// whose second-order bound uses D = w_P^2 r_P + w_Q^2 r_Q computed here. Every certified hit
// must also satisfy checkHit, and the reference must find no interpenetration before it.

TEMPLATE_TEST_CASE("random screw motions: the certified variant never misses", "[toi][random][screw]", float,
                   double) {
  using S = TestType;
  std::mt19937 rng(sizeof(S) == sizeof(float) ? 7771u : 7772u);
  ToiSettings<S> certifiedSettings;
  certifiedSettings.variant = ExtrusionVariant::Certified;
  ToiSettings<S> paperSettings;
  paperSettings.variant = ExtrusionVariant::Paper;
  const double tol = certifiedSettings.collisionTolerance, timeTol = certifiedSettings.timeTolerance;
  Stats certified, paper;
  certified.workload = std::string("screw-certified-") + scalarName<S>();
  paper.workload = std::string("screw-paper-") + scalarName<S>();
  int paperMissesOfContacts = 0;

  const int kAimed = 300, kSpinning = 200, kPairs = kAimed + kSpinning;
  int made = 0;
  while (made < kPairs) {
    // Up to a half turn per unit interval: aimed pairs first, then spinning neighbours.
    const PairSpec pair = made < kAimed ? randomPair(rng, kPi) : spinningPair(rng, kPi);
    const Bounds bounds = boundsOf(pair);
    const double hi = 2 * tol + 2 * bounds.V * timeTol;
    const Body refP = referenceBody(pair.P), refQ = referenceBody(pair.Q);
    if (sampleAt(refP, refQ, 0).lower <= 4 * hi) continue;
    ++made;
    const Reference ref = classify(refP, refQ, 0, 1, bounds, tol / 2, hi, tol / 16);
    const auto P = makeBody<S>(pair.P);
    const auto Q = makeBody<S>(pair.Q);
    // The library's acceleration bound is the one derived here (w^2 r for a screw).
    CHECK(double(P.accelerationBound() + Q.accelerationBound()) == Approx(bounds.D).epsilon(1e-5).margin(1e-6));

    const ToiResult<S> c = timeOfImpact(P, Q, S(0), S(1), certifiedSettings);
    const ToiResult<S> p = timeOfImpact(P, Q, S(0), S(1), paperSettings);
    certified.add(c);
    paper.add(p);
    INFO(certified.workload << " pair " << made << " (" << kindName(pair.P.kind) << ", " << kindName(pair.Q.kind)
                            << "): reference " << toString(ref.verdict) << " min distance in [" << ref.minLower
                            << ", " << ref.minUpper << "] at t = " << ref.tMin << "; certified "
                            << toString(c.status) << " at " << c.time << " (brent " << c.brentIterations
                            << "), paper " << toString(p.status));
    for (Stats* s : {&certified, &paper}) {
      switch (ref.verdict) {
        case Verdict::Contact: ++s->contact; break;
        case Verdict::Clear: ++s->clear; break;
        case Verdict::Grazing: ++s->grazing; break;
      }
    }
    if (ref.verdict == Verdict::Contact) {
      certified.misses += saysNoCollision(c.status);
      paper.misses += saysNoCollision(p.status);
      paperMissesOfContacts += saysNoCollision(p.status);
    }
    if (ref.verdict == Verdict::Clear) {
      certified.falseAlarms += reportsCollision(c.status);
      paper.falseAlarms += reportsCollision(p.status);
    }
    CHECK_FALSE((ref.verdict == Verdict::Contact && saysNoCollision(c.status)));  // a certified miss
    CHECK_FALSE((ref.verdict == Verdict::Clear && c.status == ToiStatus::Hit));   // a certified false alarm
    CHECK(c.status != ToiStatus::NumericalFailure);
    if (c.status == ToiStatus::Hit) {
      const double T = double(c.time);
      checkHit(c, P, Q, refP, refQ, bounds, tol, timeTol);
      // And no interpenetration anywhere before it (up to the time tolerance).
      if (T - timeTol > 0) {
        const Reference before = classify(refP, refQ, 0, T - timeTol, bounds, 0.0, 0.0, 0.0);
        CHECK(before.verdict != Verdict::Contact);
      }
    }
  }
  certified.print();
  paper.print();
  std::cout << "paper variant misses on rotating motion: " << paperMissesOfContacts << " of " << certified.contact
            << " colliding pairs (" << kPairs << " pairs, " << scalarName<S>() << ")\n";
  INFO("paper variant misses on rotating motion: " << paperMissesOfContacts << " of " << certified.contact);
  CHECK(certified.misses == 0);
  CHECK(paperMissesOfContacts >= 0);  // counted, not asserted: §3 expects some
  CHECK(paper.queries == kPairs);
  CHECK(certified.contact > 50);
  CHECK(certified.clear > 50);
  // Brent creep (time_of_impact.hpp): under rotation each restart at F's root closed only
  // a fixed fraction of the gap to the contact. Before the probe at the distance's
  // parabola these pairs took 9.8 Brent iterations a query in double (both variants) and
  // 5.4 in float; with it 6.6 and 4.7. The bound fails for the old solver.
  const double brentMean = double(certified.brentTotal + paper.brentTotal) / (certified.queries + paper.queries);
  INFO("Brent iterations per query, both variants: " << brentMean);
  CHECK(brentMean <= (sizeof(S) == sizeof(float) ? 5.0 : 7.5));
}

// =======================================================================================
// The field's hard cases.

// Starting within the tolerance: moving apart is "separating" (no new contact, not a hit);
// approaching, or overlapping, is "starts penetrating" at t0.
// Temporal coherence (§2): a query that starts where the pair's last one ended (the
// `coherence` cache) must give the verdict a cold query gives, and do less work where the
// paper expects it to, when "the states of P and Q do not change much between queries".
// The case that dominates a settling scene: a small body resting or sliding just above a
// large flat one (a bone on the floor), the closest direction far from the centre-to-centre
// one a cold GJK starts from. 150 random shapes, 0 to 0.05 above a 6 x 6 slab, each
// sliding at up to 0.5 and turning at up to 1 radian per unit time while it falls at up to
// 0.1, queried on 32 consecutive intervals [k/32, (k+1)/32] with one cache carried through,
// and again cold. Every interval's verdict (collision or none) must agree, a hit's time
// must agree to the time tolerance (both bracket the same first contact), and the warm
// queries must evaluate clearly fewer supporting distances. (Where the bodies move by their
// size between queries, the last query's simplex is stale and buys nothing: on pairs
// aimed at each other and queried on 8 intervals the warm queries did 4-7% more work.)
TEMPLATE_TEST_CASE("temporal coherence: warm queries give the cold verdicts for less work", "[toi][random][coherence]",
                   float, double) {
  using S = TestType;
  std::mt19937 rng(sizeof(S) == sizeof(float) ? 20261125u : 20261126u);
  std::uniform_real_distribution<double> u(0, 1);
  ToiSettings<S> settings;
  settings.variant = ExtrusionVariant::Certified;
  BodySpec slab;
  slab.kind = 0;
  slab.halfExtents = Eigen::Vector3d(3, 3, 0.05);
  slab.boundingRadius = slab.halfExtents.norm();
  const auto P = makeBody<S>(slab);
  long warmWork = 0, coldWork = 0, hits = 0, intervals = 0;
  constexpr int kIntervals = 32;
  for (int n = 0; n < 150; ++n) {
    BodySpec body = randomShape(rng);
    // Its lowest point 0 to 0.05 above the slab's top (z = 0.05) at t = 0.
    const double lowest = body.kind == 1 ? body.radius : body.boundingRadius;
    body.start.translation = Eigen::Vector3d(4 * u(rng) - 2, 4 * u(rng) - 2, 0.05 + lowest + 0.05 * u(rng));
    body.velocity = Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, -0.1 * u(rng));
    body.angularVelocity = randomUnit(rng) * u(rng);
    const auto Q = makeBody<S>(body);
    ExtrusionCache<S> carried;
    for (int k = 0; k < kIntervals; ++k) {
      const S t0 = S(k) / S(kIntervals), t1 = S(k + 1) / S(kIntervals);
      const ToiResult<S> warm = timeOfImpact(P, Q, t0, t1, settings, nullptr, &carried);
      const ToiResult<S> cold = timeOfImpact(P, Q, t0, t1, settings);
      INFO("body " << n << " (" << kindName(body.kind) << "), interval " << k << ": warm " << toString(warm.status)
                   << " at " << warm.time << ", cold " << toString(cold.status) << " at " << cold.time);
      ++intervals;
      warmWork += warm.sdEvaluations;
      coldWork += cold.sdEvaluations;
      CHECK(saysNoCollision(warm.status) == saysNoCollision(cold.status));
      if (warm.status == ToiStatus::Hit && cold.status == ToiStatus::Hit) {
        ++hits;
        CHECK(std::abs(double(warm.time - cold.time)) <= 2 * double(settings.timeTolerance * (t1 - t0)) + 1e-6);
      }
      if (!saysNoCollision(cold.status)) break;  // they met: a simulation would resolve it here
    }
  }
  std::cout << "TOI coherence-" << scalarName<S>() << ": " << intervals << " intervals, " << hits
            << " hits; supporting distances warm " << warmWork << ", cold " << coldWork << "\n";
  CHECK(hits > 20);
  CHECK(double(warmWork) < 0.8 * double(coldWork));
}