// The skeletal torso and the aquatic plant of the paper's §6 experiment, made here
// (no public torso mesh may be shipped): "a skeletal model of a human torso separated
// into its individual bones and vertebrae, with 80 nonconvex rigid bodies and 24,790
// triangles in total", dropped onto "an aquatic plant fixed in space with 8640 triangles".
//
// The 80 bones (docs/08_torso.md lists them):
//   24 vertebrae   C1-C7, T1-T12, L1-L5: a ring round the spinal canal, the body in
//                  front, the arch behind, spinous and transverse processes pulled out;
//   24 ribs        12 a side, flat curved bands from the spine round to the front;
//   22 costal cartilages, 11 a side: ribs 1-7 to the sternum, 8-10 towards the costal
//                  margin, 11 a tip on the floating rib (ribs 12 end bare);
//    2 sternum     the manubrium and the body with the xiphoid process;
//    2 clavicles, 2 scapulae (a curved triangular plate with its spine and acromion),
//    2 hip bones   (the iliac wing flaring out, the acetabulum, the pubic ramus),
//    1 sacrum, 1 coccyx.
// Units are metres: the torso is about 0.63 m from C1 to the coccyx. Frame: z up, y to
// the front (anterior), x to the body's right. Bones keep gaps of a few millimetres
// (discs, joints), so that none touches another at the start of a simulation.
//
// The plant (plant_model.hpp): an Amazon-sword-like rosette, a flower stalk 1 m tall and
// 12 leaves, each a stalk (petiole) and a thin drooping blade 3 mm thick: the paper's flat objects.
#pragma once

#include "plant_model.hpp"
#include "shapes.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace torso {

/// Half the width of the static floor the plant stands on (m): the scene's floor box and Fig. 5's floor.
inline constexpr double floorHalfWidth = 1.5;

/// One bone: its name, its group ("vertebra", "rib", ...), and its mesh in the torso's
/// frame (metres).
struct Bone {
  std::string name;          ///< unique, e.g. "vertebra_T6", "rib_left_3"
  std::string group;         ///< vertebra, rib, cartilage, sternum, clavicle, scapula, hip, sacrum, coccyx
  gjkx::TriangleMesh mesh;   ///< closed, outward-facing, in the torso's frame
};

/// The bones of the reduced scene (a quick test of the whole pipeline): a thoracic
/// vertebra, its two ribs and cartilages, the sternum's body.
inline const std::vector<std::string>& reducedBoneNames() {
  static const std::vector<std::string> names{"vertebra_T6",      "rib_left_6",        "rib_right_6",
                                              "cartilage_left_6", "cartilage_right_6", "sternum_body"};
  return names;
}

namespace detail {

inline double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

/// Points through `control` (Catmull-Rom), `perSegment` per span, the last control point included.
inline std::vector<V3> catmullRom(const std::vector<V3>& control, int perSegment) {
  std::vector<V3> out;
  const int n = int(control.size());
  for (int i = 0; i + 1 < n; ++i) {
    const V3 p0 = control[std::max(i - 1, 0)], p1 = control[i], p2 = control[i + 1],
             p3 = control[std::min(i + 2, n - 1)];
    for (int k = 0; k < perSegment; ++k) {
      const double t = double(k) / perSegment, t2 = t * t, t3 = t2 * t;
      out.push_back(0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3));
    }
  }
  out.push_back(control.back());
  return out;
}

/// The half width of a closed outline (x across, y up) at height y: the largest |x| where it crosses y.
inline double halfWidthAt(const std::vector<V2>& outline, double y) {
  double w = 0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const V2 a = outline[i], b = outline[(i + 1) % outline.size()];
    if ((a.y() - y) * (b.y() - y) > 0 || a.y() == b.y()) continue;
    w = std::max(w, std::fabs(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y())));
  }
  return w;
}

