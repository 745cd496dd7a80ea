// The body-pair query (§6) against brute force: the BVH returns exactly the piece pairs
// of the all-pairs test, front tracking returns the same pairs as a fresh traversal frame
// after frame, and the k-DOP extrusion test never prunes a pair that collides within the
// interval (dense sampling with GJK), for linear and for rotating motion.
#include <gjkx/kdop/body_pair.hpp>
#include <gjkx/mesh/convex_decomposition.hpp>
#include <gjkx/support_mapping/placed.hpp>
#include <gjkx/supporting_distance/intersection.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

using namespace gjkx;

namespace {

// A random nonconvex body: `count` random convex pieces (hulls of 12 points in a ball of
// radius 0.2..0.5) scattered in a ball of radius 2, overlapping like a decomposition's.
template <typename S>
Bvh<S> randomBody(std::mt19937& rng, int count, InnerHulls inner = InnerHulls::every) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Polytope<S>> pieces;
  for (int i = 0; i < count; ++i) {
    const Vector3<S> centre(S(2 * u(rng)), S(2 * u(rng)), S(2 * u(rng)));
    const double size = 0.35 + 0.15 * u(rng);
    std::vector<Vector3<S>> points;
    for (int k = 0; k < 12; ++k) points.push_back(centre + Vector3<S>(S(size * u(rng)), S(size * u(rng)), S(size * u(rng))));
    pieces.push_back(Polytope<S>::hull(points));
  }
  return Bvh<S>(pieces, inner);
}

template <typename S>
Pose<S> randomPose(std::mt19937& rng, double reach) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Pose<S>::fromAxisAngle(Vector3<S>(S(u(rng)), S(u(rng)), S(u(rng) + 1.5)), S(3.1 * u(rng)),
                                Vector3<S>(S(reach * u(rng)), S(reach * u(rng)), S(reach * u(rng))));
}

template <typename S>
Vector3<S> randomVector(std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vector3<S>(S(size * u(rng)), S(size * u(rng)), S(size * u(rng)));
}

}  // namespace

TEMPLATE_TEST_CASE("static query: the BVH returns exactly the pairs of the all-pairs 14-DOP test", "[kdop][body_pair]",
                   float, double) {
  using S = TestType;
  std::mt19937 rng(2024);
  int kept = 0, pruned = 0;
  for (int body = 0; body < 10; ++body) {
    const Bvh<S> a = randomBody<S>(rng, 5 + body * 3), b = randomBody<S>(rng, 4 + body * 2);
    for (int trial = 0; trial < 20; ++trial) {
      const Pose<S> pa = randomPose<S>(rng, 2), pb = randomPose<S>(rng, 3);
      BodyPairQuery<S> query(a, b);
      const auto out = query.queryAt(pa, pb);
      const auto expected = bruteForcePiecePairs(a, Motion<S>::fixed(pa), b, Motion<S>::fixed(pb), S(0), S(0));
      REQUIRE(out.pairs == expected);
      CHECK(out.counters.pairsKept == static_cast<int>(expected.size()));
      CHECK((out.status == BodyPairStatus::Disjoint) == expected.empty());
      kept += static_cast<int>(expected.size());
      pruned += static_cast<int>(a.pieces().size() * b.pieces().size() - expected.size());
    }
  }
  CHECK(kept > 100);    // the cases are not all apart ...
  CHECK(pruned > 100);  // ... nor all overlapping
}

TEMPLATE_TEST_CASE("interval query: the BVH returns exactly the pairs of the all-pairs k-DOP extrusion test",
                   "[kdop][body_pair]", float, double) {
  using S = TestType;
  std::mt19937 rng(99);
  for (int trial = 0; trial < 60; ++trial) {
    const Bvh<S> a = randomBody<S>(rng, 12), b = randomBody<S>(rng, 9);
    const bool turning = trial % 2 == 1;
    const Motion<S> ma = turning ? Motion<S>::screw(randomPose<S>(rng, 2), randomVector<S>(rng, 2), randomVector<S>(rng, 2))
                                 : Motion<S>::constantVelocity(randomPose<S>(rng, 2), randomVector<S>(rng, 3));
    const Motion<S> mb = Motion<S>::constantAcceleration(randomPose<S>(rng, 3), randomVector<S>(rng, 2),
                                                         turning ? randomVector<S>(rng, 5) : Vector3<S>::Zero());
    const auto out = survivingPiecePairs(a, ma, b, mb, S(0), S(0.5));
    REQUIRE(out.pairs == bruteForcePiecePairs(a, ma, b, mb, S(0), S(0.5)));
  }
}

