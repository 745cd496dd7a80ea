// Chapter 06: nonconvex bodies (§6). "Each surface is decomposed into convex pieces, the
// pieces sit in a hierarchy of 14-DOPs", tree queries prune piece pairs with the k-DOP
// extrusion test, and the front of the last query is where the next one starts. Figures:
//   kdop-pieces.png:     a real mesh (Wuson, assimp-testmodels) and a torus, triangles
//                        coloured by their convex piece (HACD), and the pieces' hulls (Qhull);
//   kdop-hierarchy.png:  the 14-DOPs of Wuson's hierarchy at depths 0, 1, 2 and 3;
//   kdop-extrusion.png:  the k-DOP extrusion test in the plane (a 14-DOP of a flat shape
//                        is an octagon: slabs x, y, x+y, x-y) on three motions;
//   kdop-front.png:      the front of the test tree of two Wusons at two successive
//                        frames, as blocks of the piece-pair matrix.
// --frames and --spin change the front's query; --trace prints the query frame by frame
// and the front of the two frames drawn node by node (docs/traces.md).
#include "../chapter.hpp"
#include "meshes.hpp"

#include <gjkx/kdop/body_pair.hpp>
#include <gjkx/render/canvas.hpp>
#include <gjkx/support_mapping/placed.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

using namespace gjkx;
using namespace gjkx::render;
using V = Vector3<double>;

namespace {

// Distinct colours for n pieces: hues around the wheel by the golden angle.
Color pieceColor(int i, double alpha = 1.0) {
  const double h = std::fmod(i * 0.61803398875, 1.0) * 6, s = 0.55, v = 0.92;
  const double c = v * s, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1)), m = v - c;
  const double rgb[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  const auto& k = rgb[static_cast<int>(h) % 6];
  return Color{k[0] + m, k[1] + m, k[2] + m, alpha};
}

// The figures show meshes upright: Wuson's files have y up, the camera has z up.
V upright(const V& v) { return V(v.x(), -v.z(), v.y()); }

Mesh meshOf(const Polytope<double>& p) {
  Mesh m{p.vertices(), p.triangles()};
  for (auto& v : m.vertices) v = upright(v);
  return m;
}

// The 14-DOP as a solid: the corners where three slab planes meet inside all 14 half-spaces.
Polytope<double> kdopSolid(const Kdop14<double>& k) {
  std::vector<V> corners;
  for (int i = 0; i < 14; ++i)
    for (int j = i + 1; j < 14; ++j)
      for (int l = j + 1; l < 14; ++l) {
        Eigen::Matrix3d n;
        V d;
        const int planes[3] = {i, j, l};
        for (int r = 0; r < 3; ++r) {
          const int slab = planes[r] / 2;
          const bool upper = planes[r] % 2 == 0;
          n.row(r) = Kdop14<double>::axis(slab).transpose();
          d[r] = upper ? k.hi[slab] : k.lo[slab];
        }
        if (std::fabs(n.determinant()) < 1e-9) continue;
        const V x = n.fullPivLu().solve(d);
        bool inside = true;
        for (int s = 0; s < 7 && inside; ++s) {
          const double a = Kdop14<double>::axis(s).dot(x);
          inside = a >= k.lo[s] - 1e-9 && a <= k.hi[s] + 1e-9;
        }
        if (inside) corners.push_back(x);
      }
  return Polytope<double>::hull(corners);
}