/// A vertebra's measures (metres).
struct VertebraSize {
  double depth;        ///< how far the body reaches forward of the arch ring
  double halfHeight;   ///< of the body
  double canal;        ///< radius of the spinal canal
  double arch;         ///< thickness of the arch (pedicles and laminae)
  double archHalf;     ///< half height of the arch
  double spinous;      ///< length of the spinous process
  V3 spinousDir;       ///< its direction
  int spinousRows;     ///< profile rows it spans either side of the middle (1: thin, 2: tall)
  double transverse;   ///< length of a transverse process
  V3 transverseDir;    ///< its direction on the right (+x) side
};

/// A vertebra with its canal's centre at `centre`: a ring swept round the canal, its
/// section growing into the body in front, with the processes pulled out of it.
inline gjkx::TriangleMesh vertebra(const VertebraSize& v, const V3& centre, int stations, int rows,
                                   const std::string& name) {
  const double ring = v.canal + v.arch;  // the loop's radius: the canal's wall is at v.canal
  std::vector<V3> loop;
  for (int k = 0; k < stations; ++k) {
    const double u = 2 * M_PI * k / stations;
    loop.push_back(centre + V3(ring * std::cos(u), ring * std::sin(u), 0));
  }
  const auto frame = frames(loop, true, [](int) { return V3(0, 0, 1); });
  Rings rings = sweepRings(loop, frame, [&](int k) {
    const double u = 2 * M_PI * k / stations, front = std::pow(std::max(0.0, std::sin(u)), 1.5);
    // Outward the body (front) or the arch; inward only the arch's thickness, so the canal stays open.
    return profile(rows, lerp(v.arch, v.depth, front), v.arch, lerp(v.archHalf, v.halfHeight, front),
                   lerp(v.archHalf, v.halfHeight, front), lerp(2.0, 5.0, front));
  });
  const int back = 3 * stations / 4, side = stations / 12;
  extrude(rings, back - 1, back + 1, -v.spinousRows, v.spinousRows, v.spinous * v.spinousDir.normalized());
  // Transverse processes a little behind the sides (profile row 0 points outward).
  extrude(rings, stations - side - 1, stations - side, -1, 1, v.transverse * v.transverseDir.normalized());
  const V3 left(-v.transverseDir.x(), v.transverseDir.y(), v.transverseDir.z());
  extrude(rings, stations / 2 + side, stations / 2 + side + 1, -1, 1, v.transverse * left.normalized());
  return ringSurface(rings, true, V3::Zero(), V3::Zero(), name);
}

}  // namespace detail

/// Resolution of the generated meshes (the triangle counts follow from them).
struct Resolution {
  int cervicalStations = 24, thoracicStations = 24, lumbarStations = 28;  ///< vertebra loop stations
  int vertebraRows = 12;      ///< vertebra profile vertices
  int ribStations = 18, ribRows = 6;            ///< rib path points, profile vertices
  int cartilageStations = 6, cartilageRows = 6;  ///< cartilage
};