// A hierarchy whose inner nodes keep no hull (a static body's, InnerHulls::none) takes
// each inner node's slab ends from its children: the same pairs as the all-pairs test, at
// one pose and over intervals, turning or not, against a body with or without inner hulls.
TEMPLATE_TEST_CASE("inner nodes without hulls: the BVH still returns exactly the pairs of the all-pairs test",
                   "[kdop][body_pair]", float, double) {
  using S = TestType;
  std::mt19937 rng(4242);
  int kept = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Bvh<S> a = randomBody<S>(rng, 16, InnerHulls::none);
    const Bvh<S> b = randomBody<S>(rng, 9, trial % 3 == 0 ? InnerHulls::none : InnerHulls::every);
    CHECK_FALSE(a.node(Bvh<S>::root()).hasHull());
    const Pose<S> pa = randomPose<S>(rng, 2), pb = randomPose<S>(rng, 3);
    BodyPairQuery<S> still(a, b);
    const auto atPose = still.queryAt(pa, pb);
    REQUIRE(atPose.pairs == bruteForcePiecePairs(a, Motion<S>::fixed(pa), b, Motion<S>::fixed(pb), S(0), S(0)));
    const Motion<S> ma = trial % 2 == 1 ? Motion<S>::fixed(pa) : Motion<S>::screw(pa, randomVector<S>(rng, 2), randomVector<S>(rng, 2));
    const Motion<S> mb = Motion<S>::constantAcceleration(pb, randomVector<S>(rng, 2), randomVector<S>(rng, 5));
    const auto over = survivingPiecePairs(a, ma, b, mb, S(0), S(0.5));
    REQUIRE(over.pairs == bruteForcePiecePairs(a, ma, b, mb, S(0), S(0.5)));
    kept += int(atPose.pairs.size() + over.pairs.size());
  }
  CHECK(kept > 100);
}

// Three bodies, each with one 14-DOP cache (BodyKdops) shared by its two pairs, as the
// world has them: the pairs are queried in turn, sometimes over the same interval (a
// collision's re-checks: same poses, ends read from the other pair), sometimes over a
// shorter one from a later start (a rollback), sometimes with a changed motion. Every
// answer must equal the all-pairs test, and sharing must save support queries.
TEMPLATE_TEST_CASE("shared 14-DOP caches: pairs of one body read each other's slab ends, same answers",
                   "[kdop][body_pair]", float, double) {
  using S = TestType;
  std::mt19937 rng(31);
  const Bvh<S> a = randomBody<S>(rng, 20), b = randomBody<S>(rng, 15), c = randomBody<S>(rng, 12);
  BodyKdops<S> ka(a), kb(b), kc(c);
  BodyPairQuery<S> ab(ka, kb), ac(ka, kc), bc(kb, kc);
  BodyPairQuery<S> abOwn(a, b), acOwn(a, c);  // the same pairs with caches of their own
  CHECK_THROWS_WITH(BodyPairQuery<S>(ka, ka), Catch::Contains("bodyPair"));
  auto motion = [&](double reach) {
    return Motion<S>::screw(randomPose<S>(rng, reach), randomVector<S>(rng, 2), randomVector<S>(rng, 1.5));
  };
  Motion<S> ma = motion(1), mb = motion(2), mc = motion(2);
  long shared = 0, own = 0;
  int kept = 0;
  for (int event = 0; event < 120; ++event) {
    const S t0 = S(0.01) * S(event % 7), t1 = S(0.1);
    if (event % 11 == 10) ma = motion(1);  // a collision gives A a new path
    const auto outAb = ab.query(ma, mb, t0, t1);
    const auto outAc = ac.query(ma, mc, t0, t1);  // A at the same two poses: its ends are read
    const auto outBc = bc.query(mb, mc, t0, t1);
    REQUIRE(outAb.pairs == bruteForcePiecePairs(a, ma, b, mb, t0, t1));
    REQUIRE(outAc.pairs == bruteForcePiecePairs(a, ma, c, mc, t0, t1));
    REQUIRE(outBc.pairs == bruteForcePiecePairs(b, mb, c, mc, t0, t1));
    const auto ownAb = abOwn.query(ma, mb, t0, t1), ownAc = acOwn.query(ma, mc, t0, t1);
    REQUIRE(ownAb.pairs == outAb.pairs);
    REQUIRE(ownAc.pairs == outAc.pairs);
    shared += outAb.counters.supportQueries + outAc.counters.supportQueries;
    own += ownAb.counters.supportQueries + ownAc.counters.supportQueries;
    kept += outAb.counters.pairsKept + outAc.counters.pairsKept + outBc.counters.pairsKept;
  }
  CHECK(kept > 0);
  CHECK(shared < own);
}