// The octagon a 14-DOP of a flat shape (z = 0) is: slabs x, y, x+y, x-y.
std::vector<Eigen::Vector2d> kdopOctagon(const Kdop14<double>& k) {
  // In the plane z = 0 the diagonal slabs (1,1,±1) both read x+y, (1,-1,±1) both x-y.
  const double lo[4] = {k.lo[0], k.lo[1], std::max(k.lo[3], k.lo[5]), std::max(k.lo[4], k.lo[6])};
  const double hi[4] = {k.hi[0], k.hi[1], std::min(k.hi[3], k.hi[5]), std::min(k.hi[4], k.hi[6])};
  const Eigen::Vector2d n[4] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  std::vector<Eigen::Vector2d> corners;
  for (int i = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j) {
      Eigen::Matrix2d m;
      m.row(0) = n[i / 2].transpose();
      m.row(1) = n[j / 2].transpose();
      if (std::fabs(m.determinant()) < 1e-12) continue;
      const Eigen::Vector2d x = m.inverse() * Eigen::Vector2d(i % 2 ? hi[i / 2] : lo[i / 2], j % 2 ? hi[j / 2] : lo[j / 2]);
      bool inside = true;
      for (int s = 0; s < 4 && inside; ++s) inside = n[s].dot(x) >= lo[s] - 1e-9 && n[s].dot(x) <= hi[s] + 1e-9;
      if (inside) corners.push_back(x);
    }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& p : corners) c += p;
  c /= double(corners.size());
  std::sort(corners.begin(), corners.end(), [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::atan2(a.y() - c.y(), a.x() - c.x()) < std::atan2(b.y() - c.y(), b.x() - c.x());
  });
  return corners;
}

struct Subject {
  std::string name;
  TriangleMesh mesh;
  ConvexDecomposition pieces;
};

void piecesFigure(const std::string& out, const std::vector<Subject>& subjects) {
  const int W = 440, H = 400;
  Canvas canvas(2 * W, static_cast<int>(subjects.size()) * H);
  for (size_t row = 0; row < subjects.size(); ++row) {
    const Subject& s = subjects[row];
    V lo = upright(s.mesh.vertices[0]), hi = lo;
    for (const auto& v : s.mesh.vertices) {
      lo = lo.cwiseMin(upright(v));
      hi = hi.cwiseMax(upright(v));
    }
    const V centre = (lo + hi) / 2;
    double radius = 0;
    for (const auto& v : s.mesh.vertices) radius = std::max(radius, (upright(v) - centre).norm());
    auto camera = [&] { canvas.setCamera(Camera::orbit(centre, 1.0 * radius, -0.6, 0.35, 0.6, canvas.plotAspect())); };
    // Left: the mesh's triangles, coloured by the piece they went to.
    canvas.setPanel({0, static_cast<int>(row) * H, W, H});
    char title[160];
    std::snprintf(title, sizeof title, "%s: %zu triangles into %d convex pieces", s.name.c_str(), s.mesh.triangles.size(),
                  s.pieces.report.pieces);
    canvas.title(title);
    camera();
    for (int p = 0; p < s.pieces.report.pieces; ++p) {
      Mesh m;
      std::map<int, int> index;
      for (size_t t = 0; t < s.mesh.triangles.size(); ++t) {
        if (s.pieces.pieceOfTriangle[t] != p) continue;
        std::array<int, 3> tri{};
        for (int k = 0; k < 3; ++k) {
          const int v = s.mesh.triangles[t][k];
          auto [it, inserted] = index.emplace(v, static_cast<int>(m.vertices.size()));
          if (inserted) m.vertices.push_back(upright(s.mesh.vertices[v]));
          tri[k] = it->second;
        }
        m.triangles.push_back(tri);
      }
      canvas.mesh(m, MeshStyle{pieceColor(p), Stroke{palette::ink, 0.5}, false, true});
    }
    // Right: the convex hulls of the pieces, as GJK sees the body.
    canvas.setPanel({W, static_cast<int>(row) * H, W, H});
    std::snprintf(title, sizeof title, "their hulls (Qhull): volume +%.0f%%", 100 * s.pieces.report.volumeExcess);
    canvas.title(title);
    camera();
    const auto hulls = s.pieces.polytopes<double>();
    for (size_t p = 0; p < hulls.size(); ++p)
      canvas.mesh(meshOf(hulls[p]), MeshStyle{pieceColor(static_cast<int>(p), 0.8), Stroke{palette::ink, 0.6}, true, true});
  }
  chapter::save(canvas, out, "kdop-pieces");
}