/// The 80 bones of the torso in its own frame.
inline std::vector<Bone> buildTorso(const Resolution& res = {}) {
  using namespace detail;
  std::vector<Bone> bones;
  auto add = [&](std::string name, std::string group, gjkx::TriangleMesh mesh) {
    mesh.source = name;
    bones.push_back(Bone{std::move(name), std::move(group), std::move(mesh)});
  };

  // ---- The spine: 7 cervical, 12 thoracic, 5 lumbar vertebrae from the top down.
  struct Level {
    std::string name;
    VertebraSize size;
    double gap;       // the disc below it
    int stations;
    V3 canal;         // centre of the canal (filled in below)
  };
  std::vector<Level> spine;
  for (int i = 0; i < 7; ++i) {
    const double t = i / 6.0;
    spine.push_back({"C" + std::to_string(i + 1),
                     {lerp(0.014, 0.018, t), lerp(0.0045, 0.006, t), 0.0075, 0.003, 0.004, lerp(0.008, 0.02, t * t),
                      V3(0, -1, -0.3), 1, 0.007, V3(1, 0.25, 0)},
                     0.004, res.cervicalStations, V3::Zero()});
  }
  for (int i = 0; i < 12; ++i) {
    const double t = i / 11.0;
    spine.push_back({"T" + std::to_string(i + 1),
                     {lerp(0.019, 0.027, t), lerp(0.0065, 0.0095, t), 0.0065, 0.0035, 0.005, lerp(0.024, 0.022, t),
                      V3(0, -1, lerp(-0.6, -0.25, t)), 1, lerp(0.016, 0.01, t), V3(1, -0.5, 0)},
                     0.005, res.thoracicStations, V3::Zero()});
  }
  for (int i = 0; i < 5; ++i) {
    const double t = i / 4.0;
    spine.push_back({"L" + std::to_string(i + 1),
                     {lerp(0.029, 0.032, t), lerp(0.011, 0.012, t), 0.0075, 0.0045, 0.007, 0.021, V3(0, -1, -0.1), 2,
                      lerp(0.022, 0.02, t), V3(1, -0.15, 0)},
                     0.007, res.lumbarStations, V3::Zero()});
  }
  // Stack them from the top of C1 down; the spine's curves (the neck and the lower back
  // forward, the chest backward) move each canal a little in y.
  double z = 0.63, length = 0;
  for (const auto& l : spine) length += 2 * l.size.halfHeight + l.gap;
  double walked = 0;
  for (auto& l : spine) {
    const double s = (walked + l.size.halfHeight) / length;
    double y = s < 0.78 ? -0.016 * std::sin(M_PI * s / 0.78) : 0.012 * std::sin(M_PI * (s - 0.78) / 0.22);
    if (s < 0.17) y += 0.01 * std::sin(M_PI * s / 0.17);
    l.canal = V3(0, y, z - l.size.halfHeight);
    z -= 2 * l.size.halfHeight + l.gap;
    walked += 2 * l.size.halfHeight + l.gap;
  }
  for (const auto& l : spine)
    add("vertebra_" + l.name, "vertebra", vertebra(l.size, l.canal, l.stations, res.vertebraRows, "vertebra_" + l.name));
  const double sacrumTop = z;  // below L5's disc
  auto thoracic = [&](int k) -> const Level& { return spine[6 + k]; };  // k = 1..12

  // ---- The ribs: rib k leaves the disc above T_k beside the vertebral bodies, runs back
  // to its angle behind the transverse processes, then round an ellipse to the front,
  // dropping as it goes. Each side's ellipse is centred off the midline (the spine
  // bulges into the chest: a kidney-shaped cross-section).
  const double A[12] = {0.055, 0.08, 0.095, 0.105, 0.113, 0.118, 0.121, 0.122, 0.12, 0.115, 0.105, 0.09};
  const double B[12] = {0.04, 0.055, 0.065, 0.072, 0.078, 0.081, 0.083, 0.083, 0.081, 0.078, 0.074, 0.07};
  const double endAngle[12] = {2.7, 2.7, 2.65, 2.6, 2.55, 2.5, 2.45, 2.25, 2.05, 1.85, 1.6, 1.3};
  const double drop[12] = {0.025, 0.04, 0.05, 0.055, 0.06, 0.062, 0.064, 0.062, 0.058, 0.052, 0.044, 0.036};
  const double offMidline = 0.042, ribHalfHeight = 0.0045, ribHalfThickness = 0.0022;
  std::vector<V3> ribEnd[2], ribEndTangent[2];
  double sternumY = 0;
  for (int k = 1; k <= 12; ++k) {
    const Level& v = thoracic(k);
    const double headZ = v.canal.z() + v.size.halfHeight + 0.5 * spine[5 + k].gap;  // the disc above T_k
    const double postY = v.canal.y() - 0.028;
    if (k >= 2 && k <= 6) sternumY += (postY + 2 * B[k - 1]) / 5;
    for (int side = 0; side < 2; ++side) {
      const double s = side == 0 ? -1 : 1;  // left, right
      const double a = A[k - 1] - offMidline, b = B[k - 1];
      std::vector<V3> control{V3(s * (v.canal.x() + v.size.canal + v.size.arch + 0.012), v.canal.y() + 0.012, headZ)};
      const int n = res.ribStations - 2;
      for (int i = 0; i < n; ++i) {
        const double t = double(i) / (n - 1), phi = 0.15 + t * (endAngle[k - 1] - 0.15);
        control.push_back(V3(s * (offMidline + a * std::sin(phi)), postY + b - b * std::cos(phi),
                             headZ - 0.004 - drop[k - 1] * std::pow(t, 1.3)));
      }
      // The neck: halfway from the head to the first point of the ellipse.
      control.insert(control.begin() + 1, 0.5 * (control[0] + control[1]) + V3(0, -0.004, 0));
      const std::vector<V3>& path = control;
      const std::string name = std::string("rib_") + (side == 0 ? "left_" : "right_") + std::to_string(k);
      add(name, "rib",
          sweep(path, [](int) { return V3(0, 0, 1); },
                [&](int i) {
                  const double t = double(i) / (path.size() - 1);
                  const double h = lerp(0.0035, ribHalfHeight, smoothstep(0, 0.3, t)) * lerp(1.0, 0.85, t);
                  return profile(res.ribRows, ribHalfThickness, ribHalfThickness, h, h);
                },
                0.003, name));
      ribEnd[side].push_back(path.back());
      ribEndTangent[side].push_back((path.back() - path[path.size() - 2]).normalized());
    }
  }

  // ---- The sternum: the manubrium (with the jugular notch) and the body ending in the
  // xiphoid process, thin plates in the plane y = sternumY facing forward.
  const double manubriumTop = ribEnd[0][0].z() + 0.03;
  const std::vector<V2> manubrium = resample({{-0.012, 0}, {0, -0.007}, {0.012, 0}, {0.026, -0.007}, {0.022, -0.022},
                                              {0.014, -0.046}, {-0.014, -0.046}, {-0.022, -0.022}, {-0.026, -0.007}},
                                             28);
  const double bodyTop = manubriumTop - 0.052;
  const std::vector<V2> sternalBody =
      resample({{0.013, 0}, {0.017, -0.04}, {0.018, -0.07}, {0.012, -0.098}, {0.005, -0.103}, {0.003, -0.13},
                {0, -0.134}, {-0.003, -0.13}, {-0.005, -0.103}, {-0.012, -0.098}, {-0.018, -0.07}, {-0.017, -0.04},
                {-0.013, 0}},
               36);
  auto sternalPlate = [&](const std::vector<V2>& outline, double top, double half, const std::string& name) {
    return plate(outline, {0.7, 0.35}, [half](const V2&, int) { return half; },
                 [&](const V2& p, double h) { return V3(p.x(), sternumY - 0.25 * p.x() * p.x() + h, top + p.y()); }, name);
  };
  add("sternum_manubrium", "sternum", sternalPlate(manubrium, manubriumTop, 0.0055, "sternum_manubrium"));
  add("sternum_body", "sternum", sternalPlate(sternalBody, bodyTop, 0.0045, "sternum_body"));

  // ---- The costal cartilages: from each rib's front end, with a gap, to the sternum's
  // edge (ribs 1-7), towards the costal margin below it (8-10), a tip (11).
  const double gap = 0.004;
  for (int side = 0; side < 2; ++side) {
    const double s = side == 0 ? -1 : 1;
    for (int k = 1; k <= 11; ++k) {
      const V3 end = ribEnd[side][k - 1], along = ribEndTangent[side][k - 1];
      const V3 start = end + (0.003 + gap + 0.002) * along;
      V3 target;
      if (k == 1) {
        target = V3(s * (halfWidthAt(manubrium, -0.03) + gap + 0.004), sternumY, manubriumTop - 0.03);
      } else if (k <= 7) {
        const double zs = std::min(end.z() + 0.006 * (k - 1), bodyTop - 0.008);
        target = V3(s * (halfWidthAt(sternalBody, zs - bodyTop) + gap + 0.004), sternumY, zs);
      } else if (k <= 10) {
        target = start + 0.024 * along + V3(-s * 0.008, 0, 0.008);
      } else {
        target = start + 0.02 * along;
      }
      const double span = (target - start).norm();
      const std::vector<V3> path =
          bezier(start, start + 0.4 * span * along, target + 0.35 * span * V3(s, 0, -0.3).normalized(), target,
                 res.cartilageStations);
      const std::string name = std::string("cartilage_") + (side == 0 ? "left_" : "right_") + std::to_string(k);
      const double r = k <= 10 ? 0.004 : 0.003;
      add(name, "cartilage",
          sweep(path, [](int) { return V3(0, 0, 1); },
                [&](int) { return profile(res.cartilageRows, 0.0028, 0.0028, r, r); }, 0.002, name));
    }
  }

  // ---- The scapulae: curved triangular plates behind ribs 2-7 with the spine (a ridge
  // running up and out into the acromion). The plate lies on an ellipse round rib 5's.
  const Level& t5 = thoracic(5);
  const double scapulaY = t5.canal.y() - 0.028 + B[4];  // centre of rib 5's ellipse
  const double sa = A[4] - offMidline + 0.022, sb = B[4] + 0.022;
  const double scapulaZ = thoracic(2).canal.z() - 0.01;
  const std::vector<V2> scapulaOutline =
      resample({{0.0, 0.035}, {0.004, -0.03}, {0.012, -0.105}, {0.05, -0.06}, {0.083, -0.012}, {0.092, 0.0},
                {0.102, 0.026}, {0.088, 0.04}, {0.06, 0.024}, {0.03, 0.03}},
               36);
  for (int side = 0; side < 2; ++side) {
    const double s = side == 0 ? -1 : 1;
    auto place = [&](const V2& p, double h) {
      const double phi = 0.32 + p.x() / (0.5 * (sa + sb));
      const V3 onEllipse(s * (offMidline + sa * std::sin(phi)), scapulaY - sb * std::cos(phi), scapulaZ + p.y());
      const V3 outward = V3(s * sb * std::sin(phi), -sa * std::cos(phi), 0).normalized();
      return V3(onEllipse + h * outward);
    };
    auto thickness = [](const V2& p, int face) {
      if (face < 0) return 0.0025;
      // The spine: a ridge from the medial border (0, 0) to the acromion (0.1, 0.03).
      const V2 a(0.0, 0.0), b(0.1, 0.03);
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const double d = (p - (a + t * (b - a))).norm();
      return 0.0025 + 0.009 * std::max(0.0, 1 - d / 0.008) * std::min(1.0, 4 * t + 0.2);
    };
    const std::string name = std::string("scapula_") + (side == 0 ? "left" : "right");
    add(name, "scapula", plate(scapulaOutline, {0.85, 0.6, 0.35, 0.12}, thickness, place, name));

    // ---- The clavicle: an S from the manubrium's top corner to the acromion.
    const V3 acromion = place(V2(0.1, 0.032), 0.0);
    const V3 sternal(s * 0.036, sternumY + 0.004, manubriumTop - 0.004);
    const V3 acromial = acromion + V3(-s * 0.006, 0.014, 0.004);
    const std::vector<V3> path = bezier(sternal, sternal + V3(s * 0.05, 0.025, 0.004),
                                        acromial + V3(-s * 0.045, 0.03, -0.004), acromial, 16);
    const std::string clavicle = std::string("clavicle_") + (side == 0 ? "left" : "right");
    add(clavicle, "clavicle",
        sweep(path, [](int) { return V3(0, 0, 1); },
              [&](int i) {
                const double r = lerp(0.0065, 0.0045, std::sin(M_PI * i / 15.0));
                return profile(8, r, r, 0.8 * r, 0.8 * r);
              },
              0.004, clavicle));
  }

  // ---- The sacrum: a curved wedge below L5 (concave in front), and the coccyx below it.
  const Level& l5 = spine.back();
  const V3 s0(0, l5.canal.y() + 0.016, sacrumTop - 0.004);
  const V3 s3(0, l5.canal.y() - 0.03, sacrumTop - 0.105);
  const std::vector<V3> sacrumPath = bezier(s0, s0 + V3(0, -0.004, -0.04), s3 + V3(0, 0.02, 0.03), s3, 12);
  add("sacrum", "sacrum",
      sweep(sacrumPath, [](int) { return V3(0, 1, 0); },
            [&](int i) {
              const double t = i / 11.0;
              return profile(12, lerp(0.05, 0.012, std::pow(t, 0.8)), lerp(0.05, 0.012, std::pow(t, 0.8)),
                             lerp(0.02, 0.006, t), lerp(0.016, 0.006, t), 3.0);
            },
            0.004, "sacrum"));
  const V3 tangent = (s3 - sacrumPath[10]).normalized();
  const V3 c0 = s3 + 0.012 * tangent;
  const std::vector<V3> coccyxPath = bezier(c0, c0 + 0.012 * tangent, c0 + V3(0, 0.01, -0.02), c0 + V3(0, 0.018, -0.03), 6);
  add("coccyx", "coccyx",
      sweep(coccyxPath, [](int) { return V3(0, 1, 0); },
            [&](int i) {
              const double r = lerp(0.008, 0.003, i / 5.0);
              return profile(8, r, r, 0.6 * r, 0.6 * r);
            },
            0.002, "coccyx"));

  // ---- The hip bones: from beside the sacrum, through the iliac wing (a tall thin
  // section flaring up and out), the acetabulum, round to the pubic symphysis in front.
  for (int side = 0; side < 2; ++side) {
    const double s = side == 0 ? -1 : 1;
    const double y0 = s0.y();
    const std::vector<V3> control{V3(s * 0.072, y0 - 0.018, sacrumTop - 0.045), V3(s * 0.1, y0 + 0.0, sacrumTop - 0.04),
                                  V3(s * 0.105, y0 + 0.04, sacrumTop - 0.075), V3(s * 0.075, y0 + 0.07, sacrumTop - 0.11),
                                  V3(s * 0.03, y0 + 0.09, sacrumTop - 0.125), V3(s * 0.01, y0 + 0.095, sacrumTop - 0.125)};
    const std::vector<V3> path = catmullRom(control, 4);
    const int K = int(path.size());
    const std::string name = std::string("hip_") + (side == 0 ? "left" : "right");
    add(name, "hip",
        sweep(path, [&](int k) { return V3(-s * 0.5 * (1 - smoothstep(0.3, 0.6, double(k) / (K - 1))), 0, 1); },
              [&](int k) {
                const double t = double(k) / (K - 1);
                const double wing = 1 - smoothstep(0.25, 0.5, t), socket = std::exp(-std::pow((t - 0.5) / 0.12, 2));
                const double pubis = smoothstep(0.6, 0.8, t);
                const double thick = lerp(lerp(0.006, 0.013, socket), 0.006, pubis);
                const double up = lerp(lerp(0.012, 0.014, socket), 0.007, pubis) + 0.06 * wing;
                const double down = lerp(lerp(0.012, 0.03, socket), 0.007, pubis);
                return profile(10, thick, thick, up, down);
              },
              0.003, name));
  }
  return bones;
}