TEMPLATE_TEST_CASE("front tracking returns the pairs of a fresh traversal, frame after frame", "[kdop][body_pair]", float,
                   double) {
  using S = TestType;
  std::mt19937 rng(5);
  const Bvh<S> a = randomBody<S>(rng, 40), b = randomBody<S>(rng, 30);
  BodyPairQuery<S> tracked(a, b);
  BodyPairSettings<S> fresh;
  fresh.frontTracking = false;
  BodyPairQuery<S> cold(a, b, fresh);
  // B flies at A, through it and out again, turning, in 200 frames of dt = 0.01.
  const Motion<S> ma = Motion<S>::screw(Pose<S>::identity(), Vector3<S>::Zero(), Vector3<S>(0, 0, S(0.7)));
  const Motion<S> mb = Motion<S>::screw(Pose<S>::translate(Vector3<S>(S(-6), S(0.5), 0)), Vector3<S>(S(6), 0, 0),
                                        Vector3<S>(S(0.4), S(0.3), 0));
  long trackedVisits = 0, coldVisits = 0;
  int climbs = 0;
  for (int frame = 0; frame < 200; ++frame) {
    const S t0 = S(frame) * S(0.01), t1 = t0 + S(0.01);
    const auto warm = tracked.query(ma, mb, t0, t1);
    const auto fresh = cold.query(ma, mb, t0, t1);
    REQUIRE(warm.pairs == fresh.pairs);
    trackedVisits += warm.counters.nodesVisited;
    coldVisits += fresh.counters.nodesVisited;
    climbs += warm.counters.climbs;
  }
  CHECK(climbs > 0);                    // the front climbed back as B left
  CHECK(trackedVisits < coldVisits);    // and it did less work than fresh traversals
}

