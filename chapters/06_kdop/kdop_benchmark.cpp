// The body-pair query of chapter 06 (§6) against FCL's own BVH collision on the same
// meshes: mesh against mesh at many poses, and over a sequence of frames with and without
// generalized front tracking. Prints, from one run:
//   RATIO kdop_query_<mesh> ours_vs_fcl=X fcl=<BV>     (our median time / FCL's faster BV, <1: ours faster)
//   RATIO kdop_front_<sequence>_<mesh> cold_vs_warm=X   (fresh traversal / front-tracked frame, >1: tracking pays)
// Times are medians of repeated passes (plain timing loop, std::chrono::steady_clock).
//
// What each side does. Ours: the piece pairs of two decomposed bodies whose 14-DOPs
// overlap (the BVH of convex pieces, exact 14-DOPs by support mapping), i.e. the pairs the
// time-of-impact solver would get. FCL: fcl::collide on fcl::BVHModel<OBBRSSd> and
// <KDOPd<16>> of the meshes' triangles, all contacts (num_max_contacts large, no contact
// points), the same exhaustive question at triangle level. Both are "which parts may
// touch"; FCL's answer is finer (triangles) and ours coarser (convex pieces, then GJK).
#include "../command_line.hpp"
#include "meshes.hpp"

#include <gjkx/kdop/body_pair.hpp>

#ifdef GJKX_HAVE_FCL
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/narrowphase/collision.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>

using namespace gjkx;

namespace {

// Median over `repeats` passes of `pass()`, in microseconds per query.
double medianMicros(int repeats, int queries, const std::function<void()>& pass) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    pass();
    times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / queries);
  }
  std::nth_element(times.begin(), times.begin() + repeats / 2, times.end());
  return times[repeats / 2];
}

#ifdef GJKX_HAVE_FCL
template <typename BV>
std::shared_ptr<fcl::BVHModel<BV>> fclModel(const TriangleMesh& mesh) {
  auto model = std::make_shared<fcl::BVHModel<BV>>();
  std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

fcl::Transform3d fclTransform(const Pose<double>& pose) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.linear() = pose.rotation;
  tf.translation() = pose.translation;
  return tf;
}

template <typename BV>
double timeFcl(const TriangleMesh& mesh, const std::vector<std::pair<Pose<double>, Pose<double>>>& poses, int repeats,
               long& contacts) {
  const auto model = fclModel<BV>(mesh);
  fcl::CollisionObjectd a(model), b(model);
  fcl::CollisionRequestd request(1000000, false);
  return medianMicros(repeats, static_cast<int>(poses.size()), [&] {
    contacts = 0;
    for (const auto& [pa, pb] : poses) {
      a.setTransform(fclTransform(pa));
      b.setTransform(fclTransform(pb));
      fcl::CollisionResultd result;
      fcl::collide(&a, &b, request, result);
      contacts += static_cast<long>(result.numContacts());
    }
  });
}
#endif

}  // namespace