void hierarchyFigure(const std::string& out, const Subject& s) {
  const Bvh<double> bvh(s.pieces.polytopes<double>());
  const int W = 540, H = 380;
  Canvas canvas(2 * W, 2 * H);
  Mesh body{{}, s.mesh.triangles};
  for (const auto& v : s.mesh.vertices) body.vertices.push_back(upright(v));
  V lo = body.vertices[0], hi = lo;
  for (const auto& v : body.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (int depth = 0; depth < 4; ++depth) {
    canvas.setPanel({(depth % 2) * W, (depth / 2) * H, W, H});
    int count = 0;
    for (const auto& n : bvh.nodes()) count += n.depth == depth || (n.isLeaf() && n.depth < depth);
    canvas.title("depth " + std::to_string(depth) + ": " + std::to_string(count) + (count == 1 ? " 14-DOP" : " 14-DOPs"));
    canvas.setCamera(Camera::orbit((lo + hi) / 2, 0.42 * (hi - lo).norm(), -0.6, 0.35, 0.6, canvas.plotAspect()));
    canvas.mesh(body, MeshStyle{palette::minkowskiSolid, Stroke{palette::ink, 0.5}, false, true});
    int colour = 0;
    for (const auto& n : bvh.nodes()) {
      if (!(n.depth == depth || (n.isLeaf() && n.depth < depth))) continue;
      // The node's 14-DOP in the figure's frame: of its hull, turned upright.
      std::vector<V> points;
      for (const auto& v : n.hull->vertices()) points.push_back(upright(v));
      const Polytope<double> solid = kdopSolid(kdopOf(Polytope<double>::hull(points)));
      canvas.mesh(Mesh{solid.vertices(), solid.triangles()},
                  MeshStyle{pieceColor(colour, 0.22), Stroke{pieceColor(colour).withAlpha(1.0), 1.4}, true, true});
      ++colour;
    }
  }
  chapter::save(canvas, out, "kdop-hierarchy");
}

// The outline of a flat polytope at a pose, in the figure's plane.
std::vector<Eigen::Vector2d> outlineAt(const Polytope<double>& x, const Pose<double>& pose) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& v : x.vertices()) out.push_back(chapter::xy(V(pose(v))));
  return out;
}

// One panel of the k-DOP extrusion test in the plane: P at rest, Q moving over [0, 1];
// `marked` is a time drawn bold (where Q hits P), or a negative number for none.
void extrusionPanel(Canvas& canvas, const std::vector<Polytope<double>>& pPieces, const Polytope<double>& q,
                    const Motion<double>& motion, const std::string& what, double marked) {
  const Bvh<double> bodyP(pPieces), bodyQ({q});
  BodyPairSettings<double> paper, certified;
  paper.variant = ExtrusionVariant::Paper;
  const auto keptPaper = survivingPiecePairs(bodyP, Motion<double>(), bodyQ, motion, 0.0, 1.0, paper).pairs.size();
  const auto keptCertified = survivingPiecePairs(bodyP, Motion<double>(), bodyQ, motion, 0.0, 1.0, certified).pairs.size();
  std::string verdict = keptCertified == 0 ? "pruned" : "kept";
  if (keptPaper == 0 && keptCertified > 0) verdict = "paper prunes, certified keeps";
  canvas.title(what + ": " + verdict);
  canvas.setWorldWindow(-3.0, 3.6, -2.3, 3.0);
  for (int k = 1; k < 10; ++k)
    canvas.polygon(outlineAt(q, motion.pose(k / 10.0)),
                   ShapeStyle{palette::bodyQFill.withAlpha(0.05), Stroke{palette::bodyQStroke.withAlpha(0.25), 0.8}});
  for (const auto& piece : pPieces) {
    canvas.polygon(chapter::xy(piece.vertices()), style::bodyP);
    canvas.polygon(kdopOctagon(kdopOf(piece)), ShapeStyle{palette::none, Stroke{palette::bodyPStroke, 1.2, {6, 4}}});
  }
  if (marked >= 0) {
    canvas.polygon(outlineAt(q, motion.pose(marked)), ShapeStyle{palette::penetration.withAlpha(0.25), Stroke{palette::penetration, 2}});
    canvas.text(chapter::xy(V(motion.pose(marked).translation)) + Eigen::Vector2d(0.55, 0.0), "Q(1/2) hits P", mathLabel,
                Anchor::Right);
  }
  for (double t : {0.0, 1.0}) {
    const auto at = place(q, motion.pose(t));
    canvas.polygon(outlineAt(q, motion.pose(t)), style::bodyQ);
    canvas.polygon(kdopOctagon(kdopOf(at)), ShapeStyle{palette::none, Stroke{palette::bodyQStroke, 1.2, {6, 4}}});
    if (marked < 0)
      canvas.text(chapter::xy(V(at.center())) + Eigen::Vector2d(0, 0.55), t == 0 ? "Q(t_0)" : "Q(t_1)", mathLabel,
                  Anchor::Center);
    else if (t == 0)
      canvas.text(chapter::xy(V(at.center())) + Eigen::Vector2d(0, 1.3), "Q(t_0) = Q(t_1)", mathLabel, Anchor::Center);
  }
  canvas.text(Eigen::Vector2d(0, -1.9), "P (two pieces, at rest); dashed: 14-DOPs", mathLabel, Anchor::Center);
}

