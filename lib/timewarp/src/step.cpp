// The step context and free flight (step.hpp).
#include <gjkx/timewarp/step.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gjkx {

FrameState::FrameState(std::size_t bodies) : paths(bodies), struck(bodies), touching(bodies) {}

BodyState renormalized(BodyState state) {
  state.worldFromBody.rotation = Eigen::Quaterniond(state.worldFromBody.rotation).normalized().toRotationMatrix();
  return state;
}

bool flyFrom(StepContext& step, int b, const BodyState& state, double t0, double t1) {
  WorldBody& body = step.bodies[b];
  FreeFlight path;
  {
    PartTimer timer(step.frame.report.parts.integration);
    path = freeFlight(body.rigid, state, t0, t1, body.gravity(step.scene.gravity));
  }
  // A free-flight path turns along the shortest arc between its end orientations
  // (motion.hpp, FreeFlightPath), so a body turning half a turn or more within one path
  // would be drawn turning the other way: the frame is run again in shorter intervals
  // (world.cpp), and nothing more is done in this one.
  if (std::holds_alternative<FreeFlightPath<double>>(path.motion.variant()) && path.turnedAngle >= 0.95 * M_PI) {
    FrameState::SpinOverflow& spin = step.frame.spinOverflow;
    spin.happened = true;
    spin.angularSpeed = state.angularVelocity.norm();
    spin.what = "body '" + body.name + "' turns " + std::to_string(path.turnedAngle) + " rad within " +
                std::to_string(t1 - t0) + " s (angular speed " + std::to_string(spin.angularSpeed) +
                " rad/s): more than the half turn a path can hold";
    return false;
  }
  if (path.status == FreeFlightStatus::StepCap)
    throw std::runtime_error("body '" + body.name + "': the free-flight integrator ran out of steps");
  body.setPath(std::move(path));
  ++body.version;
  auto& paths = step.frame.paths[b];
  if (!paths.empty() && paths.back().end > t0) paths.back().end = t0;  // cut at t0 (a rollback)
  paths.push_back({body.path, t1});
  step.record(TraceEvent::Kind::Advance, b, -1, t0, t1);
  return true;
}

bool fly(StepContext& step, int b, double t0, double t1) {
  return flyFrom(step, b, renormalized(step.bodies[b].path.stateAt(t0)), t0, t1);
}

bool ownStepsOf(const Scene& scene) { return scene.run.ordering == Ordering::Timewarp; }

bool struckStepsOf(const Scene& scene) { return ownStepsOf(scene) && scene.run.contact == ContactModel::Hybrid; }

double ownStepEnd(const StepContext& step, const BodyState& state, double t0, double t1) {
  const double spin = state.angularVelocity.norm();
  if (!step.ownSteps() || !(spin > 0)) return t1;
  const double minPath = step.settings.tuning.minPath / step.scene.frameRate;
  return std::min(t1, t0 + std::max(eighthTurn / spin, minPath));
}

bool flyOwnStep(StepContext& step, int b, double t0, double t1) {
  const BodyState state = renormalized(step.bodies[b].path.stateAt(t0));
  return flyFrom(step, b, state, t0, ownStepEnd(step, state, t0, t1));
}

double pathEnd(const StepContext& step, int b, double t1) {
  const WorldBody& body = step.bodies[b];
  return body.rigid.isStatic() ? t1 : std::min(t1, body.path.t1);
}

bool flyAll(StepContext& step, double t0, double t1) {
  const double struckStep = step.settings.tuning.struckStep / step.scene.frameRate;
  for (std::size_t b = 0; b < step.bodies.size(); ++b) {
    const WorldBody& body = step.bodies[b];
    if (body.rigid.isStatic()) continue;  // never integrated
    if (body.path.t0 == t0 && body.path.t1 >= t1) {  // already flown from here (after an impulse at t0)
      if (step.frame.paths[b].empty()) step.frame.paths[b].push_back({body.path, t1});
      continue;
    }
    // Under the hybrid, a body struck within the last interval (a pile's crash strikes each
    // bone every few milliseconds) starts in a struck body's step: its pairs checked over the
    // whole interval would most often be struck again long before the interval's end, and
    // their work beyond that lost. Where the step ends it flies on, on the same path.
    double end = t1;
    if (step.struckSteps() && t0 - body.lastStruck <= t1 - t0) end = std::min(t1, t0 + struckStep);
    if (!flyOwnStep(step, int(b), t0, end)) return false;
  }
  return true;
}

void touched(StepContext& step, int i, int pi, int j, int pj) {
  const FrameState::Touching pair{i, pi, j, pj};
  for (int b : {i, j}) {
    if (step.bodies[b].rigid.isStatic()) continue;
    auto& list = step.frame.touching[b];
    if (std::find(list.begin(), list.end(), pair) == list.end()) list.push_back(pair);
  }
}

}  // namespace gjkx