TEMPLATE_TEST_CASE("the k-DOP extrusion test never prunes a pair that collides within the interval (dense sampling)",
                   "[kdop][body_pair]", float, double) {
  using S = TestType;
  std::mt19937 rng(31);
  BodyPairSettings<S> settings;
  settings.tolerance = S(1e-3);  // prune only pairs apart by more than GJK's collision tolerance
  BodyPairSettings<S> paper = settings;
  paper.variant = ExtrusionVariant::Paper;
  int collidingPairsChecked = 0, missedByPaper = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Bvh<S> a = randomBody<S>(rng, 8), b = randomBody<S>(rng, 8);
    const bool turning = trial % 2 == 1;
    // Turning: a quarter to a whole turn over the interval, plus gravity-like acceleration.
    const Motion<S> ma = turning ? Motion<S>::screw(randomPose<S>(rng, 1), randomVector<S>(rng, 3), randomVector<S>(rng, 6))
                                 : Motion<S>::constantVelocity(randomPose<S>(rng, 1), randomVector<S>(rng, 4));
    const Motion<S> mb = turning ? Motion<S>::constantAcceleration(randomPose<S>(rng, 3), randomVector<S>(rng, 4),
                                                                   randomVector<S>(rng, 10))
                                 : Motion<S>::constantVelocity(randomPose<S>(rng, 3), randomVector<S>(rng, 4));
    const auto out = survivingPiecePairs(a, ma, b, mb, S(0), S(1), settings);
    const auto outPaper = survivingPiecePairs(a, ma, b, mb, S(0), S(1), paper);
    for (int i = 0; i < static_cast<int>(a.pieces().size()); ++i)
      for (int j = 0; j < static_cast<int>(b.pieces().size()); ++j) {
        bool collides = false;
        for (int k = 0; k <= 400 && !collides; ++k) {
          const S t = S(k) / S(400);
          collides = intersect(place(a.pieces()[i], ma.pose(t)), place(b.pieces()[j], mb.pose(t))).status ==
                     IntersectionStatus::Intersecting;
        }
        if (!collides) continue;
        ++collidingPairsChecked;
        const bool kept = std::binary_search(out.pairs.begin(), out.pairs.end(), PiecePair{i, j});
        INFO("trial " << trial << ", pieces " << i << ", " << j << (turning ? ", turning" : ", linear"));
        CHECK(kept);
        if (!std::binary_search(outPaper.pairs.begin(), outPaper.pairs.end(), PiecePair{i, j})) {
          CHECK(turning);  // for linear motion the paper's variant is exact as well
          ++missedByPaper;
        }
      }
  }
  CHECK(collidingPairsChecked > 50);
  // The check can fail: §3's test as stated, run on the turning bodies, does prune pairs that collide.
  CHECK(missedByPaper > 0);
  WARN(collidingPairsChecked << " colliding piece pairs checked; the paper's variant would have pruned " << missedByPaper);
}

TEST_CASE("body-pair query: bad input names the field", "[kdop][body_pair]") {
  std::mt19937 rng(1);
  const Bvh<double> a = randomBody<double>(rng, 3);
  BodyPairQuery<double> query(a, a);
  CHECK_THROWS_WITH(query.query(Motion<double>(), Motion<double>(), 1.0, 0.5), Catch::Contains("bodyPair.t1"));
  CHECK_THROWS_WITH(query.query(Motion<double>(), Motion<double>(), std::nan(""), 0.5), Catch::Contains("bodyPair.t0"));
  BodyPairSettings<double> bad;
  bad.tolerance = -1;
  CHECK_THROWS_WITH(BodyPairQuery<double>(a, a, bad), Catch::Contains("bodyPair.tolerance"));
}