void extrusionFigure(const std::string& out) {
  // P: an L of two convex pieces at rest (the upright one leaning); Q: a bar. Dashed:
  // the 14-DOPs, octagons in the plane (slabs x, y, x+y, x-y).
  const std::vector<Polytope<double>> pPieces = {
      Polytope<double>::polygon({V(-1.6, -1.4, 0), V(1.6, -1.4, 0), V(1.6, -0.6, 0), V(-1.6, -0.6, 0)}),
      Polytope<double>::polygon({V(-1.6, -0.6, 0), V(-0.8, -0.6, 0), V(-1.0, 1.0, 0), V(-1.8, 1.0, 0)})};
  const auto bar = Polytope<double>::polygon({V(-1.0, -0.2, 0), V(1.0, -0.2, 0), V(1.0, 0.2, 0), V(-1.0, 0.2, 0)});
  const int W = 460, H = 430;
  Canvas canvas(3 * W, H);
  canvas.setPanel({0, 0, W, H});
  extrusionPanel(canvas, pPieces, bar,
                 Motion<double>::interpolate(Pose<double>::fromAxisAngle({0, 0, 1}, 0.35, {-1.9, 2.1, 0}),
                                             Pose<double>::fromAxisAngle({0, 0, 1}, 0.35, {1.9, 2.1, 0})),
                 "passing above", -1);
  canvas.setPanel({W, 0, W, H});
  extrusionPanel(canvas, pPieces, bar,
                 Motion<double>::constantVelocity(Pose<double>::fromAxisAngle({0, 0, 1}, -0.35, {-2.3, 1.3, 0}), {4.7, -1.5, 0}),
                 "through P", -1);
  canvas.setPanel({2 * W, 0, W, H});
  extrusionPanel(canvas, pPieces, bar,
                 Motion<double>::screw(Pose<double>::translate({0.5, 0.25, 0}), {0, 0, 0}, {0, 0, M_PI}), "half a turn",
                 0.5);
  chapter::save(canvas, out, "kdop-extrusion");
}

// The front as blocks of the piece-pair matrix: a BVTT node (a, b) covers A's pieces under
// a times B's pieces under b.
// A front as a map from its BVTT nodes (a, b) to their verdicts (true: proven apart).
std::map<std::pair<int, int>, bool> keyset(const std::vector<BodyPairQuery<double>::FrontNode>& front) {
  std::map<std::pair<int, int>, bool> k;
  for (const auto& n : front) k[{n.a, n.b}] = n.disjoint;
  return k;
}

