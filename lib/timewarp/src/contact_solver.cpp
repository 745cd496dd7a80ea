// Resting contact in the hybrid model (contact_solver.hpp): the velocity solve of a group.
// (The contact part of a step, which finds the contacts and groups and calls it: contact_groups.cpp.)
#include <gjkx/timewarp/contact_solver.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gjkx {

namespace {

/// A body as the solver sees it: its velocities, and its inverse mass and inertia (zero
/// for a body outside the group: static or asleep, it does not move).
struct SolverBody {
  double inverseMass = 0;
  Eigen::Matrix3d inverseInertia = Eigen::Matrix3d::Zero();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// One manifold point as a constraint row, in the form the sweeps read (Catto's Jacobians):
/// for each direction d of the point (the normal, then the tangent plane's t1 and t2), the
/// lever arms' cross products \f$r \times d\f$ (the relative velocity along d reads
/// \f$d\cdot(v_j - v_i) + (r_j\times d)\cdot\omega_j - (r_i\times d)\cdot\omega_i\f$) and the spin
/// an impulse along d gives each body, \f$I^{-1}(r \times d)\f$.
struct Row {
  int i, j;                                   // the bodies
  double massI, massJ;                        // their inverse masses (zero outside the group)
  ManifoldPoint* point;                       // where its impulses are kept (written back at the end)
  double lambda = 0;                          // the normal impulse while the solve runs
  double friction;                            // the pair's mu
  std::array<Eigen::Vector3d, 3> d;           // n, t1, t2
  std::array<Eigen::Vector3d, 3> armI, armJ;  // r_i x d, r_j x d
  std::array<Eigen::Vector3d, 3> spinI, spinJ;  // I_i^-1 (r_i x d), I_j^-1 (r_j x d)
  double normalMass;
  TangentBlock tangent;         // the tangent plane's 2x2 block (response along t1, t2)
  double tangentScale;          // the block's size: an impulse times it is a velocity
  double target;  // the least normal velocity allowed (never positive: speculative contact)
  double f1 = 0, f2 = 0;  // the friction impulse along t1 and t2 while the solve runs
};

/// How the relative velocity at lever arms rI, rJ along unit e answers an impulse along unit d:
/// d.e (1/m_i + 1/m_j) + (r_i x d) . I_i^-1 (r_i x e) + (r_j x d) . I_j^-1 (r_j x e); for e = d,
/// the inverse of the effective mass along d.
double response(const SolverBody& I, const SolverBody& J, const Eigen::Vector3d& rI, const Eigen::Vector3d& rJ,
                const Eigen::Vector3d& d, const Eigen::Vector3d& e) {
  return d.dot(e) * (I.inverseMass + J.inverseMass) + rI.cross(d).dot(I.inverseInertia * rI.cross(e)) +
         rJ.cross(d).dot(J.inverseInertia * rJ.cross(e));
}

/// A row's effective masses between bodies I and J at its point (either may be held still:
/// a SolverBody of no inverse mass or inertia): the normal's, and the tangent plane's 2x2
/// block (response along t1, t2) with its size.
void setMasses(Row& row, const SolverBody& I, const SolverBody& J) {
  const Eigen::Vector3d rI = row.point->point - I.centre, rJ = row.point->point - J.centre;
  const Eigen::Vector3d &n = row.d[0], &t1 = row.d[1], &t2 = row.d[2];
  const double k = response(I, J, rI, rJ, n, n);
  row.normalMass = k > 0 ? 1.0 / k : 0.0;
  Eigen::Matrix2d K;
  K << response(I, J, rI, rJ, t1, t1), response(I, J, rI, rJ, t1, t2), response(I, J, rI, rJ, t2, t1),
      response(I, J, rI, rJ, t2, t2);
  row.tangent = TangentBlock::of(K);
  row.tangentScale = K.norm();
}

double kineticEnergy(const StepContext& step, const std::vector<int>& group, const std::vector<BodyState>& states) {
  double e = 0;
  for (int b : group) e += step.bodies[b].rigid.kineticEnergy(states[b]);
  return e;
}

/// True if a solve raised the kinetic energy from `before` to `after` by more than round-off
/// (the column `energy_rises` counts such solves).
bool energyRose(double before, double after) { return after > before * (1 + 1e-9) + 1e-12; }

}  // namespace

// ---------------------------------------------------------------------------------------
// The velocity solve of a group: sequential impulses (Catto 2005). Each row's impulse is
// accumulated and clamped (normal impulse >= 0, friction within Coulomb's disc |f| <= mu
// lambda_n), and each iteration applies only the change, so the result is the projected
// Gauss-Seidel solution of the contact LCP. Warm-started: each point starts from the
// impulses it took in the last solve, so a resting stack starts where it ended and the
// iterations only follow what changed.
GroupSolve solveGroup(const StepContext& step, const std::vector<int>& group, std::vector<Manifold*>& manifolds,
                      std::vector<BodyState>& states, double dt, bool gravity) {
  const StepTuning& tuning = step.settings.tuning;
  const double tolerance = step.scene.collisionTolerance;
  std::vector<SolverBody> solverBodies(step.bodies.size());
  for (int b : group) {
    const WorldBody& body = step.bodies[b];
    SolverBody& s = solverBodies[b];
    s.inverseMass = body.rigid.inverseMass();
    s.inverseInertia = body.rigid.inverseInertiaWorld(states[b].worldFromBody.rotation);
    if (gravity) states[b].velocity += step.scene.gravity * dt;
  }
  for (Manifold* m : manifolds)
    for (int b : {m->i, m->j}) solverBodies[b].centre = states[b].worldFromBody.translation;
  GroupSolve out;
  out.kineticBefore = kineticEnergy(step, group, states);
  // The velocities the sweeps change, side by side (a body's state is read back at the end).
  std::vector<Eigen::Vector3d> v(step.bodies.size()), w(step.bodies.size());
  for (Manifold* m : manifolds)
    for (int b : {m->i, m->j}) {
      v[b] = states[b].velocity;
      w[b] = states[b].angularVelocity;
    }
  // An impulse `size` along direction k of a row, and the relative velocity along it.
  Eigen::Vector3d* const V = v.data();
  Eigen::Vector3d* const W = w.data();
  const auto apply = [V, W](const Row& row, int k, double size) {
    V[row.i] -= row.massI * size * row.d[k];
    W[row.i] -= size * row.spinI[k];
    V[row.j] += row.massJ * size * row.d[k];
    W[row.j] += size * row.spinJ[k];
  };
  const auto velocityAlong = [V, W](const Row& row, int k) {
    return row.d[k].dot(V[row.j] - V[row.i]) + row.armJ[k].dot(W[row.j]) - row.armI[k].dot(W[row.i]);
  };
  const double rest = tuning.restSeparation * tolerance;
  std::vector<Row> rows;
  for (Manifold* m : manifolds) {
    const SolverBody &I = solverBodies[m->i], &J = solverBodies[m->j];
    const Eigen::Vector3d& n = m->normal;
    for (ManifoldPoint& p : m->points) {
      Row row;
      row.i = m->i;
      row.j = m->j;
      row.point = &p;
      row.massI = I.inverseMass;
      row.massJ = J.inverseMass;
      row.friction = m->friction;
      const Eigen::Vector3d rI = p.point - I.centre, rJ = p.point - J.centre;
      row.d = {n, n.unitOrthogonal(), Eigen::Vector3d::Zero()};
      row.d[2] = n.cross(row.d[1]);
      for (int k = 0; k < 3; ++k) {
        row.armI[k] = rI.cross(row.d[k]);
        row.armJ[k] = rJ.cross(row.d[k]);
        row.spinI[k] = I.inverseInertia * row.armI[k];
        row.spinJ[k] = J.inverseInertia * row.armJ[k];
      }
      setMasses(row, I, J);
      // Speculative contact: the point may close by what separates it from rest, no more.
      row.target = -std::max(0.0, p.separation - rest) / dt;
      rows.push_back(row);
    }
  }
  // Sweeps until no impulse changes the velocity at its point by more than contactSettled
  // (a tenth) of the speed that closes the rest separation in the interval (StepTuning::contactIterations
  // at most). The rows are ordered from the bottom up (against gravity), as Guendelman et
  // al. order their contact graph, and the sweeps go up and down it in turn: symmetric
  // Gauss–Seidel. A sweep that goes one way leaves its error leaning that way (a resting
  // pile's boxes drift sideways together, and settle slowly); a sweep down undoes the lean
  // of the sweep up before it.
  if (step.scene.gravity.squaredNorm() > 0) {
    const Eigen::Vector3d up = -step.scene.gravity.normalized();
    std::stable_sort(rows.begin(), rows.end(),
                     [&](const Row& a, const Row& b) { return up.dot(a.point->point) < up.dot(b.point->point); });
  }
  const double settled = tuning.contactSettled * rest / dt;
  std::vector<double> limits(rows.size(), 0.0);
  // One row's step: with friction, its tangent impulse within Coulomb's disc of radius
  // `limit`, then its normal impulse. Returns the largest velocity change it made.
  const auto relax = [&](Row& row, bool friction, double limit) {
    double largest = 0;
    if (friction) {
      // The tangent plane's 2x2 block solved exactly (its two directions are coupled
      // through the rotation): the impulse that stops the point's slip if that lies within
      // Coulomb's disc (it sticks), else the best on the disc's edge (it slides, and feels
      // mu lambda_n against its slip): frictionInDisc.
      const Eigen::Vector2d slip(velocityAlong(row, 1), velocityAlong(row, 2));
      const double speed = slip.norm();
      if (speed > 0) {
        const Eigen::Vector2d old(row.f1, row.f2);
        const Eigen::Vector2d next = frictionInDisc(row.tangent, old, slip, limit);
        const Eigen::Vector2d change = next - old;
        row.f1 = next.x();
        row.f2 = next.y();
        apply(row, 1, change.x());
        apply(row, 2, change.y());
        largest = std::min(speed, change.norm() * row.tangentScale);
      }
    }
    const double vn = velocityAlong(row, 0);
    const double old = row.lambda;
    row.lambda = std::max(0.0, old - row.normalMass * (vn - row.target));
    apply(row, 0, row.lambda - old);
    return std::max(largest, std::abs(row.lambda - old) / std::max(row.normalMass, 1e-300));
  };
  // One sweep over the rows, up the pile or down it, in turn through the whole solve (the
  // passes below are a sweep or two each once a pile rests: turning at each pass's start
  // would send nearly every sweep up).
  const auto sweep = [&](bool friction) {
    double largest = 0;
    const bool down = out.sweeps % 2 == 1;
    for (std::size_t q = 0; q < rows.size(); ++q) {
      const std::size_t r = down ? rows.size() - 1 - q : q;
      largest = std::max(largest, relax(rows[r], friction, limits[r]));
    }
    ++out.sweeps;
    return largest;
  };
  // Friction bounded by the normal impulse it is solved with is no longer a minimum of
  // anything, and Gauss-Seidel on it can wander (a stack of ten boxes never settled). So the
  // bounds are frozen: the normals are solved first, then friction and normals together
  // with the bounds mu lambda_n of the last pass, twice. With its bounds fixed each pass is
  // projected Gauss-Seidel on a convex quadratic program, and each of its steps can only
  // lower the kinetic energy.
  const int budget = tuning.contactIterations;  // per pass
  // Shock propagation on the velocities (Guendelman, Bridson and Fedkiw 2003), after the
  // passes. Gauss-Seidel stops when a sweep changes little, not when the pile is still: in
  // a pile twenty boxes high each level is left closing on the one below by a fraction of
  // the settled speed, and the errors add up the pile (its top sank a tenth of a tolerance
  // each interval, and the projection lifted it back: potential energy that fed a rocking
  // of the whole pile), as does friction's (the pile leaned). So the group is solved once
  // more level by level from the ground up: a body's level is its count of contacts from a
  // body the solver does not move (static or asleep: level 0), and at level d the contacts
  // of level-d bodies with each other and with lower ones are swept (StepTuning::shockSweeps
  // at most) with the lower bodies held, as if of infinite mass. Each level then rests on
  // the solved velocities of the one below, and no error is carried up. A group that
  // touches no such body (bodies in flight together) has no levels and is left as solved.
  std::vector<int> level(step.bodies.size(), -1);
  int levels = 0;
  {
    std::vector<std::vector<int>> touching(step.bodies.size());
    std::vector<int> queue;  // breadth first from level 0
    for (const Row& row : rows) {
      touching[row.i].push_back(row.j);
      touching[row.j].push_back(row.i);
      for (const auto& [b, mass] : {std::pair{row.i, row.massI}, std::pair{row.j, row.massJ}})
        if (mass == 0 && level[b] < 0) {
          level[b] = 0;
          queue.push_back(b);
        }
    }
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (int other : touching[queue[q]])
        if (level[other] < 0) {
          level[other] = level[queue[q]] + 1;
          levels = std::max(levels, level[other]);
          queue.push_back(other);
        }
  }
  // Each level's rows: those of its bodies with each other and with lower ones.
  std::vector<std::vector<std::size_t>> rowsOfLevel(std::size_t(levels) + 1);
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (level[rows[r].i] >= 0 && level[rows[r].j] >= 0)
      rowsOfLevel[std::size_t(std::max(level[rows[r].i], level[rows[r].j]))].push_back(r);
  const SolverBody still;  // a lower body, held: no inverse mass, no inverse inertia
  const auto shockPropagation = [&] {
    if (tuning.shockSweeps == 0) return;
    std::vector<Row> held;  // one level's rows, the lower body of each held
    for (int d = 1; d <= levels; ++d) {
      const std::vector<std::size_t>& heldOf = rowsOfLevel[std::size_t(d)];  // where each came from in rows
      held.clear();
      for (std::size_t r : heldOf) {
        Row row = rows[r];
        const bool holdI = level[row.i] < d, holdJ = level[row.j] < d;
        if (holdI) {
          row.massI = 0;
          for (Eigen::Vector3d& spin : row.spinI) spin.setZero();
        }
        if (holdJ) {
          row.massJ = 0;
          for (Eigen::Vector3d& spin : row.spinJ) spin.setZero();
        }
        setMasses(row, holdI ? still : solverBodies[row.i], holdJ ? still : solverBodies[row.j]);
        held.push_back(row);
      }
      for (int k = 0; k < tuning.shockSweeps; ++k) {
        double largest = 0;
        for (std::size_t q = 0; q < held.size(); ++q) {
          const std::size_t h = k % 2 == 1 ? held.size() - 1 - q : q;
          largest = std::max(largest, relax(held[h], true, limits[heldOf[h]]));
        }
        if (largest < settled) break;
      }
      for (std::size_t h = 0; h < held.size(); ++h) {
        Row& row = rows[heldOf[h]];
        row.lambda = held[h].lambda;
        row.f1 = held[h].f1;
        row.f2 = held[h].f2;
      }
    }
  };
  // The passes, from the stored impulses (warm) or from none (cold).
  const std::vector<Eigen::Vector3d> v0 = v, w0 = w;
  const auto solve = [&](bool warm) {
    v = v0;
    w = w0;
    for (Row& row : rows) {
      // Warm start: last solve's impulses (the friction kept in the contact plane).
      row.lambda = warm ? row.point->normalImpulse : 0.0;
      row.f1 = warm ? row.d[1].dot(row.point->frictionImpulse) : 0.0;
      row.f2 = warm ? row.d[2].dot(row.point->frictionImpulse) : 0.0;
      apply(row, 0, row.lambda);
      apply(row, 1, row.f1);
      apply(row, 2, row.f2);
    }
    for (int k = 0; k < budget && sweep(false) >= settled; ++k) {}
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t r = 0; r < rows.size(); ++r) {
        Row& row = rows[r];
        limits[r] = row.friction * row.lambda;
        const double size = std::hypot(row.f1, row.f2);
        if (size > limits[r]) {  // a warm start above the new bound is cut to it
          const double scale = limits[r] / size;
          apply(row, 1, row.f1 * scale - row.f1);
          apply(row, 2, row.f2 * scale - row.f2);
          row.f1 *= scale;
          row.f2 *= scale;
        }
      }
      for (int k = 0; k < budget && sweep(true) >= settled; ++k) {}
    }
    shockPropagation();
  };
  // The solved velocities into the bodies' states, and the group's kinetic energy then.
  const auto kineticAfter = [&] {
    for (Manifold* m : manifolds)
      for (int b : {m->i, m->j}) {
        states[b].velocity = v[b];
        states[b].angularVelocity = w[b];
      }
    return kineticEnergy(step, group, states);
  };
  // Warm, the passes start from last solve's impulses, which may leave the energy above
  // where it was (a body struck since, or sweeps that end at the budget before they have
  // taken the warm start's excess back). Such a solve is run again cold: from no impulse,
  // every step of a pass only lowers the energy (frictionInDisc).
  solve(true);
  out.kineticAfter = kineticAfter();
  if (energyRose(out.kineticBefore, out.kineticAfter)) {
    solve(false);
    out.kineticAfter = kineticAfter();
  }
  for (const Row& row : rows) {
    row.point->normalImpulse = row.lambda;
    row.point->frictionImpulse = row.f1 * row.d[1] + row.f2 * row.d[2];
  }
  return out;
}

bool GroupSolve::energyRose() const { return gjkx::energyRose(kineticBefore, kineticAfter); }

}  // namespace gjkx