/// A bone as the scene file places it: its mesh in its own frame (about the centre of
/// its bounding box) and the pose of that frame in the world at the start.
struct PlacedBone {
  std::string name;                ///< as in Bone
  std::string group;               ///< as in Bone
  gjkx::TriangleMesh mesh;         ///< in the bone's own frame
  V3 position;                     ///< where the frame's origin is at the start
  Eigen::Quaterniond orientation;  ///< the frame's orientation at the start
};

/// The random drop a seed chooses.
struct Drop {
  double yaw = 0;        ///< turn about the vertical, radians
  double tiltAxis = 0;   ///< direction of the horizontal axis of the tilt, radians
  double tilt = 0;       ///< tilt from upright, radians (60 to 90 degrees: falling more or less flat)
  double dx = 0, dy = 0; ///< offset of the torso's centre from the plant's axis, metres
  double plantTop = 0;   ///< height of the plant's highest point
  double lowest = 0;     ///< height of the torso's lowest point at the start
};

/// Everything a scene file holds: the bones placed for the drop, the plant, the drop.
struct SceneLayout {
  std::vector<PlacedBone> bones;  ///< 80, or the 6 of the reduced scene
  gjkx::TriangleMesh plant;       ///< standing on z = 0, fixed
  Drop drop;                      ///< what the seed chose
  double duration = 6;            ///< simulated seconds
};