// The front's query as tables (--trace): per frame the BVTT nodes tested (pairs of 14-DOPs put
// to the k-DOP extrusion test), the nodes the front climbed back to, the front's size, the
// piece pairs kept (their 14-DOPs overlap over the frame) and the front's update (nodes new
// to it or whose verdict changed); then the fronts of the two frames drawn, node by node.
void printFront(const std::vector<std::vector<BodyPairQuery<double>::FrontNode>>& fronts,
                const std::vector<BodyPairCounters>& counters, int frames, int best) {
  chapter::TraceTable table{"kdop-front: the body-pair query frame by frame (§6, frontal tracking)",
                            {"frame", "t_0", "t_1", "nodes tested", "climbs", "front", "pairs kept", "front nodes new",
                             "left the front"},
                            {}};
  for (int f = 0; f < frames; ++f) {
    const auto now = keyset(fronts[std::size_t(f)]);
    int fresh = 0, gone = 0;
    if (f > 0) {
      const auto before = keyset(fronts[std::size_t(f - 1)]);
      for (const auto& [k, v] : now) fresh += before.count(k) == 0 || before.at(k) != v;
      for (const auto& [k, v] : before) gone += now.count(k) == 0;
    }
    const BodyPairCounters& c = counters[std::size_t(f)];
    table.rows.push_back({std::to_string(f), chapter::format("%.4f", f / double(frames)),
                          chapter::format("%.4f", (f + 1) / double(frames)), std::to_string(c.nodesVisited),
                          std::to_string(c.climbs), std::to_string(c.frontSize), std::to_string(c.pairsKept),
                          f > 0 ? std::to_string(fresh) : "-", f > 0 ? std::to_string(gone) : "-"});
  }
  table.print();
  for (int f : {best - 1, best}) {
    const auto before = keyset(fronts[std::size_t(f == 0 ? 0 : f - 1)]);
    chapter::TraceTable nodes{"kdop-front: the front after frame " + std::to_string(f) +
                                  " (BVTT node (a, b): A's node a against B's node b)",
                              {"a", "b", "verdict", "slab that proved it apart", "new"}, {}};
    for (const auto& n : fronts[std::size_t(f)])
      nodes.rows.push_back({std::to_string(n.a), std::to_string(n.b), n.disjoint ? "apart" : "pair kept",
                            n.slab >= 0 ? std::to_string(n.slab) : "-",
                            f > 0 && (before.count({n.a, n.b}) == 0 || before.at({n.a, n.b}) != n.disjoint) ? "yes" : "no"});
    nodes.print();
  }
}