int main(int argc, char** argv) {
  int repeats = 11, poseCount = 200, frames = 400;
  CLI::App app{"Chapter 06: the body-pair query against FCL's BVH collision, and front tracking's speed-up."};
  app.add_option("--repeats", repeats, "timed passes per measurement (the median is printed)")->capture_default_str();
  app.add_option("--poses", poseCount, "random pose pairs per mesh")->capture_default_str();
  app.add_option("--frames", frames, "frames of the front-tracking sequence")->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  if (repeats < 1 || poseCount < 1 || frames < 1) {
    std::fprintf(stderr, "kdop_benchmark: --repeats, --poses and --frames must be positive\n");
    return chapter::kUsageError;
  }

  for (const auto& [name, mesh] : chapter::chapterMeshes()) {
    const ConvexDecomposition d = decompose(mesh);
    const Bvh<double> body(d.polytopes<double>());
    double size = 0;
    for (const auto& node : body.nodes()) size = std::max(size, node.hull->boundingRadius());
    std::printf("\n== %s: %zu triangles, %d convex pieces (HACD%s), volume excess %.1f%%, BVH of %zu nodes, height %d ==\n",
                name.c_str(), mesh.triangles.size(), d.report.pieces, d.report.fromCache ? ", cached" : "",
                100 * d.report.volumeExcess, body.nodes().size(), body.height());

    // Static poses: B within reach of A, both turned at random (seeded: the same every run).
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<std::pair<Pose<double>, Pose<double>>> poses;
    for (int i = 0; i < poseCount; ++i) {
      const auto turn = [&] { return Pose<double>::fromAxisAngle({u(rng), u(rng), u(rng) + 1e-3}, M_PI * u(rng), {0, 0, 0}); };
      Pose<double> pa = turn(), pb = turn();
      pb.translation = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized() * size * (1.0 + 0.8 * u(rng));
      poses.push_back({pa, pb});
    }
    BodyPairSettings<double> coldSettings;
    coldSettings.frontTracking = false;
    BodyPairQuery<double> cold(body, body, coldSettings);
    long pairs = 0, visited = 0;
    const double ours = medianMicros(repeats, poseCount, [&] {
      pairs = visited = 0;
      for (const auto& [pa, pb] : poses) {
        const auto out = cold.queryAt(pa, pb);
        pairs += out.counters.pairsKept;
        visited += out.counters.nodesVisited;
      }
    });
    std::printf("static poses (%d): ours %.2f us/query (%.1f piece pairs kept, %.1f BVTT nodes visited per query)\n",
                poseCount, ours, double(pairs) / poseCount, double(visited) / poseCount);
#ifdef GJKX_HAVE_FCL
    long contactsObb = 0, contactsKdop = 0;
    const double obbrss = timeFcl<fcl::OBBRSSd>(mesh, poses, repeats, contactsObb);
    const double kdop16 = timeFcl<fcl::KDOPd<16>>(mesh, poses, repeats, contactsKdop);
    std::printf("static poses (%d): FCL OBBRSS %.2f us/query, FCL KDOP<16> %.2f us/query (%.1f triangle contacts per query)\n",
                poseCount, obbrss, kdop16, double(contactsObb) / poseCount);
    const bool obbFaster = obbrss <= kdop16;
    std::printf("RATIO kdop_query_%s ours_vs_fcl=%.3f fcl=%s\n", name.c_str(), ours / std::min(obbrss, kdop16),
                obbFaster ? "OBBRSS" : "KDOP16");
#else
    std::printf("FCL not found: no comparison (cmake/peers.cmake)\n");
#endif

    // Two sequences of frames, each frame an interval query over [t, t + dt]. "passing": A
    // turns in place, B drifts through it, turning (about 0.3% of the size a frame).
    // "resting": B lies against A and sways a little (0.02% of the size a frame), the case
    // front tracking is made for.
    // Where B first touches A coming in along -x (its pieces' 14-DOPs meet), less 2% of the size.
    double touching = 2 * size;
    while (touching > 0 &&
           survivingPiecePairs(body, Motion<double>::fixed(Pose<double>::translate({touching, 0.2 * size, 0})), body,
                               Motion<double>(), 0.0, 0.0)
               .pairs.empty())
      touching -= 0.01 * size;
    touching -= 0.02 * size;
    struct Sequence {
      const char* name;
      Motion<double> a, b;
    };
    const Sequence sequences[] = {
        {"passing", Motion<double>::screw(Pose<double>::identity(), {0, 0, 0}, {0, 0, 0.6}),
         Motion<double>::screw(Pose<double>::translate({-1.2 * size, 0.3 * size, 0}), {1.2 * size, 0, 0}, {0.3, 0.5, 0})},
        {"resting", Motion<double>::fixed(Pose<double>::identity()),
         Motion<double>::screw(Pose<double>::translate({touching, 0.2 * size, 0}), {-0.08 * size, 0, 0}, {0, 0, 0.08})},
    };
    const double dt = 1.0 / frames;
    for (const auto& sequence : sequences) {
      BodyPairQuery<double> fresh(body, body, coldSettings);
      BodyPairQuery<double> tracked(body, body);
      long coldVisited = 0, warmVisited = 0, front = 0, kept = 0, coldSupports = 0, warmSupports = 0;
      const double coldTime = medianMicros(repeats, frames, [&] {
        coldVisited = coldSupports = kept = 0;
        for (int f = 0; f < frames; ++f) {
          const auto out = fresh.query(sequence.a, sequence.b, f * dt, (f + 1) * dt);
          coldVisited += out.counters.nodesVisited;
          coldSupports += out.counters.supportQueries;
          kept += out.counters.pairsKept;
        }
      });
      const double warmTime = medianMicros(repeats, frames, [&] {
        tracked.resetFront();
        warmVisited = warmSupports = front = 0;
        for (int f = 0; f < frames; ++f) {
          const auto out = tracked.query(sequence.a, sequence.b, f * dt, (f + 1) * dt);
          warmVisited += out.counters.nodesVisited;
          warmSupports += out.counters.supportQueries;
          front += out.counters.frontSize;
        }
      });
      std::printf("%s (%d frames, %.1f pairs kept): fresh traversal %.2f us/frame (%.1f nodes, %.0f supports), "
                  "front tracking %.2f us/frame (%.1f nodes, %.0f supports, front %.1f)\n",
                  sequence.name, frames, double(kept) / frames, coldTime, double(coldVisited) / frames,
                  double(coldSupports) / frames, warmTime, double(warmVisited) / frames, double(warmSupports) / frames,
                  double(front) / frames);
      std::printf("RATIO kdop_front_%s_%s cold_vs_warm=%.3f\n", sequence.name, name.c_str(), coldTime / warmTime);
    }
  }
  return 0;
}
