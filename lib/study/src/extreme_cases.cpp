// The stiff and extreme cases of the study (extreme_cases.hpp): the cases with their
// references, and the methods of ours that the table runs. Compiled once here: each method
// runs every solver of the library on every pair of shape kinds, in float and in double,
// which took more than a minute to compile in each program and test that used it.
#include <gjkx/study/extreme_cases.hpp>

namespace gjkx::study {

void computeReference(ToiCase& c) {
  computeReference(c.query);
  ref::DistanceFunction d(c.query);
  c.lipschitz = double(d.lipschitz());
  if (c.hasPlanarForm) computeReference(c.planar);
}

std::vector<ToiCase> makeToiCases() {
  using build::rotAxis;
  using build::rotZ;
  using V = Eigen::Vector3d;
  std::vector<ToiCase> out;
  auto add = [&](ToiCase c, bool planar) {
    if (planar) {
      c.hasPlanarForm = true;
      c.planar = build::planarTwin(c.query);
    }
    computeReference(c);
    out.push_back(std::move(c));
  };
  const ShapeDescription unitP = boxDescription(V(0.5, 0.5, 0.3)), unitQ = boxDescription(V(0.5, 0.5, 0.5));
  {
    ToiCase c;
    c.name = "touching faces";
    c.setup = "unit boxes; P's face comes down flush on Q's face and stops there exactly at t = 1 (d(1) = 0)";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(0.3, 1.5, 0);
    c.query.motionP.v = V(0.2, -0.5, 0);
    c.closedForm = 1 - 1e-10 / 0.5;  // d(t) = 0.5 (1 - t) reaches 1e-10 at 1 - 2e-10
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "sub-epsilon separation";
    c.setup = "unit boxes; P slides along Q's face at a gap of 1e-12 all the interval";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(-0.6, 1 + 1e-12, 0);
    c.query.motionP.v = V(1.2, 0, 0);
    c.expect = Expect::Either;
    c.closedForm = 0;  // the gap (1 + 1e-12) - 1 is under 1e-10 from the start
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "coincident origins";
    c.setup = "P and Q start with the same origin (deeply overlapping), P leaves at speed 1.6 turning 2 rad";
    c.query.P = boxDescription(V(0.5, 0.25, 0.3));
    c.query.Q = boxDescription(V(0.4, 0.4, 0.5));
    c.query.motionP.R0 = rotZ(0.3);
    c.query.motionP.v = V(1.5, 0.5, 0);
    c.query.motionP.w = V(0, 0, 2);
    c.closedForm = 0;
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "degenerate simplices";
    c.setup = "two squares of zero thickness in one plane (flat Minkowski difference), edges meeting parallel";
    c.query.P = build::rectangle(0.5, 0.5);
    c.query.Q = build::rectangle(0.5, 0.5);
    c.query.planar = true;  // the reference in 2D (the shapes are flat)
    c.query.motionP.p0 = V(-2, 0.3, 0);
    c.query.motionP.v = V(2.2, 0, 0);
    c.closedForm = (1 - 1e-10) / 2.2;  // P's right edge x = -1.5 + 2.2 t meets Q's left edge x = -0.5
    c.deltaWhy = "1% of the squares' size";
    add(c, false);
    out.back().hasPlanarForm = true;  // it is its own 2D form
    out.back().planar = out.back().query;
  }
  {
    ToiCase c;
    c.name = "size ratio 10^4";
    c.setup = "a box of half size 0.01 turning 3 rad falls at speed 1.1 on a box of half size 100";
    c.query.P = boxDescription(V(0.01, 0.01, 0.01));
    c.query.Q = boxDescription(V(100, 100, 100));
    c.query.motionP.p0 = V(3, 100.51, 0);
    c.query.motionP.v = V(0.4, -1, 0);
    c.query.motionP.w = V(0, 0, 3);
    c.closedForm = build::firstRoot([](LD t) { return LD(100.51) - t + build::lowestY(LD(0.01), LD(0.01), 3 * t) - 100 - LD(1e-10); });
    c.delta = 1e-3;
    c.deltaWhy = "5% of the small box's size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "coordinates near 10^5";
    c.setup = "unit boxes at x, y = 1e5 (float spacing there: 0.0078); P turning 0.5 rad meets Q at speed 2";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionQ.p0 = V(1e5, 1e5, 0);
    c.query.motionP.p0 = V(1e5 - 2, 1e5 + 0.25, 0);
    c.query.motionP.v = V(2, 0, 0);
    c.query.motionP.w = V(0, 0, 0.5);
    // P's rightmost point reaches Q's left face x = 1e5 - 0.5 (within Q's y-range: checked by the reference).
    c.closedForm = build::firstRoot([](LD t) { return LD(1e5) - 0.5L - (LD(1e5) - 2 + 2 * t + build::rightmostX(0.5L, 0.5L, 0.5L * t)) - LD(1e-10); });
    // No float allowance: the default 1% holds for a method that works in the frame of one
    // body (timeOfImpact does; with world coordinates its float run was 3.2e-3 early here).
    c.deltaWhy = "1% of the boxes' size; float spacing at 1e5 is 0.0078";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "half a turn per interval";
    c.setup = "a rod (half size 1 x 0.05) turns by pi about z: the same set at t = 0 and 1, sweeping through Q on the way";
    c.query.P = boxDescription(V(1, 0.05, 0.3));
    c.query.Q = boxDescription(V(0.1, 0.1, 0.5));
    c.query.motionP.w = V(0, 0, M_PI);
    c.query.motionQ.p0 = V(0.3, 0.75, 0);
    c.deltaWhy = "1% of the boxes' size";
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "thin rod spinning";
    c.setup = "a rod 2 long and 0.004 thick spins 12 rad about a tilted axis; its end sweeps through a cube of side 0.06";
    c.query.P = boxDescription(V(1, 0.002, 0.002));
    c.query.Q = boxDescription(V(0.03, 0.03, 0.03));
    c.query.motionP.v = V(0.1, 0.05, 0);
    c.query.motionP.w = 12 * V(0.2, 0.3, 0.93).normalized();
    // Q stands where the rod's point at 0.8 along it passes at t = 0.37.
    const auto [R, p] = c.query.motionP.poseAt(0.37);
    c.query.motionQ.p0 = p + R * V(0.8, 0, 0);
    c.query.motionQ.R0 = rotAxis(0.6, V(1, 1, 0));
    c.delta = 1e-3;
    c.deltaWhy = "a quarter of the rod's thickness";
    add(c, false);
  }
  {
    ToiCase c;
    c.name = "starting within tolerance, separating";
    // The gap is inside the tolerance (1e-5) and 32 float ulps wide: above the round-off GJK calls an
    // overlap (16 eps times the size; below it, sub-epsilon separation is the case).
    c.setup = "unit boxes 2^-18 = 3.8e-6 apart at t = 0 (inside the tolerances, 1e-5), P moving away and turning 0.2 rad";
    c.query.P = unitP;
    c.query.Q = unitQ;
    c.query.motionP.p0 = V(0, 1 + std::ldexp(1.0, -18), 0);
    c.query.motionP.v = V(0.3, 0.5, 0);
    c.query.motionP.w = V(0, 0, 0.2);
    c.expect = Expect::NoHit;
    add(c, true);
  }
  {
    ToiCase c;
    c.name = "two fast bodies";
    c.setup = "a capsule and a box, each at speed 100 (over 100 body lengths per interval) and tumbling, meet head on";
    c.query.P = capsuleDescription(0.3, 0.1);
    c.query.Q = boxDescription(V(0.2, 0.15, 0.1));
    c.query.motionP.p0 = V(-50, 0.1, 0.05);
    c.query.motionP.R0 = rotAxis(0.9, V(1, 0, 1));
    c.query.motionP.v = V(100, 0, 0);
    c.query.motionP.w = V(1.5, 2, 0);  // turns under half a revolution: the peers' end poses tell the motion
    c.query.motionQ.p0 = V(50, -0.05, 0);
    c.query.motionQ.R0 = rotAxis(0.4, V(0, 1, 1));
    c.query.motionQ.v = V(-100, 0, 0);
    c.query.motionQ.w = V(0, 1, 2.5);
    c.deltaWhy = "about 3% of the smaller body's size";
    add(c, false);
  }
  return out;
}

double referenceDistance(const StaticCase& c) {
  ToiQuery q;
  q.P = c.P;
  q.Q = c.Q;
  q.motionP.p0 = c.poseP.translation;
  q.motionP.R0 = c.poseP.rotation;
  q.motionQ.p0 = c.poseQ.translation;
  q.motionQ.R0 = c.poseQ.rotation;
  q.planar = c.P.kind == ShapeKind::Polygon && c.Q.kind == ShapeKind::Polygon && c.poseP.translation.z() == 0 &&
             c.poseQ.translation.z() == 0;
  ref::DistanceFunction d(q);
  return double(d(0));
}

std::vector<StaticCase> makeStaticCases() {
  using build::rotAxis;
  using build::rotZ;
  using V = Eigen::Vector3d;
  std::vector<StaticCase> out;
  auto pose = [](const Eigen::Matrix3d& R, const V& p) {
    Pose<double> x;
    x.rotation = R;
    x.translation = p;
    return x;
  };
  auto add = [&](StaticCase c) {
    c.reference = referenceDistance(c);
    c.scale = std::max({1.0, c.poseP.translation.norm() + c.P.boundingRadius(), c.poseQ.translation.norm() + c.Q.boundingRadius()});
    c.tau = 1e-6 * c.scale;
    out.push_back(std::move(c));
  };
  const ShapeDescription unitP = boxDescription(V(0.5, 0.5, 0.3)), unitQ = boxDescription(V(0.5, 0.5, 0.5));
  const Eigen::Matrix3d R = rotAxis(0.7, V(1, 2, 3));
  {
    StaticCase c{"touching faces", "unit boxes face to face, P slid half a face sideways (exact: d = 0)", unitP, unitQ,
                 pose(Eigen::Matrix3d::Identity(), V(0.5, 1, 0)), pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0;
    add(c);
  }
  {
    StaticCase c{"sub-epsilon separation", "the same, turned together by 0.7 rad, a gap of 1e-12 (under float's resolution)", unitP,
                 unitQ, pose(R, R * V(0.2, 1 + 1e-12, 0.1)), pose(R, V::Zero())};
    c.closedForm = 1e-12;
    add(c);
  }
  {
    const ShapeDescription box = boxDescription(V(0.5, 0.4, 0.3));
    StaticCase c{"coincident origins", "two identical boxes at the same pose (centre-to-centre direction zero)", box, box,
                 pose(R, V(0.1, 0.2, 0.3)), pose(R, V(0.1, 0.2, 0.3))};
    c.closedForm = 0;
    add(c);
  }
  {
    StaticCase c{"degenerate simplices", "two squares of zero thickness in one plane, overlapping (flat Minkowski difference)",
                 build::rectangle(0.5, 0.5), build::rectangle(0.5, 0.5), pose(rotZ(0.4), V(0.8, 0.3, 0)),
                 pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0;
    add(c);
  }
  {
    const ShapeDescription small = boxDescription(V(0.01, 0.01, 0.01)), big = boxDescription(V(100, 100, 100));
    // The small box's lowest point (turned by R) 0.005 above the big box's top face y = 100.
    const double below = 0.01 * (std::abs(R(1, 0)) + std::abs(R(1, 1)) + std::abs(R(1, 2)));
    StaticCase c{"size ratio 10^4", "a box of half size 0.01, turned, 0.005 above a box of half size 100", small, big,
                 pose(R, V(3, 100 + 0.005 + below, 0.7)), pose(Eigen::Matrix3d::Identity(), V::Zero())};
    c.closedForm = 0.005;
    add(c);
  }
  {
    // P turned by Rz(0.3) Rx(0.2), its corner of lowest x placed 0.3 right of Q's face x = 1e5 + 0.5, at
    // (y, z) = (1e5 + 0.1, 0.05) on that face, so the closest points are that corner and the face.
    const Eigen::Matrix3d Rp = rotZ(0.3) * rotAxis(0.2, V(1, 0, 0));
    const V corner = Rp * V(Rp(0, 0) > 0 ? -0.5 : 0.5, Rp(0, 1) > 0 ? -0.5 : 0.5, Rp(0, 2) > 0 ? -0.3 : 0.3);
    StaticCase c{"coordinates near 10^5", "unit boxes at 1e5 (float spacing 0.0078), P turned, a corner 0.3 from Q's face", unitP,
                 unitQ, pose(Rp, V(1e5 + 0.5 + 0.3, 1e5 + 0.1, 0.05) - corner), pose(Eigen::Matrix3d::Identity(), V(1e5, 1e5, 0))};
    c.closedForm = 0.3;
    add(c);
  }
  return out;
}

std::vector<ToiMethod> ourToiMethods() {
  const double tol = kTolerance;
  std::vector<ToiMethod> m;
  m.push_back({"static N=32", false, false, false, [](const ToiQuery& q) {
                 return withMoving<double>(q, [](const auto& P, const auto& Q, double) { return answerOf(staticSampling(P, Q, 0.0, 1.0, 32)); });
               }});
  m.push_back({"swept", false, false, true, [](const ToiQuery& q) {
                 return withMoving<double>(q, [](const auto& P, const auto& Q, double) { return answerOf(sweepingTest(P, Q, 0.0, 1.0)); });
               }});
  m.push_back({"CA", false, false, false, [tol](const ToiQuery& q) {
                 return withMoving<double>(q, [tol](const auto& P, const auto& Q, double L) {
                   return answerOf(conservativeAdvancement(P, Q, 0.0, 1.0, caSettings(tol, L)));
                 });
               }});
  auto ours = [tol](const char* name, ExtrusionVariant variant, bool useFloat, bool inFrameOfP = true) {
    std::function<ToiAnswer(const ToiQuery&)> run;
    if (useFloat)
      run = [tol, variant, inFrameOfP](const ToiQuery& q) {
        return withMoving<float>(q, [&](const auto& P, const auto& Q, float) {
          ToiSettings<float> settings = toiSettings<float>(tol, variant);
          settings.inFrameOfP = inFrameOfP;
          return answerOf(timeOfImpact(P, Q, 0.0f, 1.0f, settings));
        });
      };
    else
      run = [tol, variant](const ToiQuery& q) {
        return withMoving<double>(q, [&](const auto& P, const auto& Q, double) {
          return answerOf(timeOfImpact(P, Q, 0.0, 1.0, toiSettings<double>(tol, variant)));
        });
      };
    return ToiMethod{name, inFrameOfP, false, false, run};
  };
  m.push_back(ours("ours double", ExtrusionVariant::Paper, false));
  m.push_back(ours("ours float", ExtrusionVariant::Paper, true));
  // The same in world coordinates, not in P's frame: what the frame buys (not a library
  // default, so the test does not hold it to the table).
  m.push_back(ours("ours float, world frame", ExtrusionVariant::Paper, true, false));
  m.push_back(ours("certified double", ExtrusionVariant::Certified, false));
  m.push_back(ours("certified float", ExtrusionVariant::Certified, true));
  return m;
}

std::vector<GjkMethod> ourGjkMethods() {
  return {{"ours double", true, [](const StaticCase& c) { return oursGjk<double>(c); }},
          {"ours float", true, [](const StaticCase& c) { return oursGjk<float>(c); }}};
}

std::vector<std::string> referenceProblems(const std::vector<ToiCase>& cases, const std::vector<StaticCase>& statics) {
  std::vector<std::string> out;
  for (const ToiCase& c : cases) {
    const bool hit = c.query.refHit;
    if ((c.expect == Expect::NoHit) == hit) out.push_back(c.name + ": the reference says " + (hit ? "hit" : "no hit"));
    if (!std::isnan(c.closedForm) && std::abs(c.closedForm - c.query.tRef) > 1e-9)
      out.push_back(c.name + ": closed form t = " + sci(c.closedForm, 12) + ", brute force t = " + sci(c.query.tRef, 12));
    if (c.hasPlanarForm && (c.planar.refHit != hit || std::abs(c.planar.tRef - c.query.tRef) > 1e-9))
      out.push_back(c.name + ": the 2D form's reference t = " + sci(c.planar.tRef, 12) + " differs");
  }
  for (const StaticCase& c : statics)
    if (std::abs(c.closedForm - c.reference) > 1e-9 * c.scale)
      out.push_back(c.name + " (static): closed form " + sci(c.closedForm, 12) + ", brute force " + sci(c.reference, 12));
  return out;
}

}  // namespace gjkx::study