// A random nonconvex closed mesh: a UV sphere whose vertices lie at random radii 0.5..1.5.
TriangleMesh bumpySphere(std::mt19937& rng, int rings, int segments) {
  std::uniform_real_distribution<double> radius(0.5, 1.5);
  TriangleMesh mesh;
  mesh.source = "bumpy sphere";
  mesh.vertices.push_back({0, 0, radius(rng)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments, r = radius(rng);
      mesh.vertices.push_back({r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta)});
    }
  mesh.vertices.push_back({0, 0, -radius(rng)});
  const int south = static_cast<int>(mesh.vertices.size()) - 1;
  auto at = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.push_back({0, at(1, j), at(1, j + 1)});
    mesh.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

TEST_CASE("random meshes through HACD: the BVH equals brute force at random poses and over random motions",
          "[kdop][body_pair][mesh]") {
  std::mt19937 rng(77);
  for (int m = 0; m < 3; ++m) {
    const TriangleMesh a = bumpySphere(rng, 10, 16), b = bumpySphere(rng, 8, 12);
    validateMesh(a, {true});  // closed, outward: a real solid
    DecompositionSettings settings;
    settings.concavity = 20;  // many pieces, a deep tree
    const Bvh<double> bodyA(decompose(a, settings, "").polytopes<double>());
    const Bvh<double> bodyB(decompose(b, settings, "").polytopes<double>());
    CHECK(bodyA.pieces().size() > 3);
    int kept = 0;
    for (int trial = 0; trial < 30; ++trial) {
      const Motion<double> ma = Motion<double>::screw(randomPose<double>(rng, 0.5), randomVector<double>(rng, 1),
                                                      randomVector<double>(rng, 2));
      const Motion<double> mb = Motion<double>::constantVelocity(randomPose<double>(rng, 2.5), randomVector<double>(rng, 2));
      const auto expected = bruteForcePiecePairs(bodyA, ma, bodyB, mb, 0.0, 0.25);
      REQUIRE(survivingPiecePairs(bodyA, ma, bodyB, mb, 0.0, 0.25).pairs == expected);
      BodyPairQuery<double> at(bodyA, bodyB);
      REQUIRE(at.queryAt(ma.pose(0), mb.pose(0)).pairs ==
              bruteForcePiecePairs(bodyA, Motion<double>::fixed(ma.pose(0)), bodyB, Motion<double>::fixed(mb.pose(0)), 0.0, 0.0));
      kept += static_cast<int>(expected.size());
    }
    CHECK(kept > 0);
  }
}

TEST_CASE("a real mesh (Wuson, assimp-testmodels) against itself: BVH equals brute force at random poses",
          "[kdop][body_pair][mesh]") {
  const std::string path = "/usr/share/assimp/models/STL/Wuson.stl";
  if (!std::filesystem::exists(path)) {
    WARN("skipped: " << path << " is absent (Debian package assimp-testmodels, see cmake/install-deps.sh)");
    return;
  }
  const auto decomposition = decompose(readMesh(path));
  const Bvh<double> body(decomposition.polytopes<double>());
  std::mt19937 rng(11);
  int kept = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Pose<double> pa = randomPose<double>(rng, 0.3), pb = randomPose<double>(rng, 0.8);
    BodyPairQuery<double> query(body, body);
    const auto out = query.queryAt(pa, pb);
    REQUIRE(out.pairs == bruteForcePiecePairs(body, Motion<double>::fixed(pa), body, Motion<double>::fixed(pb), 0.0, 0.0));
    kept += out.counters.pairsKept;
  }
  CHECK(kept > 0);
}

// A traversal and a front update, step by step, on a hierarchy small enough to follow.
// Body A: two unit cubes (as polytopes), piece 0 centred at the origin, piece 1 at
// (4, 0, 0); its BVH is a root (node 0, their hull: x in [-0.5, 4.5], y and z in
// [-0.5, 0.5]) over two leaves. Body B: one unit cube, a leaf. The 14-DOP's slabs 0, 1, 2
// are x, y, z; a front node's side 2k says "B above A along slab k", 2k + 1 "A above B".
//  1. B at (0, 2, 0): the root pair is apart along y (B's y from 1.5, A's up to 0.5: a gap
//     of 1, side 2). The traversal stops there: 1 node visited, the front is that node,
//     no piece pair survives.
//  2. B at (0, 0.8, 0): the front node (root, B) is no longer apart: it is opened on A's
//     side (B is a leaf): (leaf of piece 0, B) overlaps on every slab, a surviving pair
//     (0, 0); (leaf of piece 1, B) is apart along x (A's piece from 3.5, B's up to 0.5: A
//     above B, side 1). 3 nodes visited; the front is those two leaves.
//  3. B at (0, 2, 0) again: the front's two nodes are tested (piece 0's now apart along y,
//     side 2; piece 1's still along x, its side tried first), both apart with one parent,
//     so the front climbs back: the root pair is tested (apart along y) and replaces them.
//     3 nodes visited, 1 climb, the front is the root pair again, as in 1.
TEST_CASE("a traversal and a front update, step by step, on a two-piece hierarchy", "[kdop][body_pair][steps]") {
  using V = Vector3<double>;
  std::vector<V> corners;
  for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5);
  const Polytope<double> cube = Polytope<double>::hull(corners);
  std::vector<V> shifted;
  for (const V& c : corners) shifted.push_back(c + V(4, 0, 0));
  const Bvh<double> A({cube, Polytope<double>::hull(shifted)});
  const Bvh<double> B({cube});
  REQUIRE(A.nodes().size() == 3);
  const int leaf0 = A.node(0).left, leaf1 = A.node(0).right;
  REQUIRE(A.node(leaf0).piece == 0);
  REQUIRE(A.node(leaf1).piece == 1);
  BodyPairQuery<double> query(A, B);
  const Pose<double> still = Pose<double>::identity();

  const auto first = query.queryAt(still, Pose<double>::translate(V(0, 2, 0)));
  CHECK(first.status == BodyPairStatus::Disjoint);
  CHECK(first.counters.nodesVisited == 1);
  REQUIRE(query.front().size() == 1);
  CHECK(query.front()[0].a == Bvh<double>::root());
  CHECK(query.front()[0].disjoint);
  CHECK(query.front()[0].slab == 2);

  const auto second = query.queryAt(still, Pose<double>::translate(V(0, 0.8, 0)));
  CHECK(second.status == BodyPairStatus::PairsKept);
  REQUIRE(second.pairs.size() == 1);
  CHECK(second.pairs[0] == PiecePair{0, 0});
  CHECK(second.counters.nodesVisited == 3);
  REQUIRE(query.front().size() == 2);
  CHECK(query.front()[0].a == leaf0);
  CHECK_FALSE(query.front()[0].disjoint);
  CHECK(query.front()[1].a == leaf1);
  CHECK(query.front()[1].disjoint);
  CHECK(query.front()[1].slab == 1);

  const auto third = query.queryAt(still, Pose<double>::translate(V(0, 2, 0)));
  CHECK(third.status == BodyPairStatus::Disjoint);
  CHECK(third.counters.nodesVisited == 3);
  CHECK(third.counters.climbs == 1);
  REQUIRE(query.front().size() == 1);
  CHECK(query.front()[0].a == Bvh<double>::root());
  CHECK(query.front()[0].slab == 2);
}

