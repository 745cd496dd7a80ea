// libFuzzer target: GJK (§2.2) on a pair of placed shapes, cold and then warm-started,
// distance and boolean queries, in float or double. Every result is held to the
// brute-force signed distance of fuzz_common.hpp: a Separated distance within the slack,
// Overlapping only when the reference says the shapes are within the slack, a
// separating vector only above its threshold, the lower bound never above the
// distance, no NaN anywhere, and no NumericalFailure on finite input.
// GJKX_FUZZ_VERBOSE=1 prints each run's iterations.
#include "fuzz_common.hpp"

namespace gjkx::fuzz {
namespace {

template <typename S>
GjkSettings<S> decodeSettings(Decoder& in) {
  GjkSettings<S> settings;
  switch (in.pick(4)) {
    case 0: break;                                   // closest distance
    case 1: settings.separationThreshold = S(0); break;  // boolean query
    case 2: settings.separationThreshold = S(in.number(in.scale())); break;
    default: settings.initialDirection = toS<S>(in.vector(in.scale())); break;
  }
  return settings;
}

template <typename S>
void run(Decoder& in) {
  const Shape<S> shapeP = decodeShape<S>(in);
  const Shape<S> shapeQ = decodeShape<S>(in);
  const Pose<S> poseP = decodePose<S>(in), poseQ = decodePose<S>(in);
  const GjkSettings<S> settings = decodeSettings<S>(in);

  auto check = [&](const Pose<S>& p, const Pose<S>& q, GjkCache<S>* cache, const char* what) {
    const Cloud a = cloudOf(shapeP, p), b = cloudOf(shapeQ, q);
    const Real ref = signedDistance(a, b);
    const Real extent = std::max(a.extent(), b.extent());
    // Rounded shapes run on their cores (exact, like polytopes) unless told otherwise.
    const bool rounded = (a.radius > 0 || b.radius > 0) && !settings.roundedCores;
    context() = std::string(sizeof(S) == 4 ? "float " : "double ") + what + " P " + describe(a) + " Q " + describe(b);
    if (std::getenv("GJKX_FUZZ_VERBOSE")) {  // the run's trace, from a copy of the cache
      GjkCache<S> copy;
      if (cache) copy = *cache;
      GjkTrace<S> trace;
      gjk(place(shapeP, p), place(shapeQ, q), settings, cache ? &copy : nullptr, trace);
      for (const GjkIteration<S>& it : trace.iterations) {
        std::fprintf(stderr, "gjk %s: i %d p (%.17g %.17g %.17g) q (%.17g %.17g %.17g) sd %.17g md %.17g step %d simplex",
                     what, it.i, double(it.supportP.x()), double(it.supportP.y()), double(it.supportP.z()),
                     double(it.supportQ.x()), double(it.supportQ.y()), double(it.supportQ.z()),
                     double(it.supportingDistance), double(it.minkowskiDistance), int(it.step));
        for (int k = 0; k < it.simplex.size; ++k)
          std::fprintf(stderr, " (%.17g %.17g %.17g)", double(it.simplex.vertices[k].w.x()),
                       double(it.simplex.vertices[k].w.y()), double(it.simplex.vertices[k].w.z()));
        std::fprintf(stderr, "\n");
      }
    }
    const GjkResult<S> r = gjk(place(shapeP, p), place(shapeQ, q), settings, cache);
    checkGjk(r, settings, ref, extent, rounded, what);
    // The same pair the other way round: the same answer (the distance is symmetric).
    if (r.status == GjkStatus::Separated) {
      const GjkResult<S> back = gjk(place(shapeQ, q), place(shapeP, p), settings);
      checkGjk(back, settings, ref, extent, rounded, "swapped");
    }
  };
  GjkCache<S> cache;
  check(poseP, poseQ, &cache, "cold");
  if (in.empty()) return;
  // Warm start from the first query's cache, the bodies moved to new poses.
  Pose<S> movedP = poseP, movedQ = poseQ;
  movedP.translation += toS<S>(in.vector(in.scale()));
  if (!in.flag()) movedQ = decodePose<S>(in) * poseQ;
  movedQ.validate("fuzz.movedQ");
  check(movedP, movedQ, &cache, "warm");
}

}  // namespace
}  // namespace gjkx::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using gjkx::fuzz::Decoder;
  return gjkx::fuzz::runOneInput(
      data, size, [](Decoder& in) { gjkx::fuzz::run<float>(in); }, [](Decoder& in) { gjkx::fuzz::run<double>(in); });
}