/// The scene of the paper's §6 for `seed` (the full one, or the reduced one): the torso
/// turned by a random yaw, tilted from upright by 60 to 90 degrees about a random
/// horizontal axis, its centre offset up to 8 cm from the plant's axis and its lowest
/// point 0.6 m above the plant's top, every bone at rest. The numbers come from
/// std::mt19937 through Random, so a seed gives the same scene everywhere.
inline SceneLayout layoutScene(std::uint32_t seed, bool reduced) {
  std::vector<Bone> bones = buildTorso();
  if (reduced) {
    std::vector<Bone> kept;
    for (const auto& name : reducedBoneNames())
      for (auto& b : bones)
        if (b.name == name) kept.push_back(std::move(b));
    bones = std::move(kept);
  }
  SceneLayout layout;
  layout.plant = buildPlant(reduced ? 3 : 12);
  layout.duration = reduced ? 1.0 : 6.0;
  Drop& d = layout.drop;
  Random random(seed);
  d.yaw = random.uniform(0, 2 * M_PI);
  d.tiltAxis = random.uniform(0, 2 * M_PI);
  d.tilt = random.uniform(M_PI / 3, M_PI / 2);
  d.dx = random.uniform(-0.08, 0.08);
  d.dy = random.uniform(-0.08, 0.08);
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(d.tilt, V3(std::cos(d.tiltAxis), std::sin(d.tiltAxis), 0)) * Eigen::AngleAxisd(d.yaw, V3::UnitZ()))
          .toRotationMatrix();
  V3 lo = V3::Constant(1e9), hi = V3::Constant(-1e9);
  for (const auto& b : bones)
    for (const V3& v : b.mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const V3 torsoCentre = 0.5 * (lo + hi);
  d.plantTop = 0;
  for (const V3& v : layout.plant.vertices) d.plantTop = std::max(d.plantTop, v.z());
  double lowest = 1e9;
  for (const auto& b : bones)
    for (const V3& v : b.mesh.vertices) lowest = std::min(lowest, (rotation * (v - torsoCentre)).z());
  const V3 shift(d.dx, d.dy, d.plantTop + 0.6 - lowest);  // world = rotation * (v - torsoCentre) + shift
  d.lowest = d.plantTop + 0.6;
  for (auto& b : bones) {
    V3 blo = b.mesh.vertices[0], bhi = blo;
    for (const V3& v : b.mesh.vertices) {
      blo = blo.cwiseMin(v);
      bhi = bhi.cwiseMax(v);
    }
    const V3 centre = 0.5 * (blo + bhi);
    for (V3& v : b.mesh.vertices) v -= centre;
    layout.bones.push_back(PlacedBone{b.name, b.group, std::move(b.mesh), rotation * (centre - torsoCentre) + shift,
                                      Eigen::Quaterniond(rotation)});
  }
  return layout;
}

}  // namespace torso
