// Settling slow bodies at a frame's end (sleep.hpp).
#include <gjkx/timewarp/sleep.hpp>

#include <vector>

namespace gjkx {

bool isSlow(const StepContext& step, const WorldBody& body, const BodyState& state) {
  const double g = step.scene.gravity.norm();
  return g > 0 && body.rigid.kineticEnergy(state) * body.rigid.inverseMass() / g <
                      step.band(step.settings.tuning.settleEnergy);
}

void putToSleep(StepContext& step, int b, BodyState state, double T1) {
  WorldBody& body = step.bodies[b];
  state.velocity.setZero();
  state.angularVelocity.setZero();
  body.asleep = true;
  body.contactFlight = false;
  body.slowFor = 0;
  body.setPath(freeFlight(body.rigid, state, T1, T1, body.gravity(step.scene.gravity)));  // for no time: no spin to overflow
  ++body.version;
  ++step.frame.report.counters.settled;
}

void settle(StepContext& step, double T1) {
  std::vector<WorldBody>& bodies = step.bodies;
  const FrameState& frame = step.frame;
  const double g = step.scene.gravity.norm();
  if (!(g > 0)) return;  // no weight: nothing holds a body down, rest is not defined
  const std::size_t n = bodies.size();
  // Slow: too little kinetic energy to lift the body out of the band, E_k / (m |g|) < tol.
  std::vector<char> slow(n, 0), settles(n, 0);
  std::vector<BodyState> end(n);
  for (std::size_t b = 0; b < n; ++b) {
    const WorldBody& body = bodies[b];
    if (body.rigid.isStatic() || body.asleep) continue;
    end[b] = body.path.stateAt(T1);
    slow[b] = isSlow(step, body, end[b]);
  }
  // How long each body has been slow and struck by nothing but resting or slow bodies;
  // one that has been so long enough, and was struck in this frame, may settle.
  std::vector<char> waited(n, 0);
  std::vector<int> ready;
  for (std::size_t b = 0; b < n; ++b) {
    WorldBody& body = bodies[b];
    if (body.rigid.isStatic() || body.asleep) continue;
    bool quiet = slow[b], supported = false;
    for (const int other : frame.struck[b].by) {
      quiet = quiet && (bodies[other].resting() || slow[other]);
      supported = supported || bodies[other].resting();
    }
    body.slowFor = quiet ? body.slowFor + 1.0 / step.scene.frameRate : 0.0;
    waited[b] = quiet && body.slowFor >= step.settings.tuning.settleSeconds && !frame.struck[b].by.empty();
    if (waited[b] && supported) {
      settles[b] = 1;
      ready.push_back(int(b));
    }
  }
  // The bodies that may settle on b once b settles: those it struck (striking is mutual).
  std::vector<std::vector<int>> next(n);
  for (std::size_t b = 0; b < n; ++b)
    if (waited[b])
      for (const int other : frame.struck[b].by)
        if (waited[other]) next[other].push_back(int(b));
  while (!ready.empty()) {
    const int b = ready.back();
    ready.pop_back();
    for (const int c : next[b])
      if (!settles[c]) {
        settles[c] = 1;
        ready.push_back(c);
      }
  }
  for (std::size_t b = 0; b < n; ++b) {
    if (!settles[b]) continue;
    putToSleep(step, int(b), end[b], T1);
  }
}

}  // namespace gjkx