// A simulation asks one body pair two questions on one front: which pieces may come within
// its collisions' tolerance over an interval, and which lie within a wider contact band at
// the interval's start. Alternating the two, each answer is the all-pairs test's at that
// query's tolerance, and a pair between the two tolerances is kept by the wide one only.
TEMPLATE_TEST_CASE("a tolerance per query: each answer is the all-pairs test's at that tolerance, on one front",
                   "[kdop][body_pair]", float, double) {
  using S = TestType;
  std::mt19937 rng(77);
  const S narrow = S(0.01), wide = S(0.3);
  int between = 0;
  for (int body = 0; body < 6; ++body) {
    const Bvh<S> a = randomBody<S>(rng, 6 + body), b = randomBody<S>(rng, 5 + body);
    BodyPairSettings<S> settings;
    settings.tolerance = narrow;
    BodyPairQuery<S> query(a, b, settings);
    Pose<S> pa = randomPose<S>(rng, 2), pb = randomPose<S>(rng, 3);
    for (int frame = 0; frame < 15; ++frame) {
      const Motion<S> ma = Motion<S>::screw(pa, randomVector<S>(rng, 0.2), randomVector<S>(rng, 0.3));
      const Motion<S> mb = Motion<S>::screw(pb, randomVector<S>(rng, 0.2), randomVector<S>(rng, 0.3));
      BodyPairSettings<S> wideSettings = settings;
      wideSettings.tolerance = wide;
      const auto atStart = query.query(ma, mb, S(0), S(0), wide);
      REQUIRE(atStart.pairs == bruteForcePiecePairs(a, ma, b, mb, S(0), S(0), wideSettings));
      const auto swept = query.query(ma, mb, S(0), S(1));
      REQUIRE(swept.pairs == bruteForcePiecePairs(a, ma, b, mb, S(0), S(1), settings));
      const auto narrowAtStart = bruteForcePiecePairs(a, ma, b, mb, S(0), S(0), settings);
      between += int(atStart.pairs.size() - narrowAtStart.size());
      pa = ma.pose(S(1));
      pb = mb.pose(S(1));
    }
  }
  CHECK(between > 0);  // some pairs lie between the two tolerances
  BodyPairQuery<S> query(randomBody<S>(rng, 3), randomBody<S>(rng, 3));
  CHECK_THROWS_WITH(query.query(Motion<S>(), Motion<S>(), S(0), S(0), S(-1)), Catch::Contains("bodyPair.tolerance"));
}