void frontFigure(const std::string& out, const Subject& s, int frames, double spin, bool trace) {
  const Bvh<double> bvh(s.pieces.polytopes<double>());
  // Each node's range of leaves in depth-first order.
  std::vector<std::pair<int, int>> range(bvh.nodes().size());
  int next = 0;
  std::function<void(int)> number = [&](int i) {
    const auto& n = bvh.node(i);
    range[i].first = next;
    if (n.isLeaf()) {
      ++next;
    } else {
      number(n.left);
      number(n.right);
    }
    range[i].second = next;
  };
  number(0);
  const int leaves = next;
  double size = 0;
  for (const auto& n : bvh.nodes()) size = std::max(size, n.hull->boundingRadius());
  const Motion<double> ma = Motion<double>::screw(Pose<double>::identity(), {0, 0, 0}, {0, 0, spin});
  const Motion<double> mb = Motion<double>::screw(Pose<double>::translate({-1.2 * size, 0.3 * size, 0}), {1.2 * size, 0, 0},
                                                  {0.3, 0.5, 0});
  BodyPairQuery<double> query(bvh, bvh);
  // Run the frames (400) and keep the two successive frames whose fronts differ most.
  std::vector<std::vector<BodyPairQuery<double>::FrontNode>> fronts;
  std::vector<BodyPairCounters> counters;
  for (int f = 0; f < frames; ++f) {
    counters.push_back(query.query(ma, mb, f / double(frames), (f + 1) / double(frames)).counters);
    fronts.push_back(query.front());
  }
  int best = 1, bestChange = -1;
  for (int f = 1; f < frames; ++f) {
    const auto x = keyset(fronts[f - 1]), y = keyset(fronts[f]);
    int change = 0;
    for (const auto& [k, v] : y) change += x.count(k) == 0 || x.at(k) != v;
    if (change > bestChange) {
      bestChange = change;
      best = f;
    }
  }
  if (trace) printFront(fronts, counters, frames, best);
  const int W = 560, H = 600;
  Canvas canvas(2 * W, H);
  for (int panel = 0; panel < 2; ++panel) {
    const int f = best - 1 + panel;
    const auto previous = keyset(fronts[f == 0 ? 0 : f - 1]);
    canvas.setPanel({panel * W, 0, W, H});
    char title[200];
    std::snprintf(title, sizeof title, "frame %d: front %d, %d nodes tested, %d pairs kept", f, counters[f].frontSize,
                  counters[f].nodesVisited, counters[f].pairsKept);
    canvas.title(title);
    canvas.setWorldWindow(-0.5, leaves + 0.5, -2.8, leaves + 0.5);
    for (const auto& n : fronts[f]) {
      const double x0 = range[n.a].first, x1 = range[n.a].second, y0 = range[n.b].first, y1 = range[n.b].second;
      const bool changed = f > 0 && (previous.count({n.a, n.b}) == 0 || previous.at({n.a, n.b}) != n.disjoint);
      const Color fill = n.disjoint ? palette::bodyPFill : palette::penetration.withAlpha(0.75);
      canvas.polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}},
                     ShapeStyle{fill, changed ? Stroke{palette::highlight, 2.5} : Stroke{palette::bodyPStroke, 0.8}});
    }
    canvas.text(Eigen::Vector2d(leaves / 2.0, -0.8), "A's pieces across, B's up (BVH leaf order)", mathLabel,
                Anchor::Center);
    canvas.text(Eigen::Vector2d(leaves / 2.0, -2.0), "blue: apart, red: pair kept, orange: new",
                mathLabel, Anchor::Center);
  }
  chapter::save(canvas, out, "kdop-front");
  std::printf("front: frames %d and %d (%d front nodes changed); blue: apart, red: piece pair kept, orange edge: new\n",
              best - 1, best, bestChange);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  int frames = 400;
  double spin = 0.6;
  bool trace = false;
  CLI::App app{"Draws chapter 06's figures in DIR: convex pieces, their 14-DOP hierarchy, the k-DOP extrusion test "
               "and the front. --frames and --spin change the front's query; --trace prints it (docs/traces.md)."};
  chapter::addFigureOptions(app, out);
  chapter::addTraceOption(app, trace);
  app.add_option("--frames", frames, "the frames over [0, 1] of the front's query (two Wusons)")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  app.add_option("--spin", spin, "A's turn about z over [0, 1] (radians)")
      ->check(CLI::Range(-1000.0, 1000.0))
      ->capture_default_str();
  chapter::parseOrExit(app, argc, argv);
  std::filesystem::create_directories(out);
  std::vector<Subject> subjects;
  for (auto& [name, mesh] : chapter::chapterMeshes()) {
    if (name == "spider") continue;
    auto pieces = decompose(mesh);
    std::printf("%s: %d pieces, vertices per piece:", name.c_str(), pieces.report.pieces);
    for (int n : pieces.report.verticesPerPiece) std::printf(" %d", n);
    std::printf("; volume excess %.1f%%\n", 100 * pieces.report.volumeExcess);
    subjects.push_back({name, mesh, std::move(pieces)});
  }
  piecesFigure(out, subjects);
  hierarchyFigure(out, subjects.front());
  extrusionFigure(out);
  frontFigure(out, subjects.front(), frames, spin, trace);
  return 0;
}
